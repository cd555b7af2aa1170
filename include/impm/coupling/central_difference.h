#ifndef impm_coupling_central_difference_h
#define impm_coupling_central_difference_h

#include <deal.II/base/mpi.h>

#include <impm/basis/basis_functions.h>
#include <impm/core/rigid_body.h>
#include <impm/coupling/coupling.h>
#include <impm/coupling/nodal_momentum.h>
#include <impm/coupling/stiffness_damping.h>
#include <impm/coupling/time_integrator.h>
#include <impm/mechanics/material.h>
#include <impm/points/material_points.h>
#include <impm/points/point_step.h>

#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /** @brief The smallest cell size of @p grid. */
  template <int dim>
  double
  smallest_cell_size(const CartesianGrid<dim> &grid);

  /**
   * @brief The stiffness the rigid bodies' contact adds to the explicit
   * rule, as a factor of the touching material's Young's modulus: the
   * largest penalty factor of @p rigid_bodies (the normal one; the
   * tangential one too where a body has friction), 0 without rigid bodies.
   *
   * A contact face's penalty (RigidBody::penalty_factor times E/h per area)
   * adds a spring of about @f$\alpha E@f$ (per unit of thickness in 2D) to
   * the nodes of a cell at the surface, whose lumped mass is about half a
   * cell's; with the material's own stiffness (a row sum of @f$2M/h@f$ per
   * unit area, Gershgorin's bound) the largest frequency of a boundary node
   * is @f$\omega^2 \le (4M + 2\alpha E)/(\rho h^2)@f$, so that the stable
   * step is that of a material with the P-wave modulus @f$M + \alpha
   * E/2@f$ (explicit_modulus()). With the default factor 100 and
   * @f$\nu = 0.3@f$ the step is 0.16 of the material's alone: a block on a
   * rigid floor at Courant number 0.5 of the material alone bounces off it
   * instead of sliding (doc/benchmarks/inertia.md).
   */
  template <int dim>
  double
  contact_penalty_factor(const std::vector<RigidBody<dim>> &rigid_bodies);

  /**
   * @brief What a surface adds to the modulus that sets the stable
   * explicit step of @p material: half of @p contact_penalty
   * (contact_penalty_factor()) times its Young's modulus and of @p
   * surface_stiffness (Pa/m, Coupling::surface_stiffness(): springs on a
   * face) times the cell size @p h (explicit_modulus()).
   */
  double
  surface_modulus(const Material &material,
                  const double    contact_penalty,
                  const double    surface_stiffness,
                  const double    h);

  /**
   * @brief The modulus that sets the stable explicit step of @p material:
   * its P-wave modulus, plus half of what the surface adds: @p
   * contact_penalty (contact_penalty_factor()) times its Young's modulus,
   * and @p surface_stiffness (Pa/m, Coupling::surface_stiffness(): springs
   * on a face) times the cell size @p h. A spring of k per area adds k
   * h^(d-1) to a surface node as the contact's alpha E / h does (see
   * contact_penalty_factor()): k h in place of alpha E.
   */
  double
  explicit_modulus(const Material &material,
                   const double    contact_penalty,
                   const double    surface_stiffness,
                   const double    h);

  /**
   * @brief The stable time step of the explicit central difference rule
   * for the points' current state: @p courant_number times the smallest
   * cell size over the largest speed of sound of the points, @f$c =
   * \sqrt{(M(\tau) + J M_s)/\rho_0}@f$ with the P-wave modulus of their
   * material in their Kirchhoff stress (Material::p_wave_modulus_at(): a
   * Cam-clay point stiffens with its mean stress), their reference
   * density @f$\rho_0@f$ (a point's mass and its material's Kirchhoff
   * stiffness both go with its initial volume, so a stretched or
   * compressed point keeps its speed of sound), and, on the mass of their
   * current volume, what the contact of rigid bodies, @p contact_penalty,
   * and springs on faces, @p surface_stiffness, add (surface_modulus()).
   * Collective.
   */
  template <int dim>
  double
  stable_time_step(const MaterialPoints<dim> &material_points,
                   const PointSteps<dim>     &steps,
                   const CartesianGrid<dim>  &grid,
                   const double               courant_number,
                   const double               contact_penalty,
                   const double               surface_stiffness,
                   const MPI_Comm             communicator);

  /**
   * @brief Refuse a scene's nominal time step above the stable explicit
   * step of its bodies' initial state (their density and
   * explicit_modulus() with the scene's rigid bodies'
   * contact_penalty_factor() and the couplings' @p surface_stiffness,
   * @p integrator's Courant number, with @p damping), naming the stable
   * step (one-line InputError).
   */
  template <int dim>
  void
  check_explicit_time_step(const CouplingInputs<dim>   &inputs,
                           const TimeIntegrator        &integrator,
                           const StiffnessDamping<dim> &damping,
                           const double                 surface_stiffness);

  /**
   * @brief Why an explicit step of @p time_step is cut ("" if it is not):
   * it is above @p limit, the stable step of the step's start at Courant
   * number 1 (naming the smallest cell of @p grid and the speed of sound).
   */
  template <int dim>
  std::string
  explicit_step_refusal(const double              time_step,
                        const double              limit,
                        const CartesianGrid<dim> &grid);

  /**
   * @brief One step of the central difference rule with the lumped mass
   * of @p nodes, from the residual of the step's start @p r (internal
   * minus external force, ghosted): the nodes' acceleration @f$a_I =
   * (f_I - \alpha_L |f_I| \mathrm{sign}(v_I) - \alpha_R M_I v_I)/M_I@f$
   * with @f$f_I = -r_I@f$ (the integrator's local and mass damping), their
   * new velocity @f$v_I + \Delta t\, a_I@f$, the points' new velocity and
   * acceleration (NodalMomentum::update_points() with the integrator's
   * FLIP fraction; with APIC also their velocity gradient) and the
   * increment @f$\Delta t\,v_I@f$ with the nodes'
   * new velocity (USL) or that of the updated points' momentum (MUSL, the
   * integrator's order), on the local DoFs of the system (zero
   * elsewhere). A DoF outside the system moves as its face does: it
   * takes no change of velocity (FLIP), the velocity of its
   * @p held_increment over the step (PIC; empty: every such DoF held) and
   * no acceleration, as in an implicit step. The run's @p first_step
   * takes half a step's change of velocity, @f$v^{1/2} = v^0 +
   * \tfrac12\Delta t\,a^0@f$, so that the points' velocities are those of
   * the half steps from then on (the rule's second order; a whole step at
   * the start put the motion half a step ahead). Returns the energy the local
   * and mass damping took out
   * over the step at the first @p n_owned DoFs (this process's), minus
   * their forces times the increment, and sets @p kinetic, the nodes'
   * kinetic energy there with the start's velocity and with the new one.
   * Collective.
   */
  template <int dim>
  double
  central_difference_step(const NodalMomentum<dim>  &nodes,
                          const NodalVector         &r,
                          const double               time_step,
                          const TimeIntegrator      &integrator,
                          const MaterialPoints<dim> &material_points,
                          const PointSteps<dim>     &steps,
                          std::vector<double>       &increment,
                          std::vector<double>       &velocities,
                          std::vector<double>       &accelerations,
                          std::vector<double>       &velocity_gradients,
                          const unsigned int         n_owned,
                          const std::vector<double> &held_increment,
                          const bool                 first_step,
                          NodalKineticEnergy        &kinetic);
} // namespace impm

#endif
