#ifndef impm_coupling_newmark_update_h
#define impm_coupling_newmark_update_h

#include <deal.II/base/mpi.h>

#include <impm/coupling/nodal_momentum.h>
#include <impm/coupling/step_energy.h>
#include <impm/coupling/stiffness_damping.h>
#include <impm/coupling/time_integrator.h>
#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/points/point_step.h>

#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The points' velocity and acceleration at the end of a converged
   * implicit step (Newmark or generalised-alpha), from the nodes' increment
   * @p increment (ghosted local DoFs).
   *
   * The nodes' start velocity and acceleration are the momentum and mass
   * times acceleration of @p nodes over their mass, lumped or consistent
   * (NodalMomentum::start_velocity_and_acceleration()); Newmark's rule
   * gives their new acceleration @f$a_I^{n+1} = (\Delta u_I - \Delta t\,
   * v_I^n)/(\beta\Delta t^2) - (1/(2\beta) - 1)\, a_I^n@f$, their change
   * of velocity @f$\Delta v_I = \Delta t((1 - \gamma) a_I^n + \gamma
   * a_I^{n+1})@f$, and the points take them through
   * NodalMomentum::update_points() (FLIP/PIC, or APIC with the gradient of
   * the nodes' new velocity). Collective with the consistent mass.
   *
   * @param[out] velocities, accelerations By step index and axis.
   * @param[out] velocity_gradients With APIC, by step index and dim x dim
   *   (row-major); untouched otherwise.
   * @return The nodes' kinetic energy with the start's and the new
   *   velocity on the first @p n_owned (this process's) DoFs, with the
   *   lumped mass or the consistent one (through this process's points).
   */
  template <int dim>
  NodalKineticEnergy
  newmark_point_update(const NodalMomentum<dim>  &nodes,
                       const NodalVector         &increment,
                       const double               time_step,
                       const TimeIntegrator      &integrator,
                       const MaterialPoints<dim> &material_points,
                       const PointSteps<dim>     &steps,
                       std::vector<double>       &velocities,
                       std::vector<double>       &accelerations,
                       std::vector<double>       &velocity_gradients,
                       const unsigned int         n_owned);

  /**
   * @brief The first step's start acceleration from the balance at the
   * start (the points carry none yet): @f$M a^0 = -r^0 - \alpha_R M v^0 -
   * f_v(v^0)@f$ on the system's DoFs of @p nodes, with @p residual the
   * start's residual (internal minus external force, ghosted), the mass
   * damping of the integrator and the viscous force of @p damping (if
   * active) at the initial nodal velocity. Collective with the stiffness
   * damping.
   */
  template <int dim>
  void
  set_start_acceleration(NodalMomentum<dim>        &nodes,
                         const TimeIntegrator      &integrator,
                         StiffnessDamping<dim>     &damping,
                         const LoadStepSystem<dim> &system,
                         const NodalVector         &residual);

  /** @brief What add_newmark_forces() added, on this process's DoFs. */
  template <int dim>
  struct NewmarkForceSums
  {
    /** The squared norm of the forces. */
    double norm_squared = 0.;
    /** Their sum per axis. */
    Tensor<1, dim> force;
    /** The energy the mass damping took out: the mean of its start's
     *  and end's force times the increment. */
    double damping_dissipation = 0.;
  };

  /**
   * @brief Add the inertial and mass damping force of an implicit step
   * (Newmark or generalised-alpha, Inertia) at the owned DoFs of the system
   * to @p internal_force, for the increment @p increment: @f$k_m M
   * a^{n+1} + k_a q + k_r r^n@f$ with @f$M a^{n+1} = c_1 M \Delta u - c_2
   * p - c_3 q@f$ (@p nodes' momentum p and mass times acceleration q;
   * @f$M\Delta u@f$ from @p mass_times_increment, the consistent matrix's
   * product by owned DoF, with the integrator's share of the lumped mass,
   * or the lumped mass where it is empty), and @f$r^n@f$ the start's
   * residual @p start_residual (empty: none), plus the mass damping's
   * @f$\alpha_R (p + \Delta t((1-\gamma) q + \gamma M a^{n+1}) + k_r
   * p)@f$.
   */
  template <int dim>
  NewmarkForceSums<dim>
  add_newmark_forces(const NodalMomentum<dim>  &nodes,
                     const TimeIntegrator      &integrator,
                     const double               time_step,
                     const NodalVector         &increment,
                     const std::vector<double> &mass_times_increment,
                     const std::vector<double> &start_residual,
                     const BackgroundGrid<dim> &grid,
                     NodalVector               &internal_force);
} // namespace impm

#endif
