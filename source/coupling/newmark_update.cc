#include <impm/core/point_properties.h>
#include <impm/coupling/newmark_update.h>

namespace impm
{
  namespace
  {
    /**
     * The kinetic energy of the nodal velocity @p velocity (local DoFs)
     * with the consistent mass matrix plus @p regularisation times the
     * lumped one: through this process's points, @f$\tfrac12 \sum_p m_p
     * |\sum_I N_{Ip} v_I|^2@f$, and its owned DoFs of the system.
     */
    template <int dim>
    double
    consistent_kinetic_energy(const NodalMomentum<dim>  &nodes,
                              const MaterialPoints<dim> &material_points,
                              const PointSteps<dim>     &steps,
                              const std::vector<double> &velocity,
                              const double               regularisation,
                              const unsigned int         n_owned)
    {
      double energy = 0.;
      for (const auto &point : material_points.particles())
        {
          const PointStep<dim> &step = steps.of(point);
          Tensor<1, dim>        v;
          for (unsigned int k = 0; k < step.support.n_nodes; ++k)
            for (unsigned int i = 0; i < dim; ++i)
              v[i] +=
                step.support.weights[k] * velocity[step.dofs[k * dim + i]];
          energy +=
            0.5 * PointState<dim>(point.get_properties()).mass() * (v * v);
        }
      for (unsigned int i = 0; i < n_owned; ++i)
        if (nodes.in_system(i))
          energy +=
            0.5 * regularisation * nodes.mass(i) * velocity[i] * velocity[i];
      return energy;
    }
  } // namespace



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
                       const unsigned int         n_owned)
  {
    const unsigned int n_local = nodes.n_local();
    const double       c3      = 1. / (2. * integrator.beta) - 1.;
    // The nodes' new acceleration, velocity and change of velocity (owned
    // and ghost DoFs: the points read both).
    std::vector<double> new_acceleration(n_local), new_velocity(n_local),
      velocity_change(n_local);
    NodalKineticEnergy kinetic;
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
        const double v = start_velocity[i];
        const double a = start_acceleration[i];
        if (nodes.in_system(i))
          {
            new_acceleration[i] = (increment.local_element(i) - time_step * v) /
                                    (integrator.beta * time_step * time_step) -
                                  c3 * a;
            velocity_change[i] =
              time_step * ((1. - integrator.gamma) * a +
                           integrator.gamma * new_acceleration[i]);
          }
        // A held or prescribed DoF moves as its face does: with the step's
        // mean velocity (for PIC), no change of velocity (for FLIP) and no
        // acceleration, as in an explicit step. (Newmark's rule from the
        // points' mapped velocity gave it v^{n+1} = 2 du/dt - v^n, flipping
        // sign every step where the points' velocity is not the face's,
        // and FLIP handed that to the points: a bar pulled by a face gained
        // 200 times the face's work as velocity noise.)
        new_velocity[i] = nodes.in_system(i) ?
                            v + velocity_change[i] :
                            increment.local_element(i) / time_step;
        if (i < n_owned && nodes.in_system(i))
          {
            kinetic.start += 0.5 * nodes.mass(i) * v * v;
            kinetic.end +=
              0.5 * nodes.mass(i) * new_velocity[i] * new_velocity[i];
          }
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
    // The consistent mass's kinetic energy (which its trapezoidal rule
    // keeps), not the lumped one of its velocities.
    if (integrator.consistent_mass)
      kinetic = {consistent_kinetic_energy(nodes,
                                           material_points,
                                           steps,
                                           start_velocity,
                                           integrator.mass_regularisation,
                                           n_owned),
                 consistent_kinetic_energy(nodes,
                                           material_points,
                                           steps,
                                           new_velocity,
                                           integrator.mass_regularisation,
                                           n_owned)};
    return kinetic;
  }



  template <int dim>
  void
  set_start_acceleration(NodalMomentum<dim>        &nodes,
                         const TimeIntegrator      &integrator,
                         StiffnessDamping<dim>     &damping,
                         const LoadStepSystem<dim> &system,
                         const NodalVector         &residual)
  {
    const NodalVector &damped =
      damping.active() ? damping.damped_residual(nodes, system, residual) :
                         residual;
    for (unsigned int i = 0; i < nodes.n_local(); ++i)
      if (nodes.in_system(i) && nodes.mass(i) > 0.)
        nodes.set_mass_acceleration(i,
                                    -damped.local_element(i) -
                                      integrator.mass_damping *
                                        nodes.momentum(i));
  }



  template <int dim>
  NewmarkForceSums<dim>
  add_newmark_forces(const NodalMomentum<dim>  &nodes,
                     const TimeIntegrator      &integrator,
                     const double               time_step,
                     const NodalVector         &increment,
                     const std::vector<double> &mass_times_increment,
                     const std::vector<double> &start_residual,
                     const BackgroundGrid<dim> &grid,
                     NodalVector               &internal_force)
  {
    const double          c1  = 1. / (integrator.beta * time_step * time_step);
    const double          c2  = 1. / (integrator.beta * time_step);
    const double          c3  = 1. / (2. * integrator.beta) - 1.;
    const double          k_a = integrator.alpha_m / (1. - integrator.alpha_f);
    const double          k_r = integrator.alpha_f / (1. - integrator.alpha_f);
    NewmarkForceSums<dim> sums;
    for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
      if (nodes.in_system(i))
        {
          const double p  = nodes.momentum(i);
          const double q  = nodes.mass_acceleration(i);
          const double du = increment.local_element(i);
          // M a^{n+1}
          const double mass_times_acceleration =
            c1 * (mass_times_increment.empty() ?
                    nodes.mass(i) * du :
                    mass_times_increment[i] +
                      integrator.mass_regularisation * nodes.mass(i) * du) -
            c2 * p - c3 * q;
          double force = integrator.k_m() * mass_times_acceleration + k_a * q;
          if (!start_residual.empty())
            force += k_r * start_residual[i];
          if (integrator.mass_damping > 0.)
            {
              const double damping =
                integrator.mass_damping *
                (p +
                 time_step * ((1. - integrator.gamma) * q +
                              integrator.gamma * mass_times_acceleration) +
                 k_r * p);
              force += damping;
              // The trapezoidal rule's share: the mean of the start's
              // damping force alpha p and the end's (the start's balance,
              // mapped through the points' accelerations, held the
              // start's); generalised-alpha's k_r alpha p is the start's
              // weight, not a force of its own.
              sums.damping_dissipation +=
                0.5 * ((1. - k_r) * integrator.mass_damping * p + damping) * du;
            }
          internal_force.local_element(i) += force;
          sums.norm_squared += force * force;
          sums.force[grid.component(i)] += force;
        }
    return sums;
  }



  template NodalKineticEnergy
  newmark_point_update(const NodalMomentum<2> &,
                       const NodalVector &,
                       const double,
                       const TimeIntegrator &,
                       const MaterialPoints<2> &,
                       const PointSteps<2> &,
                       std::vector<double> &,
                       std::vector<double> &,
                       std::vector<double> &,
                       const unsigned int);
  template NodalKineticEnergy
  newmark_point_update(const NodalMomentum<3> &,
                       const NodalVector &,
                       const double,
                       const TimeIntegrator &,
                       const MaterialPoints<3> &,
                       const PointSteps<3> &,
                       std::vector<double> &,
                       std::vector<double> &,
                       std::vector<double> &,
                       const unsigned int);
  template void
  set_start_acceleration(NodalMomentum<2> &,
                         const TimeIntegrator &,
                         StiffnessDamping<2> &,
                         const LoadStepSystem<2> &,
                         const NodalVector &);
  template void
  set_start_acceleration(NodalMomentum<3> &,
                         const TimeIntegrator &,
                         StiffnessDamping<3> &,
                         const LoadStepSystem<3> &,
                         const NodalVector &);
  template NewmarkForceSums<2>
  add_newmark_forces(const NodalMomentum<2> &,
                     const TimeIntegrator &,
                     const double,
                     const NodalVector &,
                     const std::vector<double> &,
                     const std::vector<double> &,
                     const BackgroundGrid<2> &,
                     NodalVector &);
  template NewmarkForceSums<3>
  add_newmark_forces(const NodalMomentum<3> &,
                     const TimeIntegrator &,
                     const double,
                     const NodalVector &,
                     const std::vector<double> &,
                     const std::vector<double> &,
                     const BackgroundGrid<3> &,
                     NodalVector &);
} // namespace impm
