#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/core/point_properties.h>
#include <impm/coupling/nodal_momentum.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  template <int dim>
  NodalMomentum<dim>::NodalMomentum(const BackgroundGrid<dim> &grid,
                                    const bool                 affine)
    : grid(grid)
    , affine(affine)
  {}



  template <int dim>
  std::array<double, PointSupport<dim>::max_nodes * dim>
  NodalMomentum<dim>::affine_parts(const PointStep<dim> &step,
                                   const double         *gradient) const
  {
    const CartesianGrid<dim> &cartesian = grid.cartesian();
    std::array<Point<dim>, PointSupport<dim>::max_nodes> nodes;
    Point<dim>                                           centre;
    double                                               weight_sum = 0.;
    for (unsigned int v = 0; v < step.support.n_nodes; ++v)
      {
        nodes[v] = cartesian.node_position(step.support.nodes[v]);
        centre += step.support.weights[v] * nodes[v];
        weight_sum += step.support.weights[v];
      }
    centre /= weight_sum;
    std::array<double, PointSupport<dim>::max_nodes * dim> parts;
    for (unsigned int v = 0; v < step.support.n_nodes; ++v)
      for (unsigned int i = 0; i < dim; ++i)
        {
          double part = 0.;
          for (unsigned int j = 0; j < dim; ++j)
            part += gradient[i * dim + j] * (nodes[v][j] - centre[j]);
          parts[v * dim + i] = part;
        }
    return parts;
  }



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
    const unsigned int gradient_first =
      affine ? layout.coupling_field("velocity_gradient") : 0;
    std::array<double, PointSupport<dim>::max_nodes * dim> parts{};
    for (const auto &point : material_points.particles())
      {
        const auto            properties = point.get_properties();
        const PointStep<dim> &step       = system.point_steps.of(point);
        const double          m          = PointState<dim>(properties).mass();
        if (affine)
          parts = affine_parts(step, &properties[gradient_first]);
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            {
              const unsigned int dof    = step.dofs[v * dim + i];
              const double       weight = step.support.weights[v] * m;
              nodal_mass.local_element(dof) += weight;
              nodal_momentum.local_element(dof) +=
                weight * (properties[velocity_first + i] + parts[v * dim + i]);
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
              affine ? v_new :
                       flip_fraction * (properties[velocity_first + i] + dv) +
                         (1. - flip_fraction) * v_new;
            accelerations[p * dim + i] = a;
          }
      }
  }



  template <int dim>
  std::vector<double>
  NodalMomentum<dim>::velocity_gradients(
    const MaterialPoints<dim> &material_points,
    const PointSteps<dim>     &steps,
    const std::vector<double> &velocity) const
  {
    std::vector<double> gradients(steps.size() * dim * dim, 0.);
    for (const auto &point : material_points.particles())
      {
        const unsigned int    p    = steps.index_of(point);
        const PointStep<dim> &step = steps[p];
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              gradients[(p * dim + i) * dim + j] +=
                velocity[step.dofs[v * dim + i]] * step.support.gradients[v][j];
      }
    return gradients;
  }



  template <int dim>
  NodalVector
  NodalMomentum<dim>::mass_weighted_sum(
    const MaterialPoints<dim> &material_points,
    const PointSteps<dim>     &steps,
    const std::vector<double> &values,
    const double              *gradients) const
  {
    NodalVector sum;
    grid.reinit_vector(sum);
    std::array<double, PointSupport<dim>::max_nodes * dim> parts{};
    for (const auto &point : material_points.particles())
      {
        const unsigned int    p    = steps.index_of(point);
        const PointStep<dim> &step = steps[p];
        const double m = PointState<dim>(point.get_properties()).mass();
        if (gradients != nullptr)
          parts = affine_parts(step, gradients + p * dim * dim);
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            sum.local_element(step.dofs[v * dim + i]) +=
              step.support.weights[v] * m *
              (values[p * dim + i] + parts[v * dim + i]);
      }
    sum.compress(VectorOperation::add);
    sum.update_ghost_values();
    return sum;
  }



  template <int dim>
  std::vector<double>
  NodalMomentum<dim>::remapped_velocity(
    const MaterialPoints<dim> &material_points,
    const PointSteps<dim>     &steps,
    const std::vector<double> &velocities,
    const std::vector<double> &velocity_gradients) const
  {
    const NodalVector updated_momentum =
      mass_weighted_sum(material_points,
                        steps,
                        velocities,
                        affine ? velocity_gradients.data() : nullptr);
    std::vector<double> velocity(n_local(), 0.);
    for (unsigned int i = 0; i < n_local(); ++i)
      if (in_system_dof[i] && mass(i) > 0.)
        velocity[i] = updated_momentum.local_element(i) / mass(i);
    return velocity;
  }



  template <int dim>
  std::vector<double>
  NodalMomentum<dim>::at_points(const MaterialPoints<dim> &material_points,
                                const PointSteps<dim>     &steps,
                                const NodalVector         &x) const
  {
    std::vector<double> values(steps.size() * dim, 0.);
    for (const auto &point : material_points.particles())
      {
        const unsigned int    p    = steps.index_of(point);
        const PointStep<dim> &step = steps[p];
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            values[p * dim + i] +=
              step.support.weights[v] * x.local_element(step.dofs[v * dim + i]);
      }
    return values;
  }



  template <int dim>
  std::vector<double>
  NodalMomentum<dim>::consistent_mass_times(
    const MaterialPoints<dim> &material_points,
    const PointSteps<dim>     &steps,
    const NodalVector         &x) const
  {
    const NodalVector product = mass_weighted_sum(
      material_points, steps, at_points(material_points, steps, x), nullptr);
    std::vector<double> result(n_local());
    for (unsigned int i = 0; i < n_local(); ++i)
      result[i] = product.local_element(i);
    return result;
  }



  template <int dim>
  std::vector<double>
  NodalMomentum<dim>::solve_consistent_mass(
    const MaterialPoints<dim> &material_points,
    const PointSteps<dim>     &steps,
    const double               regularisation,
    const NodalVector         &right_hand_side) const
  {
    const MPI_Comm communicator = grid.get_triangulation().get_communicator();
    const unsigned int n_owned  = nodal_mass.locally_owned_size();
    const auto         active   = [&](const unsigned int i) {
      return in_system_dof[i] && mass(i) > 0.;
    };
    const auto dot = [&](const std::vector<double> &a,
                         const std::vector<double> &b) {
      double sum = 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        sum += a[i] * b[i];
      return Utilities::MPI::sum(sum, communicator);
    };
    std::vector<double> x(n_owned, 0.), r(n_owned, 0.), z(n_owned, 0.),
      product(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      if (active(i))
        r[i] = right_hand_side.local_element(i);
    const double norm = std::sqrt(dot(r, r));
    NodalVector  direction;
    grid.reinit_vector(direction);
    for (unsigned int i = 0; i < n_owned; ++i)
      if (active(i))
        z[i] = r[i] / ((1. + regularisation) * mass(i));
    double       rz        = dot(r, z);
    unsigned int iteration = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      direction.local_element(i) = z[i];
    while (norm > 0. && std::sqrt(dot(r, r)) > 1e-12 * norm)
      {
        if (++iteration > 1000)
          throw CollectiveError(
            "Inertia: the consistent mass's conjugate gradients did not "
            "reach 1e-12 of the right-hand side in 1000 iterations "
            "(residual " +
            number_text(std::sqrt(dot(r, r)) / norm) +
            "); raise 'Inertia/Mass regularisation'.");
        direction.update_ghost_values();
        const std::vector<double> mass_times_direction =
          consistent_mass_times(material_points, steps, direction);
        for (unsigned int i = 0; i < n_owned; ++i)
          product[i] =
            active(i) ? mass_times_direction[i] + regularisation * mass(i) *
                                                    direction.local_element(i) :
                        0.;
        std::vector<double> d(n_owned);
        for (unsigned int i = 0; i < n_owned; ++i)
          d[i] = direction.local_element(i);
        const double alpha = rz / dot(d, product);
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            x[i] += alpha * d[i];
            r[i] -= alpha * product[i];
            z[i] = active(i) ? r[i] / ((1. + regularisation) * mass(i)) : 0.;
          }
        const double rz_new = dot(r, z);
        for (unsigned int i = 0; i < n_owned; ++i)
          direction.local_element(i) = z[i] + rz_new / rz * d[i];
        rz = rz_new;
      }
    NodalVector solution;
    grid.reinit_vector(solution);
    for (unsigned int i = 0; i < n_owned; ++i)
      solution.local_element(i) = x[i];
    solution.update_ghost_values();
    std::vector<double> result(n_local());
    for (unsigned int i = 0; i < n_local(); ++i)
      result[i] = solution.local_element(i);
    return result;
  }



  template <int dim>
  void
  NodalMomentum<dim>::consistent_velocity_and_acceleration(
    const MaterialPoints<dim> &material_points,
    const PointSteps<dim>     &steps,
    const double               regularisation,
    std::vector<double>       &velocity,
    std::vector<double>       &acceleration) const
  {
    velocity     = solve_consistent_mass(material_points,
                                     steps,
                                     regularisation,
                                     nodal_momentum);
    acceleration = solve_consistent_mass(material_points,
                                         steps,
                                         regularisation,
                                         nodal_mass_acceleration);
  }



  template <int dim>
  void
  NodalMomentum<dim>::start_velocity_and_acceleration(
    const MaterialPoints<dim> &material_points,
    const PointSteps<dim>     &steps,
    const bool                 consistent,
    const double               regularisation,
    std::vector<double>       &velocity,
    std::vector<double>       &acceleration) const
  {
    if (consistent)
      {
        consistent_velocity_and_acceleration(
          material_points, steps, regularisation, velocity, acceleration);
        return;
      }
    velocity.assign(n_local(), 0.);
    acceleration.assign(n_local(), 0.);
    for (unsigned int i = 0; i < n_local(); ++i)
      if (mass(i) > 0.)
        {
          velocity[i]     = momentum(i) / mass(i);
          acceleration[i] = mass_acceleration(i) / mass(i);
        }
  }



  template <int dim>
  void
  NodalMomentum<dim>::add_consistent_mass(
    const double                    c,
    const MaterialPoints<dim>      &material_points,
    const LoadStepSystem<dim>      &system,
    TrilinosWrappers::SparseMatrix &matrix)
  {
    const auto &steps = system.point_steps;
    std::vector<std::pair<types::global_dof_index, unsigned int>> rows;
    std::vector<types::global_dof_index>                          indices;
    for (const auto &point : material_points.particles())
      {
        const PointStep<dim> &step = steps.of(point);
        const double m = PointState<dim>(point.get_properties()).mass();
        rows.clear();
        for (unsigned int k = 0; k < step.support.n_nodes * dim; ++k)
          {
            const auto row = system.system_index(step.dofs[k]);
            if (row != numbers::invalid_dof_index)
              rows.emplace_back(row, k);
          }
        std::sort(rows.begin(), rows.end());
        indices.resize(rows.size());
        for (unsigned int a = 0; a < rows.size(); ++a)
          indices[a] = rows[a].first;
        block_adder.add(
          indices.data(),
          indices.size(),
          [&](const unsigned int a, const unsigned int b) {
            const unsigned int k = rows[a].second, l = rows[b].second;
            return k % dim != l % dim ? 0. :
                                        c * m * step.support.weights[k / dim] *
                                          step.support.weights[l / dim];
          },
          matrix,
          system.off_process_rows);
      }
  }



  template class NodalMomentum<2>;
  template class NodalMomentum<3>;
} // namespace impm
