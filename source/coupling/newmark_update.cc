#include <impm/coupling/newmark_update.h>

namespace impm
{
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
                       std::vector<double>       &velocity_gradients)
  {
    const unsigned int n_local = nodes.n_local();
    const double       c3      = 1. / (2. * integrator.beta) - 1.;
    // The nodes' new acceleration, velocity and change of velocity (owned
    // and ghost DoFs: the points read both).
    std::vector<double> new_acceleration(n_local), new_velocity(n_local),
      velocity_change(n_local);
    // The start's nodal velocity and acceleration: the momentum over the
    // mass, lumped or consistent.
    std::vector<double> start_velocity, start_acceleration;
    nodes.start_velocity_and_acceleration(material_points,
                                          steps,
                                          integrator.consistent_mass,
                                          integrator.mass_regularisation,
                                          start_velocity,
                                          start_acceleration);
    for (unsigned int i = 0; i < n_local; ++i)
      {
        const double v      = start_velocity[i];
        const double a      = start_acceleration[i];
        new_acceleration[i] = (increment.local_element(i) - time_step * v) /
                                (integrator.beta * time_step * time_step) -
                              c3 * a;
        velocity_change[i] =
          time_step * ((1. - integrator.gamma) * a +
                       integrator.gamma * new_acceleration[i]);
        new_velocity[i] = v + velocity_change[i];
      }
    nodes.update_points(material_points,
                        steps,
                        integrator.flip_fraction_of_step(time_step),
                        velocity_change,
                        new_velocity,
                        new_acceleration,
                        velocities,
                        accelerations);
    if (integrator.affine_transfer)
      velocity_gradients =
        nodes.velocity_gradients(material_points, steps, new_velocity);
  }



  template void
  newmark_point_update(const NodalMomentum<2> &,
                       const NodalVector &,
                       const double,
                       const TimeIntegrator &,
                       const MaterialPoints<2> &,
                       const PointSteps<2> &,
                       std::vector<double> &,
                       std::vector<double> &,
                       std::vector<double> &);
  template void
  newmark_point_update(const NodalMomentum<3> &,
                       const NodalVector &,
                       const double,
                       const TimeIntegrator &,
                       const MaterialPoints<3> &,
                       const PointSteps<3> &,
                       std::vector<double> &,
                       std::vector<double> &,
                       std::vector<double> &);
} // namespace impm
