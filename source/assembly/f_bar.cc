#include <deal.II/grid/grid_tools.h>

#include <impm/assembly/f_bar.h>
#include <impm/base/errors.h>
#include <impm/system/load_step_system.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <utility>

namespace impm
{
  template <int dim>
  FBar<dim>::FBar(const BackgroundGrid<dim> &grid,
                  const bool                 pressure_unknowns,
                  const double               stabilisation)
    : grid(grid)
    , pressure_unknowns(pressure_unknowns)
    , stabilisation(stabilisation)
  {}



  template <int dim>
  unsigned int
  FBar<dim>::make_patches(const MaterialPoints<dim> &material_points)
  {
    patch_start.clear();
    patch_points.clear();
    patch_points.reserve(material_points.n_local_points());
    patch_cell.clear();
    patch_body.clear();

    // The particle handler holds the points cell by cell: each cell's run
    // of points is split by body (in the order of the body indices).
    std::vector<std::pair<unsigned int, unsigned int>> cell_points; // body, p
    typename Triangulation<dim>::active_cell_iterator  cell;
    const auto                                         close_cell = [&]() {
      std::stable_sort(cell_points.begin(),
                       cell_points.end(),
                       [](const auto &x, const auto &y) {
                         return x.first < y.first;
                       });
      for (unsigned int c = 0; c < cell_points.size(); ++c)
        {
          if (c == 0 || cell_points[c].first != cell_points[c - 1].first)
            {
              patch_start.push_back(patch_points.size());
              patch_cell.push_back(cell);
              patch_body.push_back(cell_points[c].first);
            }
          patch_points.push_back(cell_points[c].second);
        }
      cell_points.clear();
    };
    unsigned int p = 0;
    for (auto point = material_points.particles().begin();
         point != material_points.particles().end();
         ++point, ++p)
      {
        if (p > 0 && point->get_surrounding_cell() != cell)
          close_cell();
        cell = point->get_surrounding_cell();
        cell_points.emplace_back(
          material_points.body_of(point->get_properties()), p);
      }
    close_cell();
    patch_start.push_back(patch_points.size());
    const unsigned int n_patches = patch_start.size() - 1;
    mean_jacobian.assign(n_patches, 1.);
    return has_pressure_unknowns() ? n_patches : 0;
  }



  template <int dim>
  void
  FBar<dim>::set_up_patches(const MaterialPoints<dim>    &material_points,
                            const LoadStepSystem<dim>    &system,
                            const unsigned int            n_local_dofs,
                            const types::global_dof_index first_pressure_index,
                            const IndexSet               &owned_rows)
  {
    const auto        &point_steps = system.point_steps;
    const unsigned int n_points    = point_steps.size();
    const unsigned int n_patches   = patch_start.size() - 1;
    volume_share.assign(n_points, 0.);
    jacobian.assign(n_points, 1.);
    dilatation_stress.resize(n_points);
    patch_volume.resize(n_patches);
    std::vector<double> start_volume(n_points);
    for (const auto &point : material_points.particles())
      {
        const PointState<dim> state(point.get_properties());
        start_volume[point_steps.index_of(point)] =
          state.jacobian() * state.initial_volume();
      }

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
        patch_volume[patch] = volume;
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
    if (has_pressure_unknowns())
      set_up_pressure_unknowns(material_points,
                               point_steps,
                               first_pressure_index,
                               owned_rows);
  }



  template <int dim>
  void
  FBar<dim>::set_up_pressure_unknowns(
    const MaterialPoints<dim>    &material_points,
    const PointSteps<dim>        &point_steps,
    const types::global_dof_index first_pressure_index,
    const IndexSet               &owned_rows)
  {
    const unsigned int n_patches   = patch_start.size() - 1;
    const unsigned int n_points    = patch_points.size();
    double             cell_volume = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      cell_volume *= grid.cartesian().cell_size[d];
    cell_length      = std::pow(cell_volume, 1. / dim);
    face_coefficient = stabilisation * cell_volume / cell_length;

    // Each point's mean stress at the start of the step.
    std::vector<double> start_stress(n_points);
    for (const auto &point : material_points.particles())
      {
        const auto tau =
          PointState<dim>(point.get_properties()).kirchhoff_stress();
        double sum = 0.;
        for (unsigned int i = 0; i < n_volume_directions(); ++i)
          sum += tau[i][i];
        start_stress[point_steps.index_of(point)] = sum / n_volume_directions();
      }
    log_volume.assign(n_points, 0.);
    point_volume.assign(n_points, 1.);
    bulk_response.assign(n_points, 1.);
    pressure_response.assign(n_points, Tensor<2, dim>());
    pressure_hoop_response.assign(n_points, 0.);
    if (grid.cartesian().axisymmetric)
      {
        hoop_stretch.assign(n_points, 1.);
        dilatation_hoop_stress.assign(n_points, 0.);
      }

    // Each cell's patches: (body, pressure unknown), for this process's
    // cells and, from their owners, for the ghost cells.
    using CellPatches =
      std::vector<std::pair<unsigned int, types::global_dof_index>>;
    std::unordered_map<unsigned int, CellPatches> patches_of_cell;
    pressure_index.resize(n_patches);
    start_pressure.assign(n_patches, 0.);
    modulus.resize(n_patches);
    row_scale.resize(n_patches);
    for (unsigned int patch = 0; patch < n_patches; ++patch)
      {
        pressure_index[patch] = first_pressure_index + patch;
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          start_pressure[patch] +=
            volume_share[patch_points[c]] * start_stress[patch_points[c]];
        modulus[patch] = point_steps[patch_points[patch_start[patch]]]
                           .material->elastic_modulus();
        row_scale[patch] = modulus[patch] * patch_volume[patch] / cell_length;
        patches_of_cell[patch_cell[patch]->active_cell_index()].emplace_back(
          patch_body[patch], pressure_index[patch]);
      }
    pressure                  = start_pressure;
    const auto &triangulation = grid.get_triangulation();
    // Neighbours only matter to the stabilisation.
    if (stabilisation > 0. &&
        Utilities::MPI::n_mpi_processes(triangulation.get_communicator()) > 1)
      GridTools::exchange_cell_data_to_ghosts<CellPatches, Triangulation<dim>>(
        triangulation,
        [&](const typename Triangulation<dim>::active_cell_iterator &cell)
          -> std_cxx17::optional<CellPatches> {
          const auto found = patches_of_cell.find(cell->active_cell_index());
          if (found == patches_of_cell.end())
            return {};
          return found->second;
        },
        [&](const typename Triangulation<dim>::active_cell_iterator &cell,
            const CellPatches                                       &data) {
          patches_of_cell[cell->active_cell_index()] = data;
        });

    // Each patch's neighbours (with a stabilisation): the patches of its
    // body in the cells that share a face with its cell. Its blocks: its
    // DoFs with its pressure, and its pressure with its neighbours'.
    neighbour_start.assign(1, 0);
    neighbour_indices.clear();
    block_start.assign(1, 0);
    block_indices.clear();
    jump_start.assign(1, 0);
    jump_indices.clear();
    std::vector<types::global_dof_index> ghosts;
    for (unsigned int patch = 0; patch < n_patches; ++patch)
      {
        const auto &cell = patch_cell[patch];
        for (const unsigned int f : cell->face_indices())
          {
            if (!(stabilisation > 0.))
              break;
            if (cell->at_boundary(f) || !cell->neighbor(f)->is_active())
              continue;
            const auto found =
              patches_of_cell.find(cell->neighbor(f)->active_cell_index());
            if (found == patches_of_cell.end())
              continue;
            for (const auto &[body, index] : found->second)
              if (body == patch_body[patch])
                {
                  neighbour_indices.push_back(index);
                  if (!owned_rows.is_element(index))
                    ghosts.push_back(index);
                }
          }
        neighbour_start.push_back(neighbour_indices.size());
        const auto first_block = block_indices.size();
        block_indices.insert(block_indices.end(),
                             patch_system_indices.begin() + dof_start[patch],
                             patch_system_indices.begin() +
                               dof_start[patch + 1]);
        block_indices.push_back(pressure_index[patch]);
        std::sort(block_indices.begin() + first_block, block_indices.end());
        block_start.push_back(block_indices.size());
        if (neighbour_start[patch + 1] > neighbour_start[patch])
          {
            const auto first_jump = jump_indices.size();
            jump_indices.push_back(pressure_index[patch]);
            jump_indices.insert(jump_indices.end(),
                                neighbour_indices.begin() +
                                  neighbour_start[patch],
                                neighbour_indices.end());
            std::sort(jump_indices.begin() + first_jump, jump_indices.end());
          }
        jump_start.push_back(jump_indices.size());
      }
    std::sort(ghosts.begin(), ghosts.end());
    ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
    IndexSet ghost_rows(owned_rows.size());
    ghost_rows.add_indices(ghosts.begin(), ghosts.end());
    pressure_rows.reinit(owned_rows,
                         ghost_rows,
                         triangulation.get_communicator(),
                         true);
  }



  template <int dim>
  std::vector<std::vector<types::global_dof_index>>
  FBar<dim>::patch_rows() const
  {
    std::vector<std::vector<types::global_dof_index>> rows;
    rows.reserve(mean_jacobian.size());
    for (unsigned int patch = 0; patch < mean_jacobian.size(); ++patch)
      if (has_pressure_unknowns())
        {
          rows.emplace_back(block_indices.begin() + block_start[patch],
                            block_indices.begin() + block_start[patch + 1]);
          if (jump_start[patch + 1] > jump_start[patch])
            rows.emplace_back(jump_indices.begin() + jump_start[patch],
                              jump_indices.begin() + jump_start[patch + 1]);
        }
      else if (dof_start[patch + 1] > dof_start[patch])
        rows.emplace_back(patch_system_indices.begin() + dof_start[patch],
                          patch_system_indices.begin() + dof_start[patch + 1]);
    return rows;
  }



  template <int dim>
  void
  FBar<dim>::average(PointSteps<dim> &point_steps)
  {
    // In axisymmetry the volume change holds the hoop stretch, and the
    // material's hoop stretch takes its share of the scaling.
    const bool axisymmetric = grid.cartesian().axisymmetric;
    if (axisymmetric)
      {
        hoop_stretch.resize(point_steps.size());
        dilatation_hoop_stress.resize(point_steps.size());
      }
    const double exponent = 1. / n_volume_directions();
    for (unsigned int patch = 0; patch < mean_jacobian.size(); ++patch)
      {
        double mean = 0.;
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int p = patch_points[c];
            jacobian[p] = determinant(point_steps[p].deformation_increment);
            if (axisymmetric)
              {
                hoop_stretch[p] = point_steps[p].hoop_increment;
                jacobian[p] *= hoop_stretch[p];
              }
            mean += volume_share[p] * jacobian[p];
          }
        mean_jacobian[patch] = mean;
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int p       = patch_points[c];
            const double       scaling = std::pow(mean / jacobian[p], exponent);
            point_steps[p].deformation_increment *= scaling;
            if (axisymmetric)
              point_steps[p].material_hoop_increment =
                scaling * hoop_stretch[p];
          }
      }
  }



  template <int dim>
  bool
  FBar<dim>::equalise_pressures(
    PointSteps<dim>                         &point_steps,
    const std::function<bool(unsigned int)> &update_point)
  {
    // A point's solve: Newton on ln dJ*, its slope k from the model's
    // tangent (the elastic modulus where the tangent gives no slope, at
    // an apex), steps of at most 5 % of volume.
    constexpr unsigned int max_iterations = 30;
    Tensor<4, 3>           C;
    // In axisymmetry the mean stress and the volume are three-dimensional
    // (the hoop's share), as in average().
    const bool         axisymmetric = grid.cartesian().axisymmetric;
    const unsigned int d            = n_volume_directions();
    for (unsigned int patch = 0; patch < mean_jacobian.size(); ++patch)
      {
        const double target = pressure[patch];
        // Met when the mean stress is within a few round-offs of the
        // target (E times 1e-16 is the round-off of a Hencky stress) or
        // the step in ln dJ* is; a solve that stops short of that but
        // within 1e-10 of the target (round-off above the estimate) is
        // accepted.
        const double tolerance =
          1e-14 * std::abs(target) + 4e-16 * modulus[patch];
        const double acceptable =
          1e-10 * std::abs(target) + 1e-12 * modulus[patch];
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int   p              = patch_points[c];
            PointStep<dim>      &step           = point_steps[p];
            const Tensor<2, dim> true_increment = step.deformation_increment;
            jacobian[p]                         = determinant(true_increment);
            if (axisymmetric)
              {
                hoop_stretch[p] = step.hoop_increment;
                jacobian[p] *= hoop_stretch[p];
              }
            const double log_jacobian = std::log(jacobian[p]);
            double      &lambda       = log_volume[p];
            bool         converged    = false;
            double       residual     = 0.;
            for (unsigned int iteration = 0; iteration < max_iterations;
                 ++iteration)
              {
                const double scaling = std::exp((lambda - log_jacobian) / d);
                step.deformation_increment = true_increment * scaling;
                if (axisymmetric)
                  step.material_hoop_increment = scaling * hoop_stretch[p];
                if (!update_point(p))
                  return false;
                const auto &tau = step.update.kirchhoff_stress;
                double      sum = 0.;
                for (unsigned int i = 0; i < d; ++i)
                  sum += tau[i][i];
                residual = sum / d - target;
                step.material->tangent(step.update, d, C);
                // t_kl = (1/d) sum_i C_iikl (k, l in the plane, and the
                // hoop's t_tt), its mean k and its isochoric part t~.
                Tensor<2, dim> t;
                double         t_hoop = 0.;
                for (unsigned int i = 0; i < d; ++i)
                  {
                    for (unsigned int k = 0; k < dim; ++k)
                      for (unsigned int l = 0; l < dim; ++l)
                        t[k][l] += C[i][i][k][l] / d;
                    if (axisymmetric)
                      t_hoop += C[i][i][2][2] / d;
                  }
                const double slope = (trace(t) + t_hoop) / d;
                for (unsigned int k = 0; k < dim; ++k)
                  t[k][k] -= slope;
                bulk_response[p]     = std::max(slope, 1e-8 * modulus[patch]);
                pressure_response[p] = t;
                pressure_hoop_response[p] = axisymmetric ? t_hoop - slope : 0.;
                // lambda stays the one just evaluated when the loop ends.
                const double step_length =
                  -residual /
                  (slope > 1e-3 * modulus[patch] ? slope : modulus[patch]);
                converged = std::abs(residual) <= tolerance ||
                            std::abs(step_length) < 1e-16;
                if (converged || iteration + 1 == max_iterations)
                  break;
                lambda += std::max(-0.05, std::min(0.05, step_length));
              }
            if ((!converged && !(std::abs(residual) <= acceptable)) ||
                !std::isfinite(lambda))
              return false;
            point_volume[p] = std::exp(lambda);
          }
      }
    return true;
  }



  template <int dim>
  void
  FBar<dim>::reset_pressure_unknowns()
  {
    pressure = start_pressure;
    std::fill(log_volume.begin(), log_volume.end(), 0.);
  }



  template <int dim>
  void
  FBar<dim>::add_to_pressure_unknowns(
    const TrilinosWrappers::MPI::Vector &solution)
  {
    // The unknown is the pressure over the body's Young's modulus.
    for (unsigned int patch = 0; patch < pressure.size(); ++patch)
      pressure[patch] += modulus[patch] * solution[pressure_index[patch]];
  }



  template <int dim>
  double
  FBar<dim>::perturb_pressure_unknown(const types::global_dof_index index,
                                      const double                  amount)
  {
    if (pressure.empty() || index < pressure_index.front() ||
        index > pressure_index.back())
      return 0.;
    const unsigned int patch = index - pressure_index.front();
    const double       scale = 1. / cell_length;
    pressure[patch] += amount * scale * modulus[patch];
    return scale;
  }



  template <int dim>
  const std::vector<std::pair<types::global_dof_index, double>> &
  FBar<dim>::pressure_residuals()
  {
    pressure_rows = 0.;
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    for (unsigned int patch = 0; patch < pressure.size(); ++patch)
      {
        double volume_difference = 0.;
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int p = patch_points[c];
            volume_difference +=
              volume_share[p] * (point_volume[p] - jacobian[p]);
          }
        const unsigned int n_neighbours =
          neighbour_start[patch + 1] - neighbour_start[patch];
        indices.push_back(pressure_index[patch]);
        values.push_back(row_scale[patch] * volume_difference +
                         face_coefficient * n_neighbours * pressure[patch]);
        for (unsigned int j = neighbour_start[patch];
             j < neighbour_start[patch + 1];
             ++j)
          {
            indices.push_back(neighbour_indices[j]);
            values.push_back(-face_coefficient * pressure[patch]);
          }
      }
    pressure_rows.add(indices, values);
    pressure_rows.compress(VectorOperation::add);
    residuals.resize(pressure.size());
    for (unsigned int patch = 0; patch < pressure.size(); ++patch)
      residuals[patch] = {pressure_index[patch],
                          pressure_rows[pressure_index[patch]]};
    return residuals;
  }



  template <int dim>
  std::string
  FBar<dim>::description() const
  {
    if (has_pressure_unknowns())
      return "F-bar with cell pressures: the points of a body in a cell "
             "share one pressure, an unknown, and their volume is the "
             "cell's" +
             (stabilisation > 0. ?
                "; pressure-jump stabilisation " + number_text(stabilisation) :
                std::string());
    return "F-bar: each point's volume change is the mean of the points of "
           "its body in its cell";
  }



  template class FBar<2>;
  template class FBar<3>;

} // namespace impm
