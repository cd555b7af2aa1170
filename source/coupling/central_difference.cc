#include <impm/base/errors.h>
#include <impm/core/point_properties.h>
#include <impm/coupling/central_difference.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impm
{
  template <int dim>
  double
  smallest_cell_size(const CartesianGrid<dim> &grid)
  {
    double h = grid.cell_size[0];
    for (unsigned int d = 1; d < dim; ++d)
      h = std::min(h, grid.cell_size[d]);
    return h;
  }



  template <int dim>
  double
  contact_penalty_factor(const std::vector<RigidBody<dim>> &rigid_bodies)
  {
    double factor = 0.;
    for (const auto &body : rigid_bodies)
      {
        factor = std::max(factor, body.penalty_factor);
        if (body.friction != RigidBody<dim>::Friction::frictionless)
          factor = std::max(factor, body.tangential_penalty_factor);
      }
    return factor;
  }



  double
  surface_modulus(const Material &material,
                  const double    contact_penalty,
                  const double    surface_stiffness,
                  const double    h)
  {
    return 0.5 * (contact_penalty * material.elastic_modulus() +
                  surface_stiffness * h);
  }



  double
  explicit_modulus(const Material &material,
                   const double    contact_penalty,
                   const double    surface_stiffness,
                   const double    h)
  {
    return material.p_wave_modulus() +
           surface_modulus(material, contact_penalty, surface_stiffness, h);
  }



  template <int dim>
  double
  stable_time_step(const MaterialPoints<dim> &material_points,
                   const PointSteps<dim>     &steps,
                   const CartesianGrid<dim>  &grid,
                   const double               courant_number,
                   const double               contact_penalty,
                   const double               surface_stiffness,
                   const MPI_Comm             communicator)
  {
    const double h       = smallest_cell_size(grid);
    double       largest = 0.;
    for (const auto &point : material_points.particles())
      {
        // The material's stiffness and the point's mass both go with its
        // initial volume (Kirchhoff stress), so its speed of sound is that
        // of its reference density whatever its volume change; a surface's
        // springs act on its current volume's mass.
        const PointState<dim> state(point.get_properties());
        const Material       &material = *steps.of(point).material;
        const double volume_ratio = state.volume() / state.initial_volume();
        const double modulus =
          material.p_wave_modulus_at(state.kirchhoff_stress()) +
          volume_ratio *
            surface_modulus(material, contact_penalty, surface_stiffness, h);
        largest =
          std::max(largest, modulus * state.initial_volume() / state.mass());
      }
    const double speed = std::sqrt(Utilities::MPI::max(largest, communicator));
    return speed > 0. ? courant_number * h / speed :
                        std::numeric_limits<double>::max();
  }



  template <int dim>
  void
  check_explicit_time_step(const CouplingInputs<dim>   &inputs,
                           const TimeIntegrator        &integrator,
                           const StiffnessDamping<dim> &damping,
                           const double                 surface_stiffness)
  {
    const double contact =
      contact_penalty_factor(inputs.parameters.rigid_bodies);
    const double h       = smallest_cell_size(inputs.grid.cartesian());
    double       largest = 0.;
    for (const auto &body : inputs.parameters.bodies)
      largest = std::max(
        largest,
        explicit_modulus(*body.material, contact, surface_stiffness, h) /
          body.density);
    const double stable = integrator.courant_number *
                          damping.critical_time_step(h / std::sqrt(largest));
    if (inputs.time.nominal_step > stable * (1. + 1e-12))
      {
        std::ostringstream out;
        out << "Inertia: the time step " << inputs.time.nominal_step
            << " s is above the stable explicit step " << stable
            << " s (Courant number " << integrator.courant_number
            << ", smallest cell " << h << " m, speed of sound "
            << std::sqrt(largest) << " m/s";
        if (contact > 0.)
          out << ", with the rigid bodies' contact penalty factor " << contact;
        if (surface_stiffness > 0.)
          out << ", with springs of " << surface_stiffness << " Pa/m on faces";
        if (damping.active())
          out << ", with the stiffness damping";
        out << "): set 'Time/Time step' to at most that.";
        throw InputError(out.str());
      }
  }



  template <int dim>
  std::string
  explicit_step_refusal(const double              time_step,
                        const double              limit,
                        const CartesianGrid<dim> &grid)
  {
    // The run started with its nominal step at most the Courant number
    // times the stable step (check_explicit_time_step()); a step is cut
    // only when the points' state has brought the true limit (Courant
    // number 1) below it, so that small changes of density do not cut
    // steps the Courant number's margin covers.
    if (time_step <= limit * (1. + 1e-12))
      return "";
    std::ostringstream out;
    out << "the time step " << time_step
        << " s is above the stable explicit step " << limit
        << " s at Courant number 1 (smallest cell " << smallest_cell_size(grid)
        << " m, speed of sound " << smallest_cell_size(grid) / limit << " m/s)";
    return out.str();
  }



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
                          NodalKineticEnergy        &kinetic)
  {
    const double velocity_step  = first_step ? 0.5 * time_step : time_step;
    kinetic                     = NodalKineticEnergy();
    const unsigned int  n_local = nodes.n_local();
    std::vector<double> acceleration(n_local), velocity_change(n_local),
      new_velocity(n_local), damping_force(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      {
        const double m = nodes.mass(i);
        if (!nodes.in_system(i) && !held_increment.empty())
          new_velocity[i] = held_increment[i] / time_step;
        if (!nodes.in_system(i) || !(m > 0.))
          continue;
        const double v     = nodes.momentum(i) / m;
        const double force = -r.local_element(i);
        // Local non-viscous damping opposes the velocity with a fraction of
        // the force's size (nothing on a node at rest).
        const double local =
          v > 0. ? -integrator.local_damping * std::abs(force) :
          v < 0. ? integrator.local_damping * std::abs(force) :
                   0.;
        damping_force[i]   = local - integrator.mass_damping * m * v;
        acceleration[i]    = (force + damping_force[i]) / m;
        velocity_change[i] = velocity_step * acceleration[i];
        new_velocity[i]    = v + velocity_change[i];
        if (i < n_owned)
          kinetic.start += 0.5 * m * v * v;
      }
    nodes.update_points(material_points,
                        steps,
                        integrator.flip_fraction_of_step(time_step),
                        velocity_change,
                        new_velocity,
                        acceleration,
                        velocities,
                        accelerations);
    // APIC: the points' velocity gradient from the nodes' new velocity,
    // remapped (MUSL) with the points' new velocity (a remap with the
    // start's gradient, or a gradient of the remapped velocity, lets a
    // spinning disc break up within a few hundred steps: tried).
    if (integrator.affine_transfer)
      velocity_gradients =
        nodes.velocity_gradients(material_points, steps, new_velocity);
    const std::vector<double> velocity =
      integrator.explicit_order == ExplicitOrder::usl ?
        new_velocity :
        nodes.remapped_velocity(material_points,
                                steps,
                                velocities,
                                velocity_gradients);
    increment.assign(n_local, 0.);
    // The nodes' kinetic energy at the end with their new velocity, whose
    // change is what the forces did: the points' kinetic energy after the
    // update (FLIP/PIC blend, MUSL remap) against it is the transfer's.
    // (With MUSL's remapped velocity here the blend's loss was left out of
    // the transfer and showed as the balance's error: -5.4 % on the
    // granular column at FLIP 0.95 per 0.005 s, 0.5 % now; the bar pulled
    // at FLIP 0.5 -13.9 %, 2e-4 now.)
    double dissipation = 0.;
    for (unsigned int i = 0; i < n_local; ++i)
      {
        increment[i] = time_step * velocity[i];
        if (i < n_owned && nodes.in_system(i) && nodes.mass(i) > 0.)
          {
            dissipation -= damping_force[i] * increment[i];
            kinetic.end +=
              0.5 * nodes.mass(i) * new_velocity[i] * new_velocity[i];
          }
      }
    return dissipation;
  }



  template double
  smallest_cell_size(const CartesianGrid<2> &);
  template double
  smallest_cell_size(const CartesianGrid<3> &);
  template double
  contact_penalty_factor(const std::vector<RigidBody<2>> &);
  template double
  contact_penalty_factor(const std::vector<RigidBody<3>> &);
  template double
  stable_time_step(const MaterialPoints<2> &,
                   const PointSteps<2> &,
                   const CartesianGrid<2> &,
                   const double,
                   const double,
                   const double,
                   const MPI_Comm);
  template double
  stable_time_step(const MaterialPoints<3> &,
                   const PointSteps<3> &,
                   const CartesianGrid<3> &,
                   const double,
                   const double,
                   const double,
                   const MPI_Comm);
  template double
  central_difference_step(const NodalMomentum<2> &,
                          const NodalVector &,
                          const double,
                          const TimeIntegrator &,
                          const MaterialPoints<2> &,
                          const PointSteps<2> &,
                          std::vector<double> &,
                          std::vector<double> &,
                          std::vector<double> &,
                          std::vector<double> &,
                          const unsigned int,
                          const std::vector<double> &,
                          const bool,
                          NodalKineticEnergy &);
  template double
  central_difference_step(const NodalMomentum<3> &,
                          const NodalVector &,
                          const double,
                          const TimeIntegrator &,
                          const MaterialPoints<3> &,
                          const PointSteps<3> &,
                          std::vector<double> &,
                          std::vector<double> &,
                          std::vector<double> &,
                          std::vector<double> &,
                          const unsigned int,
                          const std::vector<double> &,
                          const bool,
                          NodalKineticEnergy &);
  template std::string
  explicit_step_refusal(const double, const double, const CartesianGrid<2> &);
  template std::string
  explicit_step_refusal(const double, const double, const CartesianGrid<3> &);
  template void
  check_explicit_time_step(const CouplingInputs<2> &,
                           const TimeIntegrator &,
                           const StiffnessDamping<2> &,
                           const double);
  template void
  check_explicit_time_step(const CouplingInputs<3> &,
                           const TimeIntegrator &,
                           const StiffnessDamping<3> &,
                           const double);
} // namespace impm
