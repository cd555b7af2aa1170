// F-bar's part of the system matrix: each point's tangent with its F-bar
// term (FBar::point_tangent) and the coupling blocks (add_patch_stiffness):
// the rank-one block of each patch, or with cell pressure unknowns each
// patch's block over its DoFs and its pressure and the pressure-jump
// stabilisation's. The patches, their volumes and pressures are in
// f_bar.cc; the coupling's functions in f_bar_coupling.cc.
#include <impm/assembly/f_bar.h>

#include <algorithm>

namespace impm
{
  template <int dim>
  Tensor<4, dim>
  FBar<dim>::point_tangent(const unsigned int    p,
                           const Tensor<4, dim> &tangent,
                           const Tensor<2, dim> &force_stress,
                           const Tensor<2, dim> &gradient_map,
                           HoopTangent<dim>     *hoop,
                           const double          hoop_force_stress,
                           const double          hoop_map)
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
    const double d = n_volume_directions();
    if (hoop != nullptr)
      {
        // The dilatation stretches the hoop too (d(dF_tt) = e dF_tt, the
        // statement's hoop column e / hoop_map): the in-plane stress's
        // share, and the hoop force's response D_t (its geometric part,
        // minus the hoop force's factor per unit e, cancelled). The hoop
        // tangent gains the F-bar terms of its row and column.
        const double hoop_reference = 1. / hoop_map;
        D += hoop->in_plane_by_hoop * hoop_reference;
        double hoop_response =
          hoop->hoop_by_hoop * hoop_reference + hoop_force_stress;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int q = 0; q < dim; ++q)
            hoop_response += hoop->hoop_by_in_plane[k][q] * reference[k][q];
        dilatation_hoop_stress[p] = hoop_response;
      }
    dilatation_stress[p] = D;
    // With pressure unknowns the point's volume also follows the
    // isochoric part of the perturbation: d ln dJ* = -(t~ : G) / k, G
    // with its hoop part dF_tt / dF_tt.
    Tensor<2, dim> map        = gradient_map;
    double         hoop_share = 1.; // the hoop column's, over dF_tt
    if (has_pressure_unknowns())
      {
        for (unsigned int q = 0; q < dim; ++q)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              map[q][k] += pressure_response[p][k][l] * gradient_map[q][l] /
                           bulk_response[p];
        hoop_share += pressure_hoop_response[p] / bulk_response[p];
      }
    if (hoop != nullptr)
      {
        const double hoop_response = dilatation_hoop_stress[p];
        hoop->in_plane_by_hoop -= D * (hoop_share * hoop_map / d);
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int q = 0; q < dim; ++q)
            hoop->hoop_by_in_plane[k][q] -= hoop_response * map[q][k] / d;
        hoop->hoop_by_hoop -= hoop_response * hoop_share * hoop_map / d;
      }
    Tensor<4, dim> corrected = tangent;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int q = 0; q < dim; ++q)
            corrected[i][j][k][q] -= D[i][j] * map[q][k] / d;
    return corrected;
  }



  template <int dim>
  Tensor<1, dim>
  FBar<dim>::node_terms(const unsigned int    p,
                        const Tensor<1, dim> &gradient,
                        const Tensor<2, dim> &map,
                        const double          hoop_weight,
                        const double          hoop_map,
                        Tensor<1, dim>       &stress_part,
                        Tensor<1, dim>       &spatial) const
  {
    stress_part              = dilatation_stress[p] * gradient;
    spatial                  = gradient * map;
    Tensor<1, dim> isochoric = !has_pressure_unknowns() ?
                                 Tensor<1, dim>() :
                                 pressure_response[p] * spatial;
    if (grid.cartesian().axisymmetric) // the hoop row and column
      {
        const double hoop_column = hoop_weight * hoop_map;
        stress_part[0] += hoop_weight * dilatation_hoop_stress[p];
        spatial[0] += hoop_column;
        if (has_pressure_unknowns())
          isochoric[0] += pressure_hoop_response[p] * hoop_column;
      }
    return isochoric;
  }



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
    const bool         axisymmetric = grid.cartesian().axisymmetric;
    const unsigned int n_patches    = mean_jacobian.size();
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
            const double         *h =
              axisymmetric ? gradients.hoop_weights(p) : nullptr;
            const double hoop_map = axisymmetric ? gradients.hoop_map(p) : 1.;
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              {
                Tensor<1, dim> stress_part, spatial;
                node_terms(p,
                           g[v],
                           map,
                           axisymmetric ? h[v] : 0.,
                           hoop_map,
                           stress_part,
                           spatial);
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
    const bool         axisymmetric = grid.cartesian().axisymmetric;
    const unsigned int n_patches    = mean_jacobian.size();
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
            const double         *h =
              axisymmetric ? gradients.hoop_weights(p) : nullptr;
            const double hoop_map = axisymmetric ? gradients.hoop_map(p) : 1.;
            corner += volume_share[p] * point_volume[p] / k;
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              {
                Tensor<1, dim>       stress_part, spatial;
                const Tensor<1, dim> isochoric =
                  node_terms(p,
                             g[v],
                             map,
                             axisymmetric ? h[v] : 0.,
                             hoop_map,
                             stress_part,
                             spatial);
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    const int position =
                      position_in_patch[step.dofs[v * dim + i]];
                    if (position < 0)
                      continue;
                    a[position] += stress_part[i] / (n_volume_directions() * k);
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


  template Tensor<4, 2>
  FBar<2>::point_tangent(const unsigned int,
                         const Tensor<4, 2> &,
                         const Tensor<2, 2> &,
                         const Tensor<2, 2> &,
                         HoopTangent<2> *,
                         const double,
                         const double);
  template Tensor<4, 3>
  FBar<3>::point_tangent(const unsigned int,
                         const Tensor<4, 3> &,
                         const Tensor<2, 3> &,
                         const Tensor<2, 3> &,
                         HoopTangent<3> *,
                         const double,
                         const double);
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
