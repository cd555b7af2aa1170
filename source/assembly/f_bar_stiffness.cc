// F-bar's coupling blocks of the system matrix (FBar::add_patch_stiffness):
// the rank-one block of each patch, or with cell pressure unknowns each
// patch's block over its DoFs and its pressure and the pressure-jump
// stabilisation's. The patches, their volumes and pressures are in
// f_bar.cc; the coupling's functions in f_bar_coupling.cc.
#include <impm/assembly/f_bar.h>

#include <algorithm>

namespace impm
{
  template <int dim>
  void
  FBar<dim>::add_patch_stiffness(const PointSteps<dim>          &point_steps,
                                 const PointGradients<dim>      &gradients,
                                 TrilinosWrappers::SparseMatrix &matrix,
                                 const OffProcessRows &off_process_rows)
  {
    if (has_pressure_unknowns())
      {
        add_pressure_stiffness(point_steps,
                               gradients,
                               matrix,
                               off_process_rows);
        return;
      }
    const unsigned int n_patches = mean_jacobian.size();
    for (unsigned int patch = 0; patch < n_patches; ++patch)
      {
        const unsigned int first_dof = dof_start[patch];
        const unsigned int n_dofs    = dof_start[patch + 1] - first_dof;
        if (n_dofs == 0)
          continue;
        for (unsigned int k = 0; k < n_dofs; ++k)
          position_in_patch[patch_dofs[first_dof + k]] = k;
        a.assign(n_dofs, 0.);
        b.assign(n_dofs, 0.);
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int    p      = patch_points[c];
            const PointStep<dim> &step   = point_steps[p];
            const Tensor<1, dim> *g      = gradients.gradients(p);
            const Tensor<2, dim>  map    = gradients.gradient_map(p);
            const double          weight = volume_share[p] * jacobian[p];
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              {
                Tensor<1, dim> stress_part = dilatation_stress[p] * g[v];
                Tensor<1, dim> spatial     = g[v] * map;
                if (!hoop_stretch.empty()) // the hoop row and column
                  {
                    const double h_v = step.support.hoop_weights[v];
                    stress_part[0] += h_v * dilatation_hoop_stress[p];
                    spatial[0] += h_v / hoop_stretch[p];
                  }
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    const int position =
                      position_in_patch[step.dofs[v * dim + i]];
                    if (position < 0)
                      continue;
                    a[position] += stress_part[i];
                    b[position] += weight * spatial[i];
                  }
              }
          }
        for (unsigned int k = 0; k < n_dofs; ++k)
          position_in_patch[patch_dofs[first_dof + k]] = -1;
        const double coefficient =
          1. / (n_volume_directions() * mean_jacobian[patch]);
        block_adder.add(
          patch_system_indices.data() + first_dof,
          n_dofs,
          [&](const unsigned int row, const unsigned int column) {
            return coefficient * a[row] * b[column];
          },
          matrix,
          off_process_rows);
      }
  }


  template <int dim>
  void
  FBar<dim>::add_pressure_stiffness(const PointSteps<dim>          &point_steps,
                                    const PointGradients<dim>      &gradients,
                                    TrilinosWrappers::SparseMatrix &matrix,
                                    const OffProcessRows &off_process_rows)
  {
    const unsigned int n_patches = mean_jacobian.size();
    for (unsigned int patch = 0; patch < n_patches; ++patch)
      {
        const unsigned int first_dof = dof_start[patch];
        const unsigned int n_dofs    = dof_start[patch + 1] - first_dof;
        for (unsigned int k = 0; k < n_dofs; ++k)
          position_in_patch[patch_dofs[first_dof + k]] = k;
        // a: the forces' response to the pressure; b: the row's to the
        // DoFs (over the row scale); the corner: its response to the
        // pressure (over the row scale).
        a.assign(n_dofs, 0.);
        b.assign(n_dofs, 0.);
        double corner = 0.;
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int    p    = patch_points[c];
            const PointStep<dim> &step = point_steps[p];
            const Tensor<1, dim> *g    = gradients.gradients(p);
            const Tensor<2, dim>  map  = gradients.gradient_map(p);
            const double          k    = bulk_response[p];
            corner += volume_share[p] * point_volume[p] / k;
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              {
                const Tensor<1, dim> stress_part = dilatation_stress[p] * g[v];
                const Tensor<1, dim> spatial     = g[v] * map;
                const Tensor<1, dim> isochoric = pressure_response[p] * spatial;
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    const int position =
                      position_in_patch[step.dofs[v * dim + i]];
                    if (position < 0)
                      continue;
                    a[position] += stress_part[i] / (dim * k);
                    b[position] -=
                      volume_share[p] * (point_volume[p] / k * isochoric[i] +
                                         jacobian[p] * spatial[i]);
                  }
              }
          }
        for (unsigned int k = 0; k < n_dofs; ++k)
          position_in_patch[patch_dofs[first_dof + k]] = -1;

        // The block over the patch's DoFs and pressure.
        const types::global_dof_index *indices =
          block_indices.data() + block_start[patch];
        const unsigned int n   = block_start[patch + 1] - block_start[patch];
        const auto position_of = [&](const types::global_dof_index index) {
          return static_cast<unsigned int>(
            std::lower_bound(indices, indices + n, index) - indices);
        };
        block.assign(n * n, 0.);
        // The unknown is p_c / E: its column is E times the derivative by
        // p_c, of the order of the DoFs' columns (a direct solver then
        // keeps its ordering).
        const double       E   = modulus[patch];
        const unsigned int own = position_of(pressure_index[patch]);
        for (unsigned int k = 0; k < n_dofs; ++k)
          {
            const unsigned int r =
              position_of(patch_system_indices[first_dof + k]);
            block[r * n + own] = E * a[k];
            block[own * n + r] = row_scale[patch] * b[k];
          }
        block[own * n + own] = E * row_scale[patch] * corner;
        block_adder.add(
          indices,
          n,
          [&](const unsigned int row, const unsigned int column) {
            return block[row * n + column];
          },
          matrix,
          off_process_rows);

        // The stabilisation: this pressure's share of its own row and of
        // its neighbours' (a neighbour on another process: its row goes
        // to its owner).
        const unsigned int n_jump = jump_start[patch + 1] - jump_start[patch];
        if (n_jump == 0)
          continue;
        const types::global_dof_index *jump =
          jump_indices.data() + jump_start[patch];
        const unsigned int own_jump = static_cast<unsigned int>(
          std::lower_bound(jump, jump + n_jump, pressure_index[patch]) - jump);
        const double coefficient = E * face_coefficient;
        block_adder.add(
          jump,
          n_jump,
          [&](const unsigned int row, const unsigned int column) {
            if (column != own_jump)
              return 0.;
            return row == own_jump ? coefficient * (n_jump - 1) : -coefficient;
          },
          matrix,
          off_process_rows);
      }
  }


  template void
  FBar<2>::add_patch_stiffness(const PointSteps<2> &,
                               const PointGradients<2> &,
                               TrilinosWrappers::SparseMatrix &,
                               const OffProcessRows &);
  template void
  FBar<3>::add_patch_stiffness(const PointSteps<3> &,
                               const PointGradients<3> &,
                               TrilinosWrappers::SparseMatrix &,
                               const OffProcessRows &);
} // namespace impm
