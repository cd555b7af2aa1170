#include <impm/assembly/f_bar.h>
#include <impm/system/load_step_system.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace impm
{
  template <int dim>
  void
  FBar<dim>::setup(const MaterialPoints<dim> &material_points,
                   const LoadStepSystem<dim> &system,
                   const unsigned int         n_local_dofs)
  {
    const auto        &point_steps = system.point_steps;
    const unsigned int n_points    = point_steps.size();
    patch_start.clear();
    patch_points.clear();
    patch_points.reserve(n_points);
    volume_share.assign(n_points, 0.);
    jacobian.assign(n_points, 1.);
    dilatation_stress.resize(n_points);

    // The particle handler holds the points cell by cell: each cell's run
    // of points is split by body (in the order of the body indices).
    std::vector<double>                                start_volume(n_points);
    std::vector<std::pair<unsigned int, unsigned int>> cell_points; // body, p
    const auto                                         close_cell = [&]() {
      std::stable_sort(cell_points.begin(),
                       cell_points.end(),
                       [](const auto &x, const auto &y) {
                         return x.first < y.first;
                       });
      for (unsigned int c = 0; c < cell_points.size(); ++c)
        {
          if (c == 0 || cell_points[c].first != cell_points[c - 1].first)
            patch_start.push_back(patch_points.size());
          patch_points.push_back(cell_points[c].second);
        }
      cell_points.clear();
    };
    unsigned int p              = 0;
    auto         previous_point = material_points.particles().begin();
    for (auto point = material_points.particles().begin();
         point != material_points.particles().end();
         ++point, ++p)
      {
        if (p > 0 && point->get_surrounding_cell() !=
                       previous_point->get_surrounding_cell())
          close_cell();
        previous_point                   = point;
        const auto            properties = point->get_properties();
        const PointState<dim> state(properties);
        start_volume[p] = state.jacobian() * state.initial_volume();
        cell_points.emplace_back(material_points.body_of(properties), p);
      }
    close_cell();
    patch_start.push_back(patch_points.size());
    const unsigned int n_patches = patch_start.size() - 1;
    mean_jacobian.assign(n_patches, 1.);

    // Volume shares and the system DoFs each patch touches.
    dof_start.assign(1, 0);
    patch_dofs.clear();
    patch_system_indices.clear();
    position_in_patch.assign(n_local_dofs, -1);
    std::vector<std::pair<types::global_dof_index, unsigned int>> dofs;
    for (unsigned int patch = 0; patch < n_patches; ++patch)
      {
        double volume = 0.;
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          volume += start_volume[patch_points[c]];
        dofs.clear();
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int    q    = patch_points[c];
            const PointStep<dim> &step = point_steps[q];
            volume_share[q]            = start_volume[q] / volume;
            for (unsigned int k = 0; k < step.support.n_nodes * dim; ++k)
              {
                const unsigned int local = step.dofs[k];
                const auto         index = system.system_index(local);
                if (index != numbers::invalid_dof_index &&
                    position_in_patch[local] < 0)
                  {
                    position_in_patch[local] = 0;
                    dofs.emplace_back(index, local);
                  }
              }
          }
        std::sort(dofs.begin(), dofs.end());
        for (const auto &[index, local] : dofs)
          {
            position_in_patch[local] = -1;
            patch_dofs.push_back(local);
            patch_system_indices.push_back(index);
          }
        dof_start.push_back(patch_dofs.size());
      }
  }



  template <int dim>
  std::vector<std::vector<types::global_dof_index>>
  FBar<dim>::patch_rows() const
  {
    std::vector<std::vector<types::global_dof_index>> rows;
    rows.reserve(mean_jacobian.size());
    for (unsigned int patch = 0; patch < mean_jacobian.size(); ++patch)
      if (dof_start[patch + 1] > dof_start[patch])
        rows.emplace_back(patch_system_indices.begin() + dof_start[patch],
                          patch_system_indices.begin() + dof_start[patch + 1]);
    return rows;
  }



  template <int dim>
  void
  FBar<dim>::average(std::vector<PointStep<dim>> &point_steps)
  {
    for (unsigned int patch = 0; patch < mean_jacobian.size(); ++patch)
      {
        double mean = 0.;
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int p = patch_points[c];
            jacobian[p] = determinant(point_steps[p].deformation_increment);
            mean += volume_share[p] * jacobian[p];
          }
        mean_jacobian[patch] = mean;
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int p = patch_points[c];
            point_steps[p].deformation_increment *=
              std::pow(mean / jacobian[p], 1. / dim);
          }
      }
  }



  template <int dim>
  Tensor<4, dim>
  FBar<dim>::point_tangent(const unsigned int    p,
                           const Tensor<4, dim> &tangent,
                           const Tensor<2, dim> &force_stress,
                           const Tensor<2, dim> &gradient_map)
  {
    // D = A : R + S with R the inverse of the gradient map: the response
    // to a uniform dilatation of the current configuration, d(dF) = e dF.
    const Tensor<2, dim> reference = invert(gradient_map);
    Tensor<2, dim>       D         = force_stress;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int q = 0; q < dim; ++q)
            D[i][j] += tangent[i][j][k][q] * reference[k][q];
    dilatation_stress[p]     = D;
    Tensor<4, dim> corrected = tangent;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int q = 0; q < dim; ++q)
            corrected[i][j][k][q] -= D[i][j] * gradient_map[q][k] / dim;
    return corrected;
  }



  template <int dim>
  std::string
  FBar<dim>::description() const
  {
    return "F-bar: each point's volume change is the mean of the points of "
           "its body in its cell";
  }



  template class FBar<2>;
  template class FBar<3>;
} // namespace impm
