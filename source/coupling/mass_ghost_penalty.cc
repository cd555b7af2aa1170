// The ghost penalty of the mass for the implicit time integrators.
#include <impm/base/errors.h>
#include <impm/coupling/mass_ghost_penalty.h>

#include <algorithm>
#include <sstream>

namespace impm
{
  template <int dim>
  void
  MassGhostPenalty<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Mass ghost penalty",
      "0",
      Patterns::Double(0.),
      "Implicit integrators: gamma_m >= 0, the ghost penalty of the mass: "
      "gamma_m rho h^3 times the integral of the products of the jumps of "
      "the acceleration's normal gradient across the faces of cells filled "
      "to less than 'Mass ghost fill threshold' (rho the largest density "
      "of the bodies), added to the inertial force and the matrix. It keeps "
      "the matrix well conditioned where a small time step makes the mass "
      "dominate and a barely filled cell gives a node a tiny mass (the "
      "stiffness's 'Ghost stabilisation' is then too weak). A linear field "
      "of acceleration is not penalised. 0: none. The explicit integrators "
      "refuse it (their lumped mass has no matrix).");
    prm.declare_entry("Mass ghost fill threshold",
                      "0.9",
                      Patterns::Double(0., 10.),
                      "With 'Mass ghost penalty': cells whose points' "
                      "current volume is less than this fraction of the "
                      "cell's volume are stabilised (0 to 10).");
  }



  template <int dim>
  MassGhostPenalty<dim>::MassGhostPenalty(const ParameterHandler    &prm,
                                          const TimeIntegrator      &integrator,
                                          const BackgroundGrid<dim> &grid,
                                          const std::vector<Body<dim>> &bodies)
    : integrator(integrator)
    , penalty_scale(prm.get_double("Mass ghost penalty"))
    , fill_threshold(prm.get_double("Mass ghost fill threshold"))
  {
    if (penalty_scale == 0.)
      return;
    if (integrator.is_explicit())
      throw InputError(
        "Inertia: 'Mass ghost penalty' acts on the matrix of the implicit "
        "integrators; an explicit one has none (its mass is lumped): set "
        "it to 0, or choose Newmark or generalised-alpha.");
    double density = 0.;
    for (const auto &body : bodies)
      density = std::max(density, body.density);
    penalty = std::make_unique<FaceJumpPenalty<dim>>(
      grid, penalty_scale, density, 3, fill_threshold);
  }



  template <int dim>
  void
  MassGhostPenalty<dim>::choose_faces(
    const MaterialPoints<dim> &material_points,
    const std::vector<bool>   &touched)
  {
    if (penalty)
      penalty->choose_faces(material_points, touched);
  }



  template <int dim>
  void
  MassGhostPenalty<dim>::add_blocks(
    const LoadStepSystem<dim>                         &system,
    std::vector<std::vector<types::global_dof_index>> &blocks) const
  {
    if (penalty)
      penalty->add_blocks(system, blocks);
  }



  template <int dim>
  void
  MassGhostPenalty<dim>::add_forces(const NodalVector &increment,
                                    const double       time_step,
                                    NodalVector       &force) const
  {
    if (penalty)
      penalty->add_forces(increment, factor(time_step), force);
  }



  template <int dim>
  double
  MassGhostPenalty<dim>::dissipation(const NodalVector &increment,
                                     const double       time_step) const
  {
    if (!penalty)
      return 0.;
    NodalVector force;
    force.reinit(increment);
    penalty->add_forces(increment, factor(time_step), force);
    force.compress(VectorOperation::add);
    double sum = 0.;
    for (unsigned int i = 0; i < force.locally_owned_size(); ++i)
      sum += 0.5 * force.local_element(i) * increment.local_element(i);
    return sum;
  }



  template <int dim>
  void
  MassGhostPenalty<dim>::add_matrix(
    const LoadStepSystem<dim>      &system,
    const double                    time_step,
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    if (penalty)
      penalty->add_matrix(system, matrix, factor(time_step));
  }



  template <int dim>
  double
  MassGhostPenalty<dim>::factor(const double time_step) const
  {
    return integrator.k_m() / (integrator.beta * time_step * time_step);
  }



  template <int dim>
  std::string
  MassGhostPenalty<dim>::description() const
  {
    std::ostringstream out;
    out << "mass ghost penalty " << penalty_scale << " (fill threshold "
        << fill_threshold << ")";
    return out.str();
  }



  template class MassGhostPenalty<2>;
  template class MassGhostPenalty<3>;
} // namespace impm
