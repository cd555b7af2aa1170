// Rigid contact as a coupling (Coupling's functions that are not the
// contact's own): its creation from the scene, its point state, the start
// of an attempt, the contact of the step's start (for the start's
// residual), the matrix, the support it gives and its share of the
// load, and the registration. The probes and forces are in
// rigid_contact.cc, the bodies' unknowns in rigid_contact_unknowns.cc.
#include <impm/contact/rigid_contact.h>
#include <impm/system/load_step_system.h>

#include <cmath>

namespace impm
{
  template <int dim>
  RigidContact<dim>::RigidContact(const CouplingInputs<dim> &inputs)
    : RigidContact(inputs.parameters.rigid_bodies, inputs.grid)
  {
    maximum_motion = inputs.prm.get_double("Maximum motion per step");
  }



  template <int dim>
  void
  RigidContact<dim>::use_explicit_steps(const double)
  {
    // A block striking a plate at 4.5 m/s presses its faces up to
    // 4.7 h / alpha in (tests/inertia_free_fall.prm, explicit MUSL).
    explicit_steps = true;
  }



  template <int dim>
  std::string
  RigidContact<dim>::explicit_step_conflict() const
  {
    if (body_unknowns.empty())
      return "";
    return "Rigid body " + std::to_string(body_unknowns.front().body + 1) +
           ": 'Force-driven components' make its displacement an unknown of "
           "the load step's system, which an explicit step does not solve; "
           "prescribe its 'Displacement' or use an implicit integrator "
           "(Newmark or generalised-alpha).";
  }



  template <int dim>
  double
  RigidContact<dim>::round_off_force() const
  {
    return std::sqrt(
      Utilities::MPI::sum(round_off_squared,
                          grid.get_triangulation().get_communicator()));
  }



  template <int dim>
  PointFields
  RigidContact<dim>::point_fields() const
  {
    if (n_traction_entries == 0)
      return {};
    return {{traction_field, n_traction_entries, false}};
  }



  template <int dim>
  void
  RigidContact<dim>::begin_attempt(const MaterialPoints<dim> &material_points,
                                   const LoadStepSystem<dim> &system,
                                   const StepSpan            &span)
  {
    begin(material_points, system, span.start, span.target);
  }



  template <int dim>
  void
  RigidContact<dim>::visit_start_probes(
    const std::function<void(unsigned int, const Probe &)> &visit)
  {
    // evaluate() reads the bodies' poses of the attempt's end: set them to
    // the start's for the evaluation, and back.
    const auto end_displacement = displacement;
    const auto end_rotation     = rotation;
    const auto end_turn         = rotation_increment;
    const auto end_increment    = displacement_increment;
    displacement                = start_displacement;
    rotation                    = start_rotation;
    for (unsigned int b = 0; b < rigid_bodies.size(); ++b)
      {
        rotation_increment[b]     = unit_symmetric_tensor<dim>();
        displacement_increment[b] = Tensor<1, dim>();
      }
    for (unsigned int k = 0; k < probes.size(); ++k)
      {
        Probe probe = probes[k];
        evaluate(probe, probe.start_position);
        visit(k, probe);
      }
    displacement           = end_displacement;
    rotation               = end_rotation;
    rotation_increment     = end_turn;
    displacement_increment = end_increment;
  }



  template <int dim>
  void
  RigidContact<dim>::add_start_forces(const LoadStepSystem<dim> &system,
                                      const NodalVector &,
                                      NodalVector &internal_force)
  {
    visit_start_probes([&](unsigned int, const Probe &probe) {
      if (probe.active)
        subtract_probe_force(probe, system, internal_force);
    });
  }



  template <int dim>
  void
  RigidContact<dim>::add_step_energy(const LoadStepSystem<dim> &system,
                                     const NodalVector         &increment,
                                     StepEnergy                &energy)
  {
    std::vector<Tensor<1, dim>> start_forces(probes.size());
    visit_start_probes([&](unsigned int k, const Probe &probe) {
      if (probe.active)
        start_forces[k] = probe.normal_force + probe.friction_force;
    });
    for (unsigned int k = 0; k < probes.size(); ++k)
      {
        const Probe          &probe = probes[k];
        const PointStep<dim> &step  = system.point_steps[probe.point];
        Tensor<1, dim>        movement;
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            movement[i] += probe.weights[v] *
                           increment.local_element(step.dofs[v * dim + i]);
        Tensor<1, dim> mean_force = 0.5 * start_forces[k];
        if (probe.active)
          mean_force += 0.5 * (probe.normal_force + probe.friction_force);
        energy.external_work += mean_force * movement;
      }
  }



  template <int dim>
  bool
  RigidContact<dim>::add_matrix(const PointGradients<dim> &,
                                const LoadStepSystem<dim>      &system,
                                TrilinosWrappers::SparseMatrix &matrix)
  {
    add_contact_matrix(system, matrix);
    return true;
  }



  template <int dim>
  bool
  RigidContact<dim>::holds_material(const unsigned int) const
  {
    return true;
  }



  template <int dim>
  Tensor<1, dim>
  RigidContact<dim>::force_from_material() const
  {
    Tensor<1, dim> force;
    for (const BodyForce &body_force : forces_on_bodies)
      force += body_force.total;
    return force;
  }



#define IMPM_INSTANTIATE(dim)                                                 \
  template RigidContact<dim>::RigidContact(const CouplingInputs<dim> &);      \
  template PointFields RigidContact<dim>::point_fields() const;               \
  template void RigidContact<dim>::begin_attempt(const MaterialPoints<dim> &, \
                                                 const LoadStepSystem<dim> &, \
                                                 const StepSpan &);           \
  template bool RigidContact<dim>::add_matrix(                                \
    const PointGradients<dim> &,                                              \
    const LoadStepSystem<dim> &,                                              \
    TrilinosWrappers::SparseMatrix &);                                        \
  template bool RigidContact<dim>::holds_material(const unsigned int) const;  \
  template void RigidContact<dim>::use_explicit_steps(const double);          \
  template std::string    RigidContact<dim>::explicit_step_conflict() const;  \
  template double         RigidContact<dim>::round_off_force() const;         \
  template Tensor<1, dim> RigidContact<dim>::force_from_material() const;
  IMPM_INSTANTIATE(2)
  IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE


  IMPM_REGISTER_COUPLING(RigidContact,
                         "Rigid contact",
                         !inputs.parameters.rigid_bodies.empty(),
                         ([](ParameterHandler &prm) {
                           RigidContact<dim>::declare_parameters(prm);
                         }))
} // namespace impm
