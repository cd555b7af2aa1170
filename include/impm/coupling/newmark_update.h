#ifndef impm_coupling_newmark_update_h
#define impm_coupling_newmark_update_h

#include <deal.II/base/mpi.h>

#include <impm/coupling/nodal_momentum.h>
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
   */
  template <int dim>
  void
  newmark_point_update(const NodalMomentum<dim>  &nodes,
                       const NodalVector         &increment,
                       const double               time_step,
                       const TimeIntegrator      &integrator,
                       const MaterialPoints<dim> &material_points,
                       const PointSteps<dim>     &steps,
                       std::vector<double>       &velocities,
                       std::vector<double>       &accelerations,
                       std::vector<double>       &velocity_gradients);
} // namespace impm

#endif
