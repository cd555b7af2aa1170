// Ghost stabilisation as a coupling: the stiffness's face penalty.
#include <impm/assembly/ghost_stabilisation.h>
#include <impm/base/errors.h>

#include <algorithm>

namespace impm
{
  namespace Parameters
  {
    void
    Stabilisation::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Enabled",
                        "true",
                        Patterns::Bool(),
                        "Penalise the jump of the normal gradient of the "
                        "displacement increment across faces between two "
                        "cells in the system when one of them is filled "
                        "to less than 'Fill threshold', so that a node fed "
                        "only by the edge of a point's domain cannot make "
                        "the system singular. Explicit steps do not use "
                        "it. With implicit inertia it also holds back a "
                        "thin flowing front (the front's nodes carry too "
                        "little mass to outweigh it at any step): a "
                        "granular column ran out 1.16-1.19 L0 with it and "
                        "1.32 without, at steps from 0.0025 to 0.000625 "
                        "s; there the lumped mass keeps the system "
                        "regular, and switching it off (or a smaller "
                        "'Penalty scale') lets the implicit run-out meet "
                        "the explicit one (doc/benchmarks/inertia.md).");
      prm.declare_entry("Penalty scale",
                        "0.01",
                        Patterns::Double(0.),
                        "gamma >= 0: the face penalty is gamma E h times the "
                        "integral of the products of the jumps.");
      prm.declare_entry("Fill threshold",
                        "0.9",
                        Patterns::Double(0., 10.),
                        "Cells whose points' current volume is less than "
                        "this fraction of the cell's volume are treated as "
                        "partly filled (0 to 10).");
    }



    void
    Stabilisation::parse_parameters(ParameterHandler &prm)
    {
      enabled        = prm.get_bool("Enabled");
      penalty_scale  = prm.get_double("Penalty scale");
      fill_threshold = prm.get_double("Fill threshold");
    }
  } // namespace Parameters



  namespace
  {
    /** The largest Young's modulus of @p bodies. */
    template <int dim>
    double
    largest_modulus(const std::vector<Body<dim>> &bodies)
    {
      double modulus = 0.;
      for (const auto &body : bodies)
        modulus = std::max(modulus, body.material->elastic_modulus());
      return modulus;
    }
  } // namespace



  template <int dim>
  GhostStabilisation<dim>::GhostStabilisation(
    const Parameters::Stabilisation &parameters,
    const BackgroundGrid<dim>       &grid,
    const std::vector<Body<dim>>    &bodies)
    : parameters(parameters)
    , penalty(grid,
              parameters.penalty_scale,
              largest_modulus(bodies),
              1,
              parameters.fill_threshold)
  {}



  template <int dim>
  std::string
  GhostStabilisation<dim>::description() const
  {
    if (explicit_steps)
      return "ghost stabilisation: not used by explicit steps (they solve no "
             "system)";
    return "ghost stabilisation: penalty scale " +
           number_text(parameters.penalty_scale) + ", fill threshold " +
           number_text(parameters.fill_threshold);
  }



  template <int dim>
  GhostStabilisation<dim>::GhostStabilisation(const CouplingInputs<dim> &inputs)
    : GhostStabilisation(
        [&inputs]() {
          Parameters::Stabilisation parameters;
          parameters.parse_parameters(inputs.prm);
          return parameters;
        }(),
        inputs.grid,
        inputs.parameters.bodies)
  {}



  template <int dim>
  unsigned int
  GhostStabilisation<dim>::prepare(const MaterialPoints<dim> &material_points,
                                   const LoadStepSystem<dim> &,
                                   const std::vector<bool> &touched)
  {
    if (!explicit_steps)
      penalty.choose_faces(material_points, touched);
    return 0;
  }



  template <int dim>
  void
  GhostStabilisation<dim>::use_explicit_steps(const double)
  {
    explicit_steps = true;
  }



  template <int dim>
  void
  GhostStabilisation<dim>::setup(
    const MaterialPoints<dim> &,
    const LoadStepSystem<dim> &system,
    const CouplingRows &,
    std::vector<std::vector<types::global_dof_index>> &blocks)
  {
    penalty.add_blocks(system, blocks);
  }



  template <int dim>
  void
  GhostStabilisation<dim>::add_forces(const LoadStepSystem<dim> &,
                                      const NodalVector &increment,
                                      NodalVector       &internal_force)
  {
    penalty.add_forces(increment, 1., internal_force);
  }



  template <int dim>
  void
  GhostStabilisation<dim>::add_step_energy(const LoadStepSystem<dim> &,
                                           const NodalVector &increment,
                                           StepEnergy        &energy)
  {
    NodalVector force;
    force.reinit(increment);
    penalty.add_forces(increment, 1., force);
    force.compress(VectorOperation::add);
    // Half the force times the increment: the penalty grows from zero
    // with the step's increment and starts from zero again in the next.
    for (unsigned int i = 0; i < force.locally_owned_size(); ++i)
      energy.dissipated +=
        0.5 * force.local_element(i) * increment.local_element(i);
  }



  template <int dim>
  bool
  GhostStabilisation<dim>::add_constant_matrix(
    const LoadStepSystem<dim>      &system,
    TrilinosWrappers::SparseMatrix &matrix)
  {
    penalty.add_matrix(system, matrix, 1.);
    return true;
  }



  template <int dim>
  std::vector<std::string>
  GhostStabilisation<dim>::descriptions() const
  {
    return {description()};
  }



  template class GhostStabilisation<2>;
  template class GhostStabilisation<3>;

  IMPM_REGISTER_COUPLING(GhostStabilisation,
                         "Ghost stabilisation",
                         inputs.prm.get_bool("Enabled"),
                         ([](ParameterHandler &prm) {
                           Parameters::Stabilisation::declare_parameters(prm);
                         }))
} // namespace impm
