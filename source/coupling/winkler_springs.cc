#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/core/boundary_selection.h>
#include <impm/coupling/coupling.h>

#include <array>
#include <cstdint>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * @brief Elastic (Winkler) springs under a part of a body's boundary: a
     * foundation, a soil's far field, a bearing. Each boundary point of the
     * part (BoundarySelection: a side of the body, or its boundary inside a
     * region) carries springs of stiffness per unit initial area @f$k_n@f$
     * along its face's normal and @f$k_t@f$ across it, over the area of the
     * true boundary nearest to it, on that face of its domain. They act on
     * the face's total displacement @f$u_f@f$: its displacement at the
     * start of the step (kept here per point and face, updated when a step
     * is accepted, saved in checkpoints) plus the increment at the face
     * (the face weights @f$\phi_v@f$ of BasisEvaluator, as a traction's),
     * with the force @f$f = A\,(k_n\, n\otimes n + k_t\,(I - n\otimes
     * n))\, u_f@f$ spread with the same weights, so the matrix
     * @f$A\,\phi_v \phi_w (k_n\, n\otimes n + k_t\,(I - n\otimes n))@f$
     * is symmetric and exact. The face's displacement is that of the grid's
     * interpolation at the face, so the springs are meant for
     * displacements small against the body (a foundation's settlement),
     * not for a boundary that slides far along them. The springs' reaction (the
     * material's force on them) is written after every converged step
     * (`springs_force_x`, ... in `steps.csv`) and carries part of the load in
     * the reactions' balance.
     *
     * A coupling: a class and its registration line, nothing else (doc/
     * architecture.md, "Adding a coupling").
     *
     * @tparam dim Space dimension.
     */
    template <int dim>
    class WinklerSprings : public Coupling<dim>
    {
    public:
      /** @brief The subsection's entries (besides `Enabled`). */
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Enabled",
                          "false",
                          Patterns::Bool(),
                          "Whether the scene has springs under a part of a "
                          "body's boundary. Springs that are off are not "
                          "created and cost nothing.");
        BoundarySelection<dim>::declare_parameters(prm, "supported");
        prm.declare_entry("Normal stiffness",
                          "0",
                          Patterns::Double(0.),
                          "Stiffness of the springs along the face's normal "
                          "per unit initial area, Pa/m (the modulus of "
                          "subgrade reaction).");
        prm.declare_entry("Tangential stiffness",
                          "0",
                          Patterns::Double(0.),
                          "Stiffness of the springs across the face's "
                          "normal per unit initial area, Pa/m.");
      }

      /** @brief The springs of a scene (from its subsection). */
      explicit WinklerSprings(const CouplingInputs<dim> &inputs)
        : boundary(inputs.prm, "Winkler springs")
        , normal_stiffness(inputs.prm.get_double("Normal stiffness"))
        , tangential_stiffness(inputs.prm.get_double("Tangential stiffness"))
        , bodies(inputs.parameters.bodies)
        , grid(inputs.grid)
      {
        if (!(normal_stiffness > 0.) && !(tangential_stiffness > 0.))
          throw InputError("Winkler springs: give a 'Normal stiffness' or a "
                           "'Tangential stiffness' above zero (both are 0).");
      }

      /** @brief Whether springs act along @p component: those along the
       *  normal or those across it (which of the two, the side says; with
       *  a region both may). */
      bool
      holds_material(const unsigned int component) const override
      {
        if (boundary.is_region())
          return normal_stiffness > 0. || tangential_stiffness > 0.;
        return component == Names::face_axis(boundary.face()) ?
                 normal_stiffness > 0. :
                 tangential_stiffness > 0.;
      }

      std::vector<std::string>
      descriptions() const override
      {
        std::ostringstream out;
        out << "Winkler springs: " << normal_stiffness << " Pa/m normal, "
            << tangential_stiffness << " Pa/m tangential, under the "
            << boundary.description();
        if (boundary.n_points() > 0)
          out << " (" << boundary.n_points() << " points, area "
              << boundary.total_area() << ")";
        return {out.str()};
      }

      /** @brief This step's springs: per boundary point and face, the
       *  face's weights, stiffness and start-of-step displacement. */
      void
      begin_attempt(const MaterialPoints<dim> &material_points,
                    const LoadStepSystem<dim> &system,
                    const StepSpan &) override
      {
        if (!selected)
          {
            boundary.select(material_points.infos(),
                            bodies,
                            grid.cartesian(),
                            grid.get_triangulation().get_communicator());
            selected = true;
          }
        springs.clear();
        const auto &areas = boundary.areas();
        for (const auto &point : material_points.particles())
          {
            const unsigned int p    = system.point_steps.index_of(point);
            const auto         area = areas.find(point.get_id());
            if (area != areas.end())
              for (unsigned int f = 0; f < 2 * dim; ++f)
                if (area->second[f] != 0.)
                  {
                    Spring spring;
                    spring.point = p;
                    spring.key   = {point.get_id(), f};
                    system.face_weights(p,
                                        point.get_location(),
                                        PointState<dim>(point.get_properties())
                                          .domain_half_length(),
                                        Names::face_axis(f),
                                        Names::face_sign(f),
                                        spring.weights);
                    for (unsigned int d = 0; d < dim; ++d)
                      spring.stiffness[d][d] =
                        area->second[f] * (d == Names::face_axis(f) ?
                                             normal_stiffness :
                                             tangential_stiffness);
                    const auto start = face_displacement.find(spring.key);
                    if (start != face_displacement.end())
                      spring.displacement = start->second;
                    spring.start_displacement = spring.displacement;
                    springs.push_back(spring);
                  }
          }
      }

      void
      add_forces(const LoadStepSystem<dim> &system,
                 const NodalVector         &increment,
                 NodalVector               &internal_force) override
      {
        for (Spring &spring : springs)
          {
            const PointStep<dim> &step = system.point_steps[spring.point];
            spring.displacement        = spring.start_displacement;
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                spring.displacement[i] +=
                  spring.weights[v] *
                  increment.local_element(step.dofs[v * dim + i]);
            spring.force = spring.stiffness * spring.displacement;
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                internal_force.local_element(step.dofs[v * dim + i]) +=
                  spring.weights[v] * spring.force[i];
          }
      }

      bool
      add_matrix(const PointGradients<dim> &,
                 const LoadStepSystem<dim>      &system,
                 TrilinosWrappers::SparseMatrix &matrix) override
      {
        for (const Spring &spring : springs)
          {
            const PointStep<dim> &step = system.point_steps[spring.point];
            const unsigned int    n    = step.support.n_nodes * dim;
            for (unsigned int r = 0; r < n; ++r)
              {
                const auto row = system.system_index(step.dofs[r]);
                if (row == numbers::invalid_dof_index)
                  continue;
                for (unsigned int s = 0; s < n; ++s)
                  {
                    const auto   column = system.system_index(step.dofs[s]);
                    const double value  = spring.weights[r / dim] *
                                         spring.weights[s / dim] *
                                         spring.stiffness[r % dim][s % dim];
                    if (column != numbers::invalid_dof_index && value != 0.)
                      matrix.add(row, column, value);
                  }
              }
          }
        return true;
      }

      /** @brief Keep each face's displacement (on every process: points
       *  move between them) and sum the springs' force. */
      void
      accept(MaterialPoints<dim> &,
             const LoadStepSystem<dim> &,
             const NodalVector &) override
      {
        const MPI_Comm communicator =
          grid.get_triangulation().get_communicator();
        Tensor<1, dim>      force;
        std::vector<double> local;
        for (const Spring &spring : springs)
          {
            force += spring.force;
            local.push_back(static_cast<double>(spring.key.first));
            local.push_back(spring.key.second);
            for (unsigned int d = 0; d < dim; ++d)
              local.push_back(spring.displacement[d]);
          }
        for (unsigned int d = 0; d < dim; ++d)
          accepted_force[d] = Utilities::MPI::sum(force[d], communicator);
        for (const auto &part : Utilities::MPI::all_gather(communicator, local))
          read_displacements(part);
      }

      void
      save(RunState &state) const override
      {
        std::vector<double> values;
        for (const auto &[key, displacement] : face_displacement)
          {
            values.push_back(static_cast<double>(key.first));
            values.push_back(key.second);
            for (unsigned int d = 0; d < dim; ++d)
              values.push_back(displacement[d]);
          }
        state.set("winkler springs.face displacements", values);
      }

      void
      load(const RunState &state) override
      {
        face_displacement.clear();
        read_displacements(
          state.get_list("winkler springs.face displacements"));
      }

      Tensor<1, dim>
      force_from_material() const override
      {
        return accepted_force;
      }

      std::vector<std::string>
      step_measure_columns() const override
      {
        std::vector<std::string> columns;
        for (unsigned int d = 0; d < dim; ++d)
          columns.push_back("springs_force_" + Names::axis(d));
        return columns;
      }

      void
      step_measures(const double,
                    std::vector<StepMeasure> &measures) const override
      {
        for (unsigned int d = 0; d < dim; ++d)
          measures.push_back({"springs_force_" + Names::axis(d),
                              "W" + Names::axis(d),
                              accepted_force[d],
                              MeasureKind::force});
      }

    private:
      /** A spring's key: the point's id and the face of its domain. */
      using Key = std::pair<std::uint64_t, unsigned int>;

      /** The springs of one face of a boundary point in this step. */
      struct Spring
      {
        /** The point's index in the step's points. */
        unsigned int point = 0;
        /** The point and face. */
        Key key;
        /** The face's weights over the point's support. */
        std::array<double, PointSupport<dim>::max_nodes> weights;
        /** The springs' stiffness times their area (N/m). */
        Tensor<2, dim> stiffness;
        /** The face's displacement at the start of the step and at the
         *  last add_forces(). */
        Tensor<1, dim> start_displacement, displacement;
        /** The material's force on the springs at the last add_forces(). */
        Tensor<1, dim> force;
      };

      /** @brief Read (id, face, displacement) records into
       *  face_displacement. */
      void
      read_displacements(const std::vector<double> &values)
      {
        for (unsigned int k = 0; k + dim + 2 <= values.size(); k += dim + 2)
          {
            Tensor<1, dim> displacement;
            for (unsigned int d = 0; d < dim; ++d)
              displacement[d] = values[k + 2 + d];
            face_displacement[{static_cast<std::uint64_t>(values[k]),
                               static_cast<unsigned int>(values[k + 1])}] =
              displacement;
          }
      }

      BoundarySelection<dim>        boundary;
      const double                  normal_stiffness;
      const double                  tangential_stiffness;
      const std::vector<Body<dim>> &bodies;
      const BackgroundGrid<dim>    &grid;
      /** Whether the boundary points are found (at the first step). */
      bool                selected = false;
      std::vector<Spring> springs;
      /** Each spring's face displacement at the last accepted step. */
      std::map<Key, Tensor<1, dim>> face_displacement;
      /** The material's force on the springs at the last accepted step. */
      Tensor<1, dim> accepted_force;
    };
  } // namespace

  IMPM_REGISTER_COUPLING(WinklerSprings,
                         "Winkler springs",
                         inputs.prm.get_bool("Enabled"),
                         ([](ParameterHandler &prm) {
                           WinklerSprings<dim>::declare_parameters(prm);
                         }))
} // namespace impm
