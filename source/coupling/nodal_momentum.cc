#include <impm/core/point_properties.h>
#include <impm/coupling/nodal_momentum.h>

namespace impm
{
  template <int dim>
  NodalMomentum<dim>::NodalMomentum(const BackgroundGrid<dim> &grid)
    : grid(grid)
  {}



  template <int dim>
  void
  NodalMomentum<dim>::map_points(const MaterialPoints<dim> &material_points,
                                 const LoadStepSystem<dim> &system)
  {
    grid.reinit_vector(nodal_mass);
    grid.reinit_vector(nodal_momentum);
    grid.reinit_vector(nodal_mass_acceleration);
    const auto        &layout         = material_points.layout();
    const unsigned int velocity_first = layout.coupling_field("velocity");
    const unsigned int acceleration_first =
      layout.coupling_field("acceleration");
    for (const auto &point : material_points.particles())
      {
        const auto            properties = point.get_properties();
        const PointStep<dim> &step       = system.point_steps.of(point);
        const double          m          = PointState<dim>(properties).mass();
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            {
              const unsigned int dof    = step.dofs[v * dim + i];
              const double       weight = step.support.weights[v] * m;
              nodal_mass.local_element(dof) += weight;
              nodal_momentum.local_element(dof) +=
                weight * properties[velocity_first + i];
              nodal_mass_acceleration.local_element(dof) +=
                weight * properties[acceleration_first + i];
            }
      }
    for (NodalVector *vector :
         {&nodal_mass, &nodal_momentum, &nodal_mass_acceleration})
      {
        vector->compress(VectorOperation::add);
        vector->update_ghost_values();
      }
    in_system_dof.assign(nodal_mass.locally_owned_size() +
                           nodal_mass.get_partitioner()->n_ghost_indices(),
                         false);
    for (unsigned int i = 0; i < n_local(); ++i)
      {
        in_system_dof[i] = system.system_index(i) != numbers::invalid_dof_index;
        if (!in_system_dof[i])
          {
            nodal_momentum.local_element(i)          = 0.;
            nodal_mass_acceleration.local_element(i) = 0.;
          }
      }
  }



  template <int dim>
  void
  NodalMomentum<dim>::update_points(const MaterialPoints<dim> &material_points,
                                    const PointSteps<dim>     &steps,
                                    const double               flip_fraction,
                                    const std::vector<double> &velocity_change,
                                    const std::vector<double> &new_velocity,
                                    const std::vector<double> &new_acceleration,
                                    std::vector<double>       &velocities,
                                    std::vector<double> &accelerations) const
  {
    const unsigned int velocity_first =
      material_points.layout().coupling_field("velocity");
    velocities.assign(steps.size() * dim, 0.);
    accelerations.assign(steps.size() * dim, 0.);
    for (const auto &point : material_points.particles())
      {
        const auto            properties = point.get_properties();
        const unsigned int    p          = steps.index_of(point);
        const PointStep<dim> &step       = steps[p];
        for (unsigned int i = 0; i < dim; ++i)
          {
            double dv = 0., v_new = 0., a = 0.;
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              {
                const unsigned int dof = step.dofs[v * dim + i];
                const double       N   = step.support.weights[v];
                dv += N * velocity_change[dof];
                v_new += N * new_velocity[dof];
                a += N * new_acceleration[dof];
              }
            velocities[p * dim + i] =
              flip_fraction * (properties[velocity_first + i] + dv) +
              (1. - flip_fraction) * v_new;
            accelerations[p * dim + i] = a;
          }
      }
  }



  template <int dim>
  std::vector<double>
  NodalMomentum<dim>::remapped_velocity(
    const MaterialPoints<dim> &material_points,
    const PointSteps<dim>     &steps,
    const std::vector<double> &velocities) const
  {
    NodalVector updated_momentum;
    grid.reinit_vector(updated_momentum);
    for (const auto &point : material_points.particles())
      {
        const unsigned int    p    = steps.index_of(point);
        const PointStep<dim> &step = steps[p];
        const double m = PointState<dim>(point.get_properties()).mass();
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            updated_momentum.local_element(step.dofs[v * dim + i]) +=
              step.support.weights[v] * m * velocities[p * dim + i];
      }
    updated_momentum.compress(VectorOperation::add);
    updated_momentum.update_ghost_values();
    std::vector<double> velocity(n_local(), 0.);
    for (unsigned int i = 0; i < n_local(); ++i)
      if (in_system_dof[i] && mass(i) > 0.)
        velocity[i] = updated_momentum.local_element(i) / mass(i);
    return velocity;
  }



  template class NodalMomentum<2>;
  template class NodalMomentum<3>;
} // namespace impm
