#include <deal.II/base/mpi.h>

#include <impm/assembly/assembler.h>
#include <impm/mechanics/equilibrium_forms.h>
#include <impm/mechanics/point_stiffness.h>
#include <impm/mechanics/pulled_back_stress.h>
#include <impm/system/dense_block_adder.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <type_traits>

namespace impm
{
  template <int dim>
  Assembler<dim>::Assembler(
    const MaterialPoints<dim>                            &material_points,
    LoadStepSystem<dim>                                  &system,
    const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects,
    Coupling<dim>                                        *volume_coupling,
    const MPI_Comm                                        communicator)
    : material_points(material_points)
    , system(system)
    , force_effects(force_effects)
    , volume_coupling(volume_coupling)
    , communicator(communicator)
  {}



  template <int dim>
  void
  Assembler<dim>::set_start_stresses()
  {
    for (const auto &point : material_points.particles())
      {
        PointStep<dim>       &step = system.point_steps.of(point);
        const PointState<dim> state(point.get_properties());
        step.deformation_increment         = unit_symmetric_tensor<dim>();
        step.deformation_increment_inverse = unit_symmetric_tensor<dim>();
        step.update.kirchhoff_stress       = state.kirchhoff_stress();
        step.update.elastic_left_cauchy_green =
          state.elastic_left_cauchy_green();
        step.update.plastic            = false;
        step.update.plastic_multiplier = 0.;
        step.update.elastic_energy = std::numeric_limits<double>::quiet_NaN();
      }
  }



  template <int dim>
  bool
  Assembler<dim>::update_stresses(const NodalVector &increment)
  {
    bool admissible = true;
    // The return map of one point (once its increment is known); false
    // if it failed.
    const auto update_point = [&](PointStep<dim>                &step,
                                  const ArrayView<const double> &properties) {
      // An increment whose trial elastic strain is not positive definite
      // in floating point (a wild iterate: the model throws) fails the
      // Newton solve.
      try
        {
          // Only a model that sets it leaves an energy (no stale one).
          step.update.elastic_energy = std::numeric_limits<double>::quiet_NaN();
          step.material->update(
            step.full_deformation_increment(),
            PointState<dim>(properties).elastic_left_cauchy_green(),
            material_points.material_state(properties),
            step.update);
          return true;
        }
      catch (const ExceptionBase &)
        {
          admissible = false;
          return false;
        }
    };
    auto                                &point_steps  = system.point_steps;
    const bool                           axisymmetric = system.axisymmetric();
    std::vector<ArrayView<const double>> point_properties;
    if (volume_coupling != nullptr)
      point_properties.resize(point_steps.size());
    for (const auto &point : material_points.particles())
      {
        PointStep<dim> &step = point_steps.of(point);
        if (volume_coupling != nullptr)
          point_properties[point_steps.index_of(point)] =
            point.get_properties();
        const auto    &s  = step.support;
        Tensor<2, dim> dF = unit_symmetric_tensor<dim>();
        for (unsigned int v = 0; v < s.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            {
              const double du = increment.local_element(step.dofs[v * dim + i]);
              for (unsigned int j = 0; j < dim; ++j)
                dF[i][j] += du * s.gradients[v][j];
            }
        step.deformation_increment = dF;
        // An inverted or non-finite increment fails the Newton solve (and
        // lets the step control cut the step).
        const double jacobian = determinant(dF);
        if (!(jacobian > 0.) || !std::isfinite(jacobian))
          {
            admissible = false;
            continue;
          }
        step.deformation_increment_inverse = invert(dF);
        // Axisymmetry: the hoop stretch r^{n+1} / r^n (its average over
        // the point's ring).
        if (axisymmetric)
          {
            double hoop_strain = 0.;
            for (unsigned int v = 0; v < s.n_nodes; ++v)
              hoop_strain +=
                s.hoop_weights[v] * increment.local_element(step.dofs[v * dim]);
            step.hoop_increment = 1. + hoop_strain;
            if (!(step.hoop_increment > 0.) ||
                !std::isfinite(step.hoop_increment))
              {
                admissible = false;
                continue;
              }
            step.material_hoop_increment = step.hoop_increment;
            // The point itself must stay off the axis too: the hoop
            // stretch is its ring's average (GIMP), which can stay
            // positive while the point crosses r = 0 (its ring turned
            // inside out, an inverted point; the run ended with the point
            // outside the grid).
            if (!(point.get_location()[0] + step.displacement(increment)[0] >
                  0.))
              {
                admissible = false;
                continue;
              }
          }
        // Without a coupling that sets the volumes each point is updated
        // at once; with it, through the coupling once every increment is
        // known.
        if (volume_coupling == nullptr)
          update_point(step, point.get_properties());
      }
    if (volume_coupling != nullptr &&
        Utilities::MPI::min(admissible ? 1 : 0, communicator) == 1)
      admissible = volume_coupling->update_stresses(
        point_steps, [&](const unsigned int q) {
          return update_point(point_steps[q], point_properties[q]);
        });
    return Utilities::MPI::min(admissible ? 1 : 0, communicator) == 1;
  }



  template <int dim>
  void
  Assembler<dim>::assemble_external_force(const double load_factor,
                                          NodalVector &external_force) const
  {
    external_force = 0.;
    if (!force_effects.empty())
      {
        const auto infos = material_points.infos(system.point_steps);
        std::vector<Tensor<1, dim>> forces(infos.size());
        std::vector<FaceForce<dim>> face_forces;
        for (const auto &effect : force_effects)
          {
            effect->add_forces(infos, load_factor, forces);
            effect->add_face_forces(infos, load_factor, face_forces);
          }
        for (unsigned int p = 0; p < infos.size(); ++p)
          {
            const PointStep<dim> &step = system.point_steps[p];
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                external_force.local_element(step.dofs[v * dim + i]) +=
                  step.support.weights[v] * forces[p][i];
          }
        if (!face_forces.empty())
          {
            // The start-of-step positions and domains of the points.
            std::vector<std::pair<Point<dim>, Tensor<1, dim>>> domains(
              infos.size());
            for (const auto &point : material_points.particles())
              domains[system.point_steps.index_of(point)] = {
                point.get_location(),
                PointState<dim>(point.get_properties()).domain_half_length()};
            std::array<double, PointSupport<dim>::max_nodes> weights;
            for (const auto &face : face_forces)
              {
                const PointStep<dim> &step = system.point_steps[face.point];
                system.face_weights(face.point,
                                    domains[face.point].first,
                                    domains[face.point].second,
                                    face.axis,
                                    face.sign,
                                    weights);
                for (unsigned int v = 0; v < step.support.n_nodes; ++v)
                  for (unsigned int i = 0; i < dim; ++i)
                    external_force.local_element(step.dofs[v * dim + i]) +=
                      weights[v] * face.force[i];
              }
          }
      }
    external_force.compress(VectorOperation::add);
  }



  namespace
  {
    /**
     * @brief Axisymmetry: add one point's hoop force to its radial nodal
     * forces, @f$f_{v,r} \mathrel{+}= T \bar N_{\theta,v}@f$ with the
     * statement's hoop weights @f$\bar N_{\theta,v}@f$ and their factor
     * @f$T@f$ (PreviouslyConvergedForm::hoop_force_stress(),
     * UpdatedLagrangianForm::hoop_force_stress()).
     */
    template <int dim>
    void
    add_hoop_forces(const PointStep<dim> &step,
                    const double          hoop_force_stress,
                    const double         *hoop_weights,
                    double               *forces)
    {
      for (unsigned int v = 0; v < step.support.n_nodes; ++v)
        forces[v * dim] += hoop_force_stress * hoop_weights[v];
    }


    /**
     * @brief The assembler of one statement of equilibrium, @p Form
     * (PreviouslyConvergedForm or UpdatedLagrangianForm).
     */
    template <int dim, typename Form>
    class FormAssembler : public Assembler<dim>
    {
    public:
      /** The updated Lagrangian form maps the gradients to the current
       * configuration. */
      static constexpr bool maps_gradients =
        std::is_same_v<Form, UpdatedLagrangianForm<dim>>;

      /** @brief Constructor: see Assembler::create(). */
      FormAssembler(
        const MaterialPoints<dim>                            &material_points,
        LoadStepSystem<dim>                                  &system,
        const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects,
        Coupling<dim>                                        *volume_coupling,
        const MPI_Comm                                        communicator)
        : Assembler<dim>(material_points,
                         system,
                         force_effects,
                         volume_coupling,
                         communicator)
      {}

      const Tensor<1, dim> *
      gradients(const unsigned int p) const override
      {
        if constexpr (maps_gradients)
          return mapped_gradients[p].data();
        else
          return this->system.point_steps[p].support.gradients.data();
      }

      Tensor<2, dim>
      gradient_map(const unsigned int p) const override
      {
        if constexpr (maps_gradients)
          return unit_symmetric_tensor<dim>();
        else
          return this->system.point_steps[p].deformation_increment_inverse;
      }

      const double *
      hoop_weights(const unsigned int p) const override
      {
        if constexpr (maps_gradients)
          return p < mapped_hoop_weights.size() ?
                   mapped_hoop_weights[p].data() :
                   nullptr; // not axisymmetric: none mapped
        else
          return this->system.point_steps[p].support.hoop_weights.data();
      }

      double
      hoop_map(const unsigned int p) const override
      {
        return Form::hoop_map(this->system.point_steps[p].hoop_increment);
      }

      void
      add_internal_force(NodalVector &internal_force) override
      {
        auto      &point_steps  = this->system.point_steps;
        const bool axisymmetric = this->system.axisymmetric();
        // The updated Lagrangian form keeps its mapped gradients for the
        // matrix of this iterate.
        if constexpr (maps_gradients)
          {
            mapped_gradients.resize(point_steps.size());
            if (axisymmetric)
              mapped_hoop_weights.resize(point_steps.size());
          }
        std::array<double, PointSupport<dim>::max_nodes * dim> forces;
        for (unsigned int p = 0; p < point_steps.size(); ++p)
          {
            const PointStep<dim> &step      = point_steps[p];
            const Tensor<1, dim> *gradients = step.support.gradients.data();
            if constexpr (maps_gradients)
              {
                Form::map_gradients(gradients,
                                    step.support.n_nodes,
                                    step.deformation_increment_inverse,
                                    mapped_gradients[p].data());
                gradients = mapped_gradients[p].data();
              }
            const Tensor<2, dim> stress =
              Form::force_stress(step.update,
                                 step.deformation_increment_inverse,
                                 step.initial_volume);
            const unsigned int n = step.support.n_nodes * dim;
            std::fill(forces.begin(), forces.begin() + n, 0.);
            add_point_forces(stress,
                             gradients,
                             step.support.n_nodes,
                             forces.data());
            if (axisymmetric)
              {
                if constexpr (maps_gradients)
                  for (unsigned int v = 0; v < step.support.n_nodes; ++v)
                    mapped_hoop_weights[p][v] =
                      step.support.hoop_weights[v] / step.hoop_increment;
                add_hoop_forces(step,
                                Form::hoop_force_stress(step.update,
                                                        step.hoop_increment,
                                                        step.initial_volume),
                                hoop_weights(p),
                                forces.data());
              }
            for (unsigned int k = 0; k < n; ++k)
              internal_force.local_element(step.dofs[k]) += forces[k];
          }
      }

      void
      add_stiffness(TrilinosWrappers::SparseMatrix &matrix) const override
      {
        const auto    &point_steps     = this->system.point_steps;
        Coupling<dim> *volume_coupling = this->volume_coupling;
        const bool     axisymmetric    = this->system.axisymmetric();
        // One support's dense matrix (52 kB in 3D): on the heap.
        const auto stiffness = std::make_unique<PointStiffness<dim>>();
        std::array<Tensor<1, dim>, PointSupport<dim>::max_nodes>
          group_gradients;
        // Axisymmetry: the hoop weights on the group's support.
        std::array<double, PointSupport<dim>::max_nodes> group_hoop_weights;
        for (const AssemblyGroup &group : this->system.assembly_groups)
          {
            // The group's matrix over all its support's DoFs; the rows and
            // columns in the linear system are picked when it is added.
            // A volume coupling's point term has no major symmetry.
            // The hoop terms are added to every entry (general).
            const bool symmetric =
              volume_coupling == nullptr && !axisymmetric &&
              std::all_of(
                group.points.begin(),
                group.points.end(),
                [&](const unsigned int p) {
                  return point_steps[p].material->has_symmetric_tangent();
                });
            stiffness->reset(group.n_nodes,
                             symmetric ? TangentSymmetry::major :
                                         TangentSymmetry::general);
            const unsigned char *node_positions = group.node_positions.data();
            for (const unsigned int p : group.points)
              {
                const PointStep<dim> &step = point_steps[p];
                HoopTangent<dim>      hoop;
                Tensor<4, dim>        tangent =
                  axisymmetric ?
                           Form::axisymmetric_tangent(
                      *step.material,
                      step.update,
                      step.deformation_increment_inverse,
                      step.hoop_increment,
                      step.initial_volume,
                      hoop) :
                           Form::tangent(*step.material,
                                  step.update,
                                  step.deformation_increment_inverse,
                                  step.initial_volume);
                if (volume_coupling != nullptr)
                  tangent = volume_coupling->point_tangent(
                    p,
                    tangent,
                    Form::force_stress(step.update,
                                       step.deformation_increment_inverse,
                                       step.initial_volume),
                    gradient_map(p),
                    axisymmetric ? &hoop : nullptr,
                    Form::hoop_force_stress(step.update,
                                            step.hoop_increment,
                                            step.initial_volume),
                    hoop_map(p));
                const Tensor<1, dim> *gradients = this->gradients(p);
                const double         *weights_over_radius =
                  axisymmetric ? hoop_weights(p) : nullptr;
                if (!group.node_positions.empty())
                  {
                    // The point's gradients on the group's support, zero
                    // on the nodes the point's support lacks.
                    std::fill(group_gradients.begin(),
                              group_gradients.begin() + group.n_nodes,
                              Tensor<1, dim>());
                    if (axisymmetric)
                      {
                        std::fill(group_hoop_weights.begin(),
                                  group_hoop_weights.begin() + group.n_nodes,
                                  0.);
                        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
                          group_hoop_weights[node_positions[v]] =
                            weights_over_radius[v];
                        weights_over_radius = group_hoop_weights.data();
                      }
                    for (unsigned int v = 0; v < step.support.n_nodes; ++v)
                      group_gradients[*node_positions++] = gradients[v];
                    gradients = group_gradients.data();
                  }
                stiffness->add(tangent, gradients, group.in_system.data());
                if (axisymmetric)
                  stiffness->add_hoop(hoop,
                                      weights_over_radius,
                                      gradients,
                                      group.in_system.data());
              }
            // Read in place: each entry is one gather.
            stiffness->complete();
            const unsigned int n = group.rows.size();
            row_offsets.resize(n);
            column_offsets.resize(n);
            for (unsigned int a = 0; a < n; ++a)
              {
                row_offsets[a]    = stiffness->row_offset(group.local[a]);
                column_offsets[a] = stiffness->column_offset(group.local[a]);
              }
            block_adder.add(group.rows.data(),
                            n,
                            StoredBlock{stiffness->data(),
                                        row_offsets.data(),
                                        column_offsets.data()},
                            matrix,
                            this->system.off_process_rows);
          }
      }

    private:
      /**
       * Updated Lagrangian form only: the gradients mapped by the last
       * internal-force assembly, reused by the matrix of the same iterate.
       */
      std::vector<std::array<Tensor<1, dim>, PointSupport<dim>::max_nodes>>
        mapped_gradients;
      /**
       * Updated Lagrangian form in axisymmetry only: the hoop weights mapped
       * to the current configuration, @f$\bar N_v / \Delta F_{\theta
       * \theta}@f$, by the last internal-force assembly.
       */
      std::vector<std::array<double, PointSupport<dim>::max_nodes>>
        mapped_hoop_weights;
      /** Adds the groups' blocks to the matrix. */
      mutable DenseBlockAdder block_adder;
      /** Where a group's rows and columns are in its stiffness's data. */
      mutable std::vector<unsigned int> row_offsets, column_offsets;
    };
  } // namespace



  template <int dim>
  std::unique_ptr<Assembler<dim>>
  Assembler<dim>::create(
    const Parameters::Formulation                         formulation,
    const MaterialPoints<dim>                            &material_points,
    LoadStepSystem<dim>                                  &system,
    const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects,
    Coupling<dim>                                        *volume_coupling,
    const MPI_Comm                                        communicator)
  {
    switch (formulation)
      {
        case Parameters::Formulation::updated_lagrangian:
          return std::make_unique<
            FormAssembler<dim, UpdatedLagrangianForm<dim>>>(material_points,
                                                            system,
                                                            force_effects,
                                                            volume_coupling,
                                                            communicator);
        default:
          return std::make_unique<
            FormAssembler<dim, PreviouslyConvergedForm<dim>>>(material_points,
                                                              system,
                                                              force_effects,
                                                              volume_coupling,
                                                              communicator);
      }
  }



  template class Assembler<2>;
  template class Assembler<3>;
} // namespace impm
