// The ghost penalty's faces and matrices: FaceJumpPenalty.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/vector.h>

#include <impm/system/face_jump_penalty.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace impm
{
  template <int dim>
  FaceJumpPenalty<dim>::FaceJumpPenalty(const BackgroundGrid<dim> &grid,
                                        const double               scale,
                                        const double               coefficient,
                                        const unsigned int         h_power,
                                        const double fill_threshold)
    : grid(grid)
    , coefficient(scale * coefficient)
    , h_power(h_power)
    , fill_threshold(fill_threshold)
  {}



  template <int dim>
  void
  FaceJumpPenalty<dim>::choose_faces(const MaterialPoints<dim> &material_points,
                                     const std::vector<bool>   &touched)
  {
    face_penalties.clear();
    const auto &dof_handler = grid.get_dof_handler();
    const auto &fe          = grid.get_fe();

    // Volume fraction of each cell filled by its points' current volumes,
    // shared with the neighbours' ghost copies.
    std::vector<double> fill = material_points.cell_fill_fractions(grid);
    GridTools::exchange_cell_data_to_ghosts<double, DoFHandler<dim>>(
      dof_handler,
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell) {
        return fill[cell->active_cell_index()];
      },
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
          const double value) { fill[cell->active_cell_index()] = value; });

    // A cell takes part when all its DoFs are in use.
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs_here(n), dofs_there(n);
    const auto local = [&](const types::global_dof_index dof) {
      return grid.local_index(dof);
    };
    const auto in_use = [&](const std::vector<types::global_dof_index> &dofs) {
      for (const auto dof : dofs)
        if (!touched[local(dof)])
          return false;
      return true;
    };

    const QGauss<dim - 1> quadrature(2);
    const UpdateFlags     flags = update_gradients | update_normal_vectors |
                              update_JxW_values | update_quadrature_points;
    FEFaceValues<dim>   here(grid.get_mapping(), fe, quadrature, flags);
    FEFaceValues<dim>   there(grid.get_mapping(), fe, quadrature, flags);
    std::vector<double> normal_derivative(2 * n);
    // Per face number: the penalty matrix of the last cell extents.
    std::array<FullMatrix<double>, GeometryInfo<dim>::faces_per_cell>
                                                                  face_matrices;
    std::array<Tensor<1, dim>, GeometryInfo<dim>::faces_per_cell> face_extents;
    std::array<bool, GeometryInfo<dim>::faces_per_cell> face_matrix_known{};
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        cell->get_dof_indices(dofs_here);
        if (!in_use(dofs_here))
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
            const auto neighbor = cell->neighbor(f);
            // Each face once: by the lower active cell index between owned
            // cells (a CellId, built from the cell's ancestry, took 3 % of
            // an explicit run), by the lower rank across processes.
            if (neighbor->is_locally_owned() ?
                  cell->active_cell_index() > neighbor->active_cell_index() :
                  cell->subdomain_id() > neighbor->subdomain_id())
              continue;
            if (std::min(fill[cell->active_cell_index()],
                         fill[neighbor->active_cell_index()]) >= fill_threshold)
              continue;
            neighbor->get_dof_indices(dofs_there);
            if (!in_use(dofs_there))
              continue;

            // The matrix depends on the face's number and the cell's
            // extents only (Cartesian cells, Q1): computed once for each.
            Tensor<1, dim> extents;
            for (unsigned int d = 0; d < dim; ++d)
              extents[d] = cell->extent_in_direction(d);
            // (Equal to round-off: the extents are vertex differences.)
            if (!face_matrix_known[f] ||
                (face_extents[f] - extents).norm() > 1e-12 * extents.norm())
              {
                here.reinit(cell, f);
                there.reinit(neighbor, cell->neighbor_of_neighbor(f));
                const double scale =
                  coefficient *
                  std::pow(cell->extent_in_direction(f / 2), h_power);
                FullMatrix<double> &matrix = face_matrices[f];
                matrix.reinit(2 * n, 2 * n);
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  {
                    AssertThrow(here.quadrature_point(q).distance(
                                  there.quadrature_point(q)) <
                                  1e-10 * cell->diameter(),
                                ExcInternalError());
                    const Tensor<1, dim> normal = here.normal_vector(q);
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        const unsigned int c =
                          fe.system_to_component_index(i).first;
                        normal_derivative[i] =
                          here.shape_grad_component(i, q, c) * normal;
                        normal_derivative[n + i] =
                          -there.shape_grad_component(i, q, c) * normal;
                      }
                    for (unsigned int i = 0; i < 2 * n; ++i)
                      for (unsigned int j = 0; j < 2 * n; ++j)
                        if (fe.system_to_component_index(i % n).first ==
                            fe.system_to_component_index(j % n).first)
                          matrix(i, j) += scale * normal_derivative[i] *
                                          normal_derivative[j] * here.JxW(q);
                  }
                face_matrix_known[f] = true;
                face_extents[f]      = extents;
              }
            // In axisymmetry the face is a ring: 2 pi r at its centre.
            FullMatrix<double> ring_matrix;
            if (grid.cartesian().axisymmetric)
              {
                ring_matrix = face_matrices[f];
                ring_matrix *=
                  grid.cartesian().ring_length(cell->face(f)->center());
              }
            const FullMatrix<double> &matrix =
              grid.cartesian().axisymmetric ? ring_matrix : face_matrices[f];
            // The two cells share the face's nodes: each DoF once, with
            // its rows and columns summed.
            std::vector<unsigned int> cell_dofs(2 * n);
            for (unsigned int i = 0; i < n; ++i)
              {
                cell_dofs[i]     = local(dofs_here[i]);
                cell_dofs[n + i] = local(dofs_there[i]);
              }
            std::vector<unsigned char> cell_components(2 * n);
            for (unsigned int i = 0; i < 2 * n; ++i)
              cell_components[i] = fe.system_to_component_index(i % n).first;
            face_penalties.push_back(
              merge_shared_dofs(cell_dofs, cell_components, matrix));
          }
      }
  }



  template <int dim>
  void
  FaceJumpPenalty<dim>::add_forces(const NodalVector &values,
                                   const double       factor,
                                   NodalVector       &force) const
  {
    Vector<double> face_values, face_force;
    for (const FacePenalty &face : face_penalties)
      {
        face_values.reinit(face.dofs.size());
        face_force.reinit(face.dofs.size());
        for (unsigned int i = 0; i < face.dofs.size(); ++i)
          face_values[i] = values.local_element(face.dofs[i]);
        face.matrix.vmult(face_force, face_values);
        for (unsigned int i = 0; i < face.dofs.size(); ++i)
          force.local_element(face.dofs[i]) += factor * face_force[i];
      }
  }



  template <int dim>
  void
  FaceJumpPenalty<dim>::add_matrix(const LoadStepSystem<dim>      &system,
                                   TrilinosWrappers::SparseMatrix &matrix,
                                   const double                    factor) const
  {
    // Each face's block on its DoFs in the linear system, one component at
    // a time (the penalty couples a component only to itself: a third of
    // the block in 3D), by rows in ascending system order (as
    // DenseBlockAdder wants them).
    std::vector<std::pair<types::global_dof_index, unsigned int>> entries;
    std::vector<types::global_dof_index>                          rows;
    std::vector<unsigned int>                                     local;
    std::vector<unsigned int>                                     row_offsets;
    for (const FacePenalty &face : face_penalties)
      {
        // The face's matrix, times the factor once for all components.
        const FullMatrix<double> *face_matrix = &face.matrix;
        if (factor != 1.)
          {
            scaled_matrix = face.matrix;
            scaled_matrix *= factor;
            face_matrix = &scaled_matrix;
          }
        for (unsigned int component = 0; component < dim; ++component)
          {
            entries.clear();
            for (unsigned int i = 0; i < face.dofs.size(); ++i)
              {
                const auto row = system.system_index(face.dofs[i]);
                if (row != numbers::invalid_dof_index &&
                    face.components[i] == component)
                  entries.emplace_back(row, i);
              }
            if (entries.empty())
              continue;
            std::sort(entries.begin(), entries.end());
            rows.resize(entries.size());
            local.resize(entries.size());
            for (unsigned int k = 0; k < entries.size(); ++k)
              {
                rows[k]  = entries[k].first;
                local[k] = entries[k].second;
              }
            // The face's matrix is row-major.
            row_offsets.resize(entries.size());
            for (unsigned int k = 0; k < entries.size(); ++k)
              row_offsets[k] = local[k] * face_matrix->n();
            block_adder.add(rows.data(),
                            rows.size(),
                            StoredBlock{&(*face_matrix)(0, 0),
                                        row_offsets.data(),
                                        local.data()},
                            matrix,
                            system.off_process_rows);
          }
      }
  }



  template <int dim>
  typename FaceJumpPenalty<dim>::FacePenalty
  FaceJumpPenalty<dim>::merge_shared_dofs(
    const std::vector<unsigned int>  &cell_dofs,
    const std::vector<unsigned char> &cell_components,
    const FullMatrix<double>         &cell_matrix)
  {
    FacePenalty face;
    face.dofs = cell_dofs;
    std::sort(face.dofs.begin(), face.dofs.end());
    face.dofs.erase(std::unique(face.dofs.begin(), face.dofs.end()),
                    face.dofs.end());
    std::vector<unsigned int> position(cell_dofs.size());
    for (unsigned int i = 0; i < cell_dofs.size(); ++i)
      position[i] =
        std::lower_bound(face.dofs.begin(), face.dofs.end(), cell_dofs[i]) -
        face.dofs.begin();
    face.components.resize(face.dofs.size());
    for (unsigned int i = 0; i < cell_dofs.size(); ++i)
      face.components[position[i]] = cell_components[i];
    face.matrix.reinit(face.dofs.size(), face.dofs.size());
    for (unsigned int i = 0; i < cell_dofs.size(); ++i)
      for (unsigned int j = 0; j < cell_dofs.size(); ++j)
        face.matrix(position[i], position[j]) += cell_matrix(i, j);
    return face;
  }



  template <int dim>
  void
  FaceJumpPenalty<dim>::add_blocks(
    const LoadStepSystem<dim>                         &system,
    std::vector<std::vector<types::global_dof_index>> &blocks) const
  {
    for (const FacePenalty &face : face_penalties)
      {
        std::vector<types::global_dof_index> indices;
        for (const unsigned int dof : face.dofs)
          if (system.system_index(dof) != numbers::invalid_dof_index)
            indices.push_back(system.system_index(dof));
        std::sort(indices.begin(), indices.end());
        blocks.push_back(std::move(indices));
      }
  }



  template class FaceJumpPenalty<2>;
  template class FaceJumpPenalty<3>;
} // namespace impm
