#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/core/boundary_selection.h>
#include <impm/coupling/coupling.h>

#include <algorithm>
#include <array>
#include <cmath>
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
     * @brief Springs and dashpots under a part of a body's boundary: the
     * common part of WinklerSprings (a foundation, a soil's far field, a
     * bearing) and AbsorbingBoundary (viscous dashpots that let waves out).
     *
     * Each boundary point of the part (BoundarySelection: a side of the
     * body, or its boundary inside a region) carries, over the area of the
     * true boundary nearest to it on that face of its domain, springs of
     * stiffness per unit initial area @f$k_n@f$ along the face's normal and
     * @f$k_t@f$ across it, and dashpots of viscosity per unit area
     * @f$c_n@f$ and @f$c_t@f$. They act on the face's total displacement
     * @f$u_f@f$: its displacement at the start of the step (kept here per
     * point and face, updated when a step is accepted, saved in
     * checkpoints) plus the increment at the face (the face weights
     * @f$\phi_v@f$ of BasisEvaluator, as a traction's), with the force
     * @f$f = A\,K\,u_f + A\,C\,\Delta u_f/\Delta t@f$, @f$K = k_n\,
     * n\otimes n + k_t\,(I - n\otimes n)@f$ and @f$C@f$ alike, spread with
     * the same weights, so the matrix @f$A\,\phi_v \phi_w (K +
     * C/\Delta t)@f$ is symmetric and exact. The dashpots' velocity is the
     * step's mean velocity @f$\Delta u_f/\Delta t@f$: with the
     * trapezoidal rule, @f$(v^n + v^{n+1})/2@f$ exactly, so the energy they
     * take in a step is @f$A\,\Delta u_f\cdot C\,\Delta u_f/\Delta t
     * \geq 0@f$ (summed as `absorbed_energy`). The face's displacement is that
     * of the grid's interpolation at the face, so the supports are meant for
     * displacements small against the body (a foundation's settlement, a
     * wave), not for a boundary that slides far along them. Their reaction
     * (the material's force on them) is written after every converged step
     * and carries part of the load in the reactions' balance.
     *
     * @tparam dim Space dimension.
     */
    template <int dim>
    class BoundarySupport : public Coupling<dim>
    {
    public:
      /** @brief The supports of a scene's subsection @p section, with
       *  the stiffnesses and viscosities per unit area given. */
      BoundarySupport(const CouplingInputs<dim> &inputs,
                      const std::string         &section,
                      const std::string         &column_prefix,
                      const double               normal_stiffness,
                      const double               tangential_stiffness,
                      const double               normal_viscosity,
                      const double               tangential_viscosity)
        : normal_stiffness(normal_stiffness)
        , tangential_stiffness(tangential_stiffness)
        , normal_viscosity(normal_viscosity)
        , tangential_viscosity(tangential_viscosity)
        , boundary(inputs.prm, section)
        , column_prefix(column_prefix)
        , bodies(inputs.parameters.bodies)
        , grid(inputs.grid)
      {}

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
        // (Dashpots alone hold no static load: a body on them only is
        // free to drift.)
      }

      /** @brief This step's springs: per boundary point and face, the
       *  face's weights, stiffness and start-of-step displacement. */
      void
      begin_attempt(const MaterialPoints<dim> &material_points,
                    const LoadStepSystem<dim> &system,
                    const StepSpan            &span) override
      {
        time_step = span.time_step();
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
                      {
                        const bool normal = d == Names::face_axis(f);
                        spring.stiffness[d][d] =
                          area->second[f] *
                          (normal ? normal_stiffness : tangential_stiffness);
                        spring.damping[d][d] =
                          area->second[f] *
                          (normal ? normal_viscosity : tangential_viscosity);
                      }
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
            if (time_step > 0.)
              spring.force +=
                spring.damping *
                (spring.displacement - spring.start_displacement) / time_step;
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
                    const double value =
                      spring.weights[r / dim] * spring.weights[s / dim] *
                      (spring.stiffness[r % dim][s % dim] +
                       (time_step > 0. ?
                          spring.damping[r % dim][s % dim] / time_step :
                          0.));
                    if (column != numbers::invalid_dof_index && value != 0.)
                      matrix.add(row, column, value);
                  }
              }
          }
        return true;
      }

      /** @brief The springs' and dashpots' work on the material: minus
       *  the springs' mean force over the step (linear in the face's
       *  displacement, so exact) and the dashpots' force of the step's mean
       *  velocity, times the face's displacement in the step. */
      void
      add_step_energy(const LoadStepSystem<dim> &,
                      const NodalVector &,
                      StepEnergy &energy) override
      {
        for (const Spring &spring : springs)
          {
            const Tensor<1, dim> change =
              spring.displacement - spring.start_displacement;
            Tensor<1, dim> mean_force =
              spring.stiffness *
              (0.5 * (spring.displacement + spring.start_displacement));
            if (time_step > 0.)
              mean_force += spring.damping * change / time_step;
            energy.external_work -= mean_force * change;
          }
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
        double              energy = 0.;
        std::vector<double> local;
        for (const Spring &spring : springs)
          {
            force += spring.force;
            if (time_step > 0.)
              {
                const Tensor<1, dim> change =
                  spring.displacement - spring.start_displacement;
                energy += change * (spring.damping * change) / time_step;
              }
            local.push_back(static_cast<double>(spring.key.first));
            local.push_back(spring.key.second);
            for (unsigned int d = 0; d < dim; ++d)
              local.push_back(spring.displacement[d]);
          }
        for (unsigned int d = 0; d < dim; ++d)
          accepted_force[d] = Utilities::MPI::sum(force[d], communicator);
        absorbed_energy += Utilities::MPI::sum(energy, communicator);
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
        state.set(state_key() + ".face displacements", values);
        if (has_dashpots())
          state.set(state_key() + ".absorbed energy", absorbed_energy);
      }

      void
      load(const RunState &state) override
      {
        face_displacement.clear();
        read_displacements(state.get_list(state_key() + ".face displacements"));
        if (has_dashpots())
          absorbed_energy = state.get_double(state_key() + ".absorbed energy");
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
          columns.push_back(column_prefix + "_force_" + Names::axis(d));
        if (has_dashpots())
          columns.push_back("absorbed_energy");
        return columns;
      }

      void
      step_measures(const double,
                    std::vector<StepMeasure> &measures) const override
      {
        for (unsigned int d = 0; d < dim; ++d)
          measures.push_back(
            {column_prefix + "_force_" + Names::axis(d),
             (column_prefix == "springs" ? "W" : "A") + Names::axis(d),
             accepted_force[d],
             MeasureKind::force});
        if (has_dashpots())
          measures.push_back(
            {"absorbed_energy", "Ea", absorbed_energy, MeasureKind::energy});
      }

      /** @brief The springs' stiffer direction, for the stable explicit
       *  step. */
      double
      surface_stiffness() const override
      {
        return std::max(normal_stiffness, tangential_stiffness);
      }

      /** @brief Dashpots act on the step's mean velocity, the increment
       *  over the time step, which an explicit step does not solve for. */
      std::string
      explicit_step_conflict() const override
      {
        if (!has_dashpots())
          return "";
        return "Absorbing boundary: its dashpots act on the step's mean "
               "velocity, which an explicit step does not solve for; use an "
               "implicit integrator (Newmark or generalised-alpha).";
      }

    protected:
      /** The springs' stiffness (Pa/m) and the dashpots' viscosity
       *  (Pa s/m) per unit area, along the face's normal and across it. */
      const double normal_stiffness;
      const double tangential_stiffness;
      const double normal_viscosity;
      const double tangential_viscosity;

      /** @brief Whether the supports have dashpots. */
      bool
      has_dashpots() const
      {
        return normal_viscosity > 0. || tangential_viscosity > 0.;
      }

      /** @brief The key of the supports' entries in a checkpoint. */
      std::string
      state_key() const
      {
        return column_prefix == "springs" ? "winkler springs" : column_prefix;
      }

      /** @brief One line on the supports: @p what, then where. */
      std::string
      description(const std::string &what) const
      {
        std::ostringstream out;
        out << what << ", under the " << boundary.description();
        if (boundary.n_points() > 0)
          out << " (" << boundary.n_points() << " points, area "
              << boundary.total_area() << ")";
        return out.str();
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
        /** The dashpots' viscosity times their area (N s/m). */
        Tensor<2, dim> damping;
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

      BoundarySelection<dim> boundary;
      /** The first word of the force columns in steps.csv. */
      const std::string             column_prefix;
      const std::vector<Body<dim>> &bodies;
      const BackgroundGrid<dim>    &grid;
      /** Whether the boundary points are found (at the first step). */
      bool                selected = false;
      std::vector<Spring> springs;
      /** Each spring's face displacement at the last accepted step. */
      std::map<Key, Tensor<1, dim>> face_displacement;
      /** The material's force on the springs at the last accepted step. */
      Tensor<1, dim> accepted_force;
      /** The step's duration (0 in a scene without time: no dashpots). */
      double time_step = 0.;
      /** The energy the dashpots took since the start. */
      double absorbed_energy = 0.;
    };



    /**
     * @brief Elastic (Winkler) springs under a part of a body's boundary
     * (BoundarySupport with springs only).
     *
     * A coupling: a class and its registration line, nothing else (doc/
     * architecture.md, "Adding a coupling").
     */
    template <int dim>
    class WinklerSprings : public BoundarySupport<dim>
    {
    public:
      /** @brief The subsection's entries. */
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
        : BoundarySupport<dim>(inputs,
                               "Winkler springs",
                               "springs",
                               inputs.prm.get_double("Normal stiffness"),
                               inputs.prm.get_double("Tangential stiffness"),
                               0.,
                               0.)
      {
        if (!(this->normal_stiffness > 0.) &&
            !(this->tangential_stiffness > 0.))
          throw InputError("Winkler springs: give a 'Normal stiffness' or a "
                           "'Tangential stiffness' above zero (both are 0).");
      }

      std::vector<std::string>
      descriptions() const override
      {
        std::ostringstream out;
        out << "Winkler springs: " << this->normal_stiffness << " Pa/m normal, "
            << this->tangential_stiffness << " Pa/m tangential";
        return {this->description(out.str())};
      }
    };



    /**
     * @brief A viscous absorbing boundary (Lysmer and Kuhlemeyer 1969) on
     * a part of a body's boundary: dashpots of viscosity @f$\rho c_p@f$
     * along the face's normal and @f$\rho c_s@f$ across it per unit area
     * (BoundarySupport with dashpots only), from the density and elastic
     * constants of the material next to it: @f$c_p = \sqrt{(\lambda +
     * 2\mu)/\rho}@f$, @f$c_s = \sqrt{\mu/\rho}@f$. A plane wave that
     * meets it at normal incidence leaves without reflection; waves at
     * other angles are partly reflected. It needs time (`Time/End time`),
     * and holds no static load: a body under gravity on it needs a
     * support too (or an initial stress and its reaction).
     */
    template <int dim>
    class AbsorbingBoundary : public BoundarySupport<dim>
    {
    public:
      /** @brief The subsection's entries. */
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Enabled",
                          "false",
                          Patterns::Bool(),
                          "Whether a part of a body's boundary lets waves "
                          "out through viscous dashpots (Lysmer and "
                          "Kuhlemeyer). Off: not created, costs nothing.");
        BoundarySelection<dim>::declare_parameters(prm, "absorbing");
        prm.declare_entry("Density",
                          "0",
                          Patterns::Double(0.),
                          "Density of the material outside, kg/m^3 (> 0).");
        prm.declare_entry("Young's modulus",
                          "0",
                          Patterns::Double(0.),
                          "Young's modulus of the material outside, Pa "
                          "(> 0).");
        prm.declare_entry("Poisson's ratio",
                          "0",
                          Patterns::Double(-1., 0.5),
                          "Poisson's ratio of the material outside (-1 to "
                          "below 0.5).");
      }

      /** @brief The dashpots of a scene (from its subsection). */
      explicit AbsorbingBoundary(const CouplingInputs<dim> &inputs)
        : BoundarySupport<dim>(inputs,
                               "Absorbing boundary",
                               "absorbing",
                               0.,
                               0.,
                               normal_impedance(inputs),
                               shear_impedance(inputs))
      {
        if (!inputs.time.in_time())
          throw InputError("Absorbing boundary needs time: set 'Time/End "
                           "time' above 0.");
      }

      std::vector<std::string>
      descriptions() const override
      {
        std::ostringstream out;
        out << "absorbing boundary: dashpots of " << this->normal_viscosity
            << " Pa s/m normal, " << this->tangential_viscosity
            << " Pa s/m tangential";
        return {this->description(out.str())};
      }

    private:
      /** @brief rho c_p from the subsection's entries (checked). */
      static double
      normal_impedance(const CouplingInputs<dim> &inputs)
      {
        const double rho = inputs.prm.get_double("Density");
        const double E   = inputs.prm.get_double("Young's modulus");
        const double nu  = inputs.prm.get_double("Poisson's ratio");
        if (!(rho > 0.) || !(E > 0.) || !(nu < 0.5))
          throw InputError("Absorbing boundary: give the 'Density' and "
                           "'Young's modulus' (> 0) and 'Poisson's ratio' "
                           "(below 0.5) of the material outside.");
        return std::sqrt(rho * E * (1. - nu) / ((1. + nu) * (1. - 2. * nu)));
      }

      /** @brief rho c_s from the subsection's entries. */
      static double
      shear_impedance(const CouplingInputs<dim> &inputs)
      {
        const double rho = inputs.prm.get_double("Density");
        const double E   = inputs.prm.get_double("Young's modulus");
        const double nu  = inputs.prm.get_double("Poisson's ratio");
        return std::sqrt(rho * E / (2. * (1. + nu)));
      }
    };
  } // namespace

  IMPM_REGISTER_COUPLING(WinklerSprings,
                         "Winkler springs",
                         inputs.prm.get_bool("Enabled"),
                         ([](ParameterHandler &prm) {
                           WinklerSprings<dim>::declare_parameters(prm);
                         }))
  IMPM_REGISTER_COUPLING(AbsorbingBoundary,
                         "Absorbing boundary",
                         inputs.prm.get_bool("Enabled"),
                         ([](ParameterHandler &prm) {
                           AbsorbingBoundary<dim>::declare_parameters(prm);
                         }))
} // namespace impm
