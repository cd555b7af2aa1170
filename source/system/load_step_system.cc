#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <impm/system/load_step_system.h>

#include <algorithm>
#include <iterator>
#include <numeric>
#include <stdexcept>

namespace impm
{
  template <int dim>
  LoadStepSystem<dim>::LoadStepSystem(const BackgroundGrid<dim> &grid,
                                      const MPI_Comm             communicator)
    : grid(grid)
    , communicator(communicator)
  {}



  template <int dim>
  void
  LoadStepSystem<dim>::evaluate_basis(
    const MaterialPoints<dim> &material_points,
    const BasisType            basis)
  {
    this->basis = basis;
    const BasisEvaluator<dim> evaluator(grid.cartesian(), basis);
    point_steps.reinit(material_points.particles());
    for (const auto &point : material_points.particles())
      {
        PointStep<dim>       &step       = point_steps.of(point);
        const auto            properties = point.get_properties();
        const PointState<dim> state(properties);
        evaluator.evaluate(point.get_location(),
                           state.domain_half_length(),
                           step.support);
        step.initial_volume = state.initial_volume();
        step.material       = &material_points.material_of(properties);
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          {
            const auto *dofs = grid.node_dofs(step.support.nodes[v]);
            if (dofs == nullptr)
              throw std::runtime_error(
                "Material point " + std::to_string(point.get_id()) +
                " couples to a node outside this process's ghost layer.");
            for (unsigned int c = 0; c < dim; ++c)
              step.dofs[v * dim + c] = (*dofs)[c];
          }
      }
  }



  template <int dim>
  void
  LoadStepSystem<dim>::face_weights(
    const unsigned int                                p,
    const Point<dim>                                 &position,
    const Tensor<1, dim>                             &half_length,
    const unsigned int                                axis,
    const double                                      sign,
    std::array<double, PointSupport<dim>::max_nodes> &weights) const
  {
    const BasisEvaluator<dim> evaluator(grid.cartesian(), basis);
    evaluator.face_weights(
      position, half_length, axis, sign, point_steps[p].support, weights);
  }



  template <int dim>
  std::vector<bool>
  LoadStepSystem<dim>::touched_dofs() const
  {
    // Mark every DoF a point touches, and tell the owners.
    NodalVector marker;
    grid.reinit_vector(marker);
    for (const PointStep<dim> &step : point_steps)
      for (unsigned int k = 0; k < step.support.n_nodes * dim; ++k)
        marker.local_element(step.dofs[k]) = 1.;
    marker.compress(VectorOperation::add);
    marker.update_ghost_values();
    const unsigned int n_local = grid.n_local_dofs();
    std::vector<bool>  touched(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      touched[i] = marker.local_element(i) > 0.;
    return touched;
  }



  template <int dim>
  void
  LoadStepSystem<dim>::number(const std::vector<bool>      &touched,
                              const types::global_dof_index n_coupling_rows,
                              const bool                    with_groups)
  {
    touched_in_step = touched;
    // Owned DoFs in the system: touched and not constrained, numbered
    // contiguously per process.
    const unsigned int      n_owned = grid.n_locally_owned_dofs();
    std::vector<bool>       in_system(n_owned);
    types::global_dof_index n_local_system = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        in_system[i] =
          touched[i] && !grid.get_constraints().is_constrained(
                          grid.locally_owned_dofs().nth_index_in_set(i));
        n_local_system += in_system[i];
      }
    // The couplings' rows of unknowns follow this process's nodal rows.
    n_nodal_rows = n_local_system;
    n_local_system += n_coupling_rows;
    first_row = 0;
    MPI_Exscan(&n_local_system,
               &first_row,
               1,
               Utilities::MPI::mpi_type_id_for_type<types::global_dof_index>,
               MPI_SUM,
               communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      first_row = 0;
    const types::global_dof_index n_system =
      Utilities::MPI::sum(n_local_system, communicator);

    NodalVector marker;
    grid.reinit_vector(marker);
    marker                       = -1.;
    types::global_dof_index next = first_row;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (in_system[i])
        marker.local_element(i) = static_cast<double>(next++);
    marker.update_ghost_values();
    const unsigned int n_local = grid.n_local_dofs();
    index_in_system.resize(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      index_in_system[i] =
        marker.local_element(i) >= 0. ?
          static_cast<types::global_dof_index>(marker.local_element(i)) :
          numbers::invalid_dof_index;

    owned.clear();
    owned.set_size(n_system);
    owned.add_range(first_row, first_row + n_local_system);
    assembly_groups.clear();
    if (with_groups)
      assembly_groups =
        make_assembly_groups(point_steps, index_in_system, grid.cartesian());
  }



  template <int dim>
  bool
  LoadStepSystem<dim>::make_pattern(
    const std::vector<std::vector<types::global_dof_index>> &blocks)
  {
    const types::global_dof_index offset         = first_row;
    const types::global_dof_index n_local_system = owned.n_elements();
    const types::global_dof_index n_system       = owned.size();
    // The constant part's faces (and, with a new pattern, its addresses)
    // may have changed.
    constant_part.clear();
    const std::uint64_t fingerprint = pattern_fingerprint(blocks);
    ++n_setups;
    if (Utilities::MPI::min(fingerprint == matrix_fingerprint ? 1u : 0u,
                            communicator) == 1u)
      {
        ++n_patterns_reused;
        return true;
      }
    matrix_fingerprint = fingerprint;
    // This process's own rows, and those it assembles for others, which
    // their owners receive into their own patterns: the matrix is made
    // from its process's rows alone. (The others' rows go into their set
    // all at once: one index at a time shifts the set's ranges, 3 % of the
    // 3D collapse at h = 0.5 m.)
    const auto is_owned = [&](const types::global_dof_index row) {
      return row >= offset && row < offset + n_local_system;
    };
    std::vector<types::global_dof_index> other_rows;
    for (const auto &indices : blocks)
      std::copy_if(indices.begin(),
                   indices.end(),
                   std::back_inserter(other_rows),
                   [&](const auto row) { return !is_owned(row); });
    for (const AssemblyGroup &group : assembly_groups)
      std::copy_if(group.rows.begin(),
                   group.rows.end(),
                   std::back_inserter(other_rows),
                   [&](const auto row) { return !is_owned(row); });
    std::sort(other_rows.begin(), other_rows.end());
    other_rows.erase(std::unique(other_rows.begin(), other_rows.end()),
                     other_rows.end());
    IndexSet others(n_system);
    others.add_indices(other_rows.begin(), other_rows.end());
    DynamicSparsityPattern own_pattern(owned);
    DynamicSparsityPattern other_pattern(others);
    const auto             add_block =
      [&](const std::vector<types::global_dof_index> &indices) {
        for (const auto row : indices)
          (is_owned(row) ? own_pattern : other_pattern)
            .add_entries(row, indices.begin(), indices.end(), true);
      };
    for (const auto &indices : blocks)
      add_block(indices);
    for (const AssemblyGroup &group : assembly_groups)
      add_block(group.rows);
    off_process_rows.reinit(owned, other_pattern, communicator);
    off_process_rows.add_received_to(own_pattern);
    matrix.reinit(owned, owned, own_pattern, communicator);
    off_process_rows.connect(matrix);
    rhs.reinit(owned, communicator);
    solution.reinit(owned, communicator);
    return false;
  }



  template <int dim>
  bool
  LoadStepSystem<dim>::begin_matrix()
  {
    if (matrix.is_compressed())
      const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix()).PutScalar(0.);
    else
      matrix = 0.;
    off_process_rows.zero();
    constant_part.restore();
    return constant_part.has_record();
  }



  template <int dim>
  void
  LoadStepSystem<dim>::keep_constant_part()
  {
    if (constant_part.has_record() ||
        off_process_rows.any_added_through_matrix())
      return;
    constant_part.record(matrix.trilinos_matrix());
    if (off_process_rows.active())
      constant_part.record(off_process_rows.matrix());
  }



  template <int dim>
  void
  LoadStepSystem<dim>::finish_matrix(const bool added_through_matrix)
  {
    off_process_rows.add_to(matrix);
    // The assembly's own writes went into the rows in place (the owned
    // ones and the off-process ones just sent): deal.II's compress(), a
    // global exchange of 1.5 ms per assembly on 2 processes, only if
    // something used the matrix's add().
    const bool added =
      added_through_matrix || off_process_rows.any_added_through_matrix();
    if (Utilities::MPI::max(added ? 1u : 0u, communicator) == 1u)
      matrix.compress(VectorOperation::add);
  }



  template <int dim>
  double
  LoadStepSystem<dim>::norm_in_system(const NodalVector &vector) const
  {
    double sum = 0.;
    for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
      if (index_in_system[i] != numbers::invalid_dof_index)
        sum += std::pow(vector.local_element(i), 2);
    return std::sqrt(Utilities::MPI::sum(sum, communicator));
  }



  template <int dim>
  NearNullSpace
  LoadStepSystem<dim>::rigid_body_modes() const
  {
    const types::global_dof_index first =
      owned.n_elements() > 0 ? owned.nth_index_in_set(0) : 0;
    // The rows of this process: component and node position (the volume
    // unknowns after the nodal rows have no rigid-body modes).
    std::vector<std::pair<unsigned int, Point<dim>>> rows(n_nodal_rows);
    std::vector<double> lowest(dim, std::numeric_limits<double>::max());
    std::vector<double> highest(dim, std::numeric_limits<double>::lowest());
    for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
      if (index_in_system[i] != numbers::invalid_dof_index)
        {
          const Point<dim> &position       = grid.position(i);
          rows[index_in_system[i] - first] = {grid.component(i), position};
          for (unsigned int d = 0; d < dim; ++d)
            {
              lowest[d]  = std::min(lowest[d], position[d]);
              highest[d] = std::max(highest[d], position[d]);
            }
        }
    Utilities::MPI::min(lowest, communicator, lowest);
    Utilities::MPI::max(highest, communicator, highest);
    Point<dim> centre;
    double     extent = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        centre[d] = 0.5 * (lowest[d] + highest[d]);
        extent    = std::max(extent, highest[d] - lowest[d]);
      }
    const double scale = extent > 0. ? 2. / extent : 1.;

    // In axisymmetry a rotation of the meridian plane strains the rings:
    // only the translations are kept.
    const unsigned int n_rotations =
      grid.cartesian().axisymmetric ? 0 : (dim == 2 ? 1 : 3);
    NearNullSpace modes;
    modes.n_modes = dim + n_rotations;
    modes.n_rows  = owned.n_elements();
    modes.values.assign(modes.n_modes * modes.n_rows, 0.);
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        const auto &[component, position] = rows[r];
        const Tensor<1, dim> x            = (position - centre) * scale;
        modes.values[component * modes.n_rows + r] = 1.;
        // Rotation about axis a: (e_a x x)[component]; in 2D about z.
        if (n_rotations == 0)
          continue;
        if constexpr (dim == 2)
          modes.values[dim * modes.n_rows + r] = component == 0 ? -x[1] : x[0];
        else
          for (unsigned int a = 0; a < 3; ++a)
            {
              const unsigned int b = (a + 1) % 3, c = (a + 2) % 3;
              // (e_a x x) = x[b] e_c - x[c] e_b
              const double value = component == c ? x[b] :
                                   component == b ? -x[c] :
                                                    0.;
              modes.values[(dim + a) * modes.n_rows + r] = value;
            }
      }
    return modes;
  }



  template <int dim>
  double
  LoadStepSystem<dim>::set_residual(
    const NodalVector                                             &external,
    const NodalVector                                             &internal,
    const std::vector<std::pair<types::global_dof_index, double>> &further_rows)
  {
    for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
      if (index_in_system[i] != numbers::invalid_dof_index)
        rhs[index_in_system[i]] =
          external.local_element(i) - internal.local_element(i);
    for (const auto &[row, residual] : further_rows)
      rhs[row] = -residual;
    rhs.compress(VectorOperation::insert);
    return rhs.l2_norm();
  }



  template <int dim>
  void
  LoadStepSystem<dim>::add_solution_to(NodalVector &increment) const
  {
    add_to_nodal(solution, increment);
  }



  template <int dim>
  void
  LoadStepSystem<dim>::copy_to_system(
    const NodalVector             &nodal,
    TrilinosWrappers::MPI::Vector &system_vector) const
  {
    system_vector.reinit(rhs);
    for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
      if (index_in_system[i] != numbers::invalid_dof_index)
        system_vector[index_in_system[i]] = nodal.local_element(i);
    system_vector.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  LoadStepSystem<dim>::add_to_nodal(
    const TrilinosWrappers::MPI::Vector &system_vector,
    NodalVector                         &nodal) const
  {
    for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
      if (index_in_system[i] != numbers::invalid_dof_index)
        nodal.local_element(i) += system_vector[index_in_system[i]];
    nodal.update_ghost_values();
  }



  template <int dim>
  std::uint64_t
  LoadStepSystem<dim>::pattern_fingerprint(
    const std::vector<std::vector<types::global_dof_index>> &blocks) const
  {
    std::vector<const std::vector<types::global_dof_index> *> row_sets;
    for (const AssemblyGroup &group : assembly_groups)
      row_sets.push_back(&group.rows);
    for (const auto &rows : blocks)
      row_sets.push_back(&rows);
    const auto by_content = [](const auto *a, const auto *b) {
      return *a < *b;
    };
    const auto same = [](const auto *a, const auto *b) { return *a == *b; };
    std::sort(row_sets.begin(), row_sets.end(), by_content);
    row_sets.erase(std::unique(row_sets.begin(), row_sets.end(), same),
                   row_sets.end());
    // FNV-1a over the sizes and the rows; never 0 (0 means no matrix).
    std::uint64_t hash = 1469598103934665603ull;
    const auto    mix  = [&hash](const std::uint64_t value) {
      hash = (hash ^ value) * 1099511628211ull;
    };
    mix(owned.size());
    mix(owned.n_elements());
    mix(owned.n_elements() > 0 ? owned.nth_index_in_set(0) : 0);
    for (const auto *rows : row_sets)
      {
        mix(rows->size());
        for (const auto row : *rows)
          mix(row);
      }
    return hash == 0 ? 1 : hash;
  }



  template class LoadStepSystem<2>;
  template class LoadStepSystem<3>;
} // namespace impm
