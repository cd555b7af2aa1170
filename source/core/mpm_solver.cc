#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <deal.II/numerics/vector_tools.h>

#include <impm/core/mpm_solver.h>
#include <impm/core/run.h>
#include <impm/mechanics/equilibrium_forms.h>
#include <impm/mechanics/pulled_back_stress.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace impm
{
  namespace
  {
    /** The phases of a load step, in the order they run. */
    const std::vector<std::string> phase_names = {"basis evaluation",
                                                  "system setup",
                                                  "stress update",
                                                  "assembly",
                                                  "linear solve",
                                                  "point update",
                                                  "output"};

    /** Read a 3x3 tensor stored row by row. */
    Tensor<2, 3>
    read_tensor(const ArrayView<const double> &properties,
                const unsigned int             first)
    {
      Tensor<2, 3> t;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          t[i][j] = properties[first + 3 * i + j];
      return t;
    }

    /** Write a 3x3 tensor row by row. */
    void
    write_tensor(const Tensor<2, 3>      &t,
                 const ArrayView<double> &properties,
                 const unsigned int       first)
    {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          properties[first + 3 * i + j] = t[i][j];
    }

    /** Read a symmetric 3x3 tensor stored as its six unrolled entries. */
    SymmetricTensor<2, 3>
    read_symmetric(const ArrayView<const double> &properties,
                   const unsigned int             first)
    {
      SymmetricTensor<2, 3> t;
      for (unsigned int k = 0; k < 6; ++k)
        t.access_raw_entry(k) = properties[first + k];
      return t;
    }

    /** Write a symmetric 3x3 tensor as its six unrolled entries. */
    void
    write_symmetric(const SymmetricTensor<2, 3> &t,
                    const ArrayView<double>     &properties,
                    const unsigned int           first)
    {
      for (unsigned int k = 0; k < 6; ++k)
        properties[first + k] = t.access_raw_entry(k);
    }

    /** Write @p text to @p path through a temporary file and a rename. */
    void
    write_file_atomically(const std::string &path, const std::string &text)
    {
      {
        std::ofstream out(path + ".tmp");
        AssertThrow(out, ExcMessage("Cannot write " + path));
        out << text;
      }
      std::rename((path + ".tmp").c_str(), path.c_str());
    }
  } // namespace



  template <int dim>
  MPMSolver<dim>::MPMSolver(
    const Parameters::All<dim>                    &parameters,
    std::vector<std::unique_ptr<ForceEffect<dim>>> force_effects,
    const MPI_Comm                                 communicator)
    : parameters(parameters)
    , force_effects(std::move(force_effects))
    , communicator(communicator)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(communicator) == 0 &&
              !parameters.testing.enabled)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , triangulation(communicator)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
    , basis_type(basis_type_from_string(parameters.material_points.basis))
    , point_output(parameters.scene.output_directory, "points", communicator)
  {}



  template <int dim>
  void
  MPMSolver<dim>::make_grid()
  {
    const auto &p = parameters.grid;
    grid.initialize(p.lower_corner, p.upper_corner, p.n_cells);

    // A coarse mesh refined globally: the largest power of two that divides
    // every cell count keeps the coarse mesh, which every process stores,
    // small for large grids.
    unsigned int refinements = 0;
    while (std::all_of(p.n_cells.begin(), p.n_cells.end(), [&](unsigned n) {
      return n % (1u << (refinements + 1)) == 0;
    }))
      ++refinements;
    std::vector<unsigned int> coarse_cells(dim);
    for (unsigned int d = 0; d < dim; ++d)
      coarse_cells[d] = p.n_cells[d] >> refinements;
    GridGenerator::subdivided_hyper_rectangle(
      triangulation, coarse_cells, p.lower_corner, p.upper_corner, true);
    triangulation.refine_global(refinements);
  }



  template <int dim>
  void
  MPMSolver<dim>::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    increment.reinit(locally_owned_dofs, locally_relevant_dofs, communicator);
    internal_force.reinit(increment);
    external_force.reinit(increment);
    const auto &partitioner = *increment.get_partitioner();

    // Grid-face conditions: every constrained DoF is kept out of the linear
    // system; prescribed ones get their share of the displacement in each
    // load step. A DoF on two constrained faces follows the first of them,
    // and its reaction counts there.
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    prescribed_dofs.clear();
    reaction_dofs.clear();
    reaction_columns.clear();
    const auto &grid_parameters = parameters.grid;
    for (unsigned int face = 0; face < 2 * dim; ++face)
      {
        const std::string &condition = grid_parameters.face_conditions[face];
        for (unsigned int c = 0; c < dim; ++c)
          if (condition == "fixed" || condition == "prescribed" ||
              ((condition == "roller" || condition == "prescribed normal") &&
               c == face / 2))
            reaction_columns.push_back(face * dim + c);
      }
    std::vector<bool> assigned(locally_owned_dofs.n_elements() +
                                 partitioner.n_ghost_indices(),
                               false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f))
              continue;
            const unsigned int face = cell->face(f)->boundary_id();
            const std::string &condition =
              grid_parameters.face_conditions[face];
            if (condition == "none")
              continue;
            const bool prescribed = condition.rfind("prescribed", 0) == 0;
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                const Point<dim> x      = cell->face(f)->vertex(v);
                bool             inside = true;
                if (grid_parameters.face_has_region[face])
                  for (unsigned int d = 0; d < dim; ++d)
                    inside =
                      inside &&
                      x[d] >= grid_parameters.face_regions[face].first[d] -
                                1e-10 * grid.cell_size[d] &&
                      x[d] <= grid_parameters.face_regions[face].second[d] +
                                1e-10 * grid.cell_size[d];
                if (!inside)
                  continue;
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    const bool all_components =
                      condition == "fixed" || condition == "prescribed";
                    if (!all_components && c != face / 2)
                      continue;
                    const types::global_dof_index dof =
                      cell->face(f)->vertex_dof_index(v, c);
                    const unsigned int local = partitioner.global_to_local(dof);
                    if (assigned[local])
                      continue;
                    assigned[local] = true;
                    constraints.add_line(dof);
                    if (prescribed &&
                        grid_parameters.face_displacements[face][c] != 0.)
                      prescribed_dofs.emplace_back(
                        local, grid_parameters.face_displacements[face][c]);
                    if (local < locally_owned_dofs.n_elements())
                      reaction_dofs.emplace_back(local, face * dim + c);
                  }
              }
          }
    constraints.close();
    reactions.assign(2 * dim * dim, 0.);

    // Map each grid node to the local indices of its DoFs.
    node_dofs.clear();
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto [component, vertex] = fe.system_to_component_index(i);
              const std::uint64_t node =
                grid.node_index(grid.nearest_node(cell->vertex(vertex)));
              node_dofs[node][component] =
                partitioner.global_to_local(cell_dofs[i]);
            }
        }
  }



  template <int dim>
  void
  MPMSolver<dim>::create_material_points()
  {
    using P                 = PointProperties<dim>;
    const auto &bodies      = parameters.bodies;
    bool        any_plastic = false;
    for (const auto &body : bodies)
      any_plastic = any_plastic || body.material->is_plastic();
    layout.initialize(P::n_fixed_properties, any_plastic, bodies.size() > 1);
    material_points.initialize(triangulation, mapping, layout.n_properties);

    double cell_volume = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      cell_volume *= grid.cell_size[d];

    std::vector<double> properties(layout.n_properties, 0.);
    for (unsigned int i = 0; i < 3; ++i)
      {
        properties[P::deformation_gradient + 4 * i]  = 1.;
        properties[P::elastic_left_cauchy_green + i] = 1.;
      }

    // Ids from the structured cell index, the body and the position in the
    // cell: the same on any number of processes.
    constexpr unsigned int max_per_cell = dim == 2 ? 100 : 1000;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          std::uint64_t cell_index = 0;
          Point<dim>    cell_lower;
          for (int d = dim - 1; d >= 0; --d)
            {
              const unsigned int i = static_cast<unsigned int>(std::floor(
                (cell->center()[d] - grid.lower[d]) / grid.cell_size[d]));
              cell_index           = cell_index * grid.n_cells[d] + i;
              cell_lower[d]        = grid.node_coordinate(d, i);
            }
          std::vector<Point<dim>> placed;
          for (unsigned int b = 0; b < bodies.size(); ++b)
            {
              const auto        &body       = bodies[b];
              const unsigned int n          = body.points_per_direction;
              unsigned int       n_per_cell = 1;
              for (unsigned int d = 0; d < dim; ++d)
                n_per_cell *= n;
              const double volume           = cell_volume / n_per_cell;
              properties[P::initial_volume] = volume;
              properties[P::mass]           = body.density * volume;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  properties[P::domain_half_length + d] =
                    grid.cell_size[d] / (2. * n);
                  properties[P::initial_domain_half_length + d] =
                    grid.cell_size[d] / (2. * n);
                }
              if (layout.body != PointLayout::absent)
                properties[layout.body] = b;
              for (unsigned int q = 0; q < n_per_cell; ++q)
                {
                  Point<dim>   position, reference;
                  unsigned int rest = q;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      reference[d] = (rest % n + 0.5) / n;
                      rest /= n;
                      position[d] =
                        cell_lower[d] + reference[d] * grid.cell_size[d];
                    }
                  // A position inside two bodies belongs to the first.
                  if (!body.contains(position) ||
                      std::any_of(placed.begin(),
                                  placed.end(),
                                  [&](const Point<dim> &other) {
                                    return other.distance(position) <
                                           1e-12 * grid.cell_size[0];
                                  }))
                    continue;
                  placed.push_back(position);
                  for (unsigned int d = 0; d < dim; ++d)
                    properties[P::initial_position + d] = position[d];
                  material_points.insert_particle(
                    position,
                    reference,
                    (cell_index * Body<dim>::max_bodies + b) * max_per_cell + q,
                    cell,
                    ArrayView<const double>(properties));
                }
            }
        }
    material_points.update_cached_numbers();
    double mass = 0.;
    for (const auto &point : material_points)
      mass += point.get_properties()[P::mass];
    initial_mass = Utilities::MPI::sum(mass, communicator);
    AssertThrow(material_points.n_global_particles() > 0,
                ExcMessage("The bodies contain no material points: no point "
                           "position of the grid's cells lies inside them."));
  }



  template <int dim>
  void
  MPMSolver<dim>::evaluate_basis()
  {
    TimerOutput::Scope scope(timer, "basis evaluation");
    using P = PointProperties<dim>;
    const BasisEvaluator<dim> basis(grid, basis_type);
    point_steps.resize(material_points.n_locally_owned_particles());
    unsigned int p = 0;
    for (const auto &point : material_points)
      {
        PointStep                    &step       = point_steps[p++];
        const ArrayView<const double> properties = point.get_properties();
        Tensor<1, dim>                half_length;
        for (unsigned int d = 0; d < dim; ++d)
          half_length[d] = properties[P::domain_half_length + d];
        basis.evaluate(point.get_location(), half_length, step.support);
        step.initial_volume = properties[P::initial_volume];
        step.material       = &material_of(properties);
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          {
            const auto node = node_dofs.find(step.support.nodes[v]);
            AssertThrow(node != node_dofs.end(),
                        ExcMessage("Material point " +
                                   std::to_string(point.get_id()) +
                                   " couples to a node outside this "
                                   "process's ghost layer."));
            for (unsigned int c = 0; c < dim; ++c)
              step.dofs[v * dim + c] = node->second[c];
          }
      }
  }



  template <int dim>
  void
  MPMSolver<dim>::number_system_dofs()
  {
    TimerOutput::Scope scope(timer, "system setup");

    // Mark every DoF a point touches, and tell the owners.
    LinearAlgebra::distributed::Vector<double> marker(locally_owned_dofs,
                                                      locally_relevant_dofs,
                                                      communicator);
    for (const PointStep &step : point_steps)
      for (unsigned int k = 0; k < step.support.n_nodes * dim; ++k)
        marker.local_element(step.dofs[k]) = 1.;
    marker.compress(VectorOperation::add);
    marker.update_ghost_values();
    const unsigned int n_local_elements =
      locally_owned_dofs.n_elements() +
      increment.get_partitioner()->n_ghost_indices();
    std::vector<bool> touched(n_local_elements);
    for (unsigned int i = 0; i < n_local_elements; ++i)
      touched[i] = marker.local_element(i) > 0.;
    marker.zero_out_ghost_values();

    // Owned DoFs in the system: touched and not constrained, numbered
    // contiguously per process.
    const unsigned int      n_owned = locally_owned_dofs.n_elements();
    std::vector<bool>       in_system(n_owned);
    types::global_dof_index n_local_system = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        in_system[i] = touched[i] && !constraints.is_constrained(
                                       locally_owned_dofs.nth_index_in_set(i));
        n_local_system += in_system[i];
      }
    types::global_dof_index offset = 0;
    MPI_Exscan(&n_local_system,
               &offset,
               1,
               Utilities::MPI::mpi_type_id_for_type<types::global_dof_index>,
               MPI_SUM,
               communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      offset = 0;
    const types::global_dof_index n_system =
      Utilities::MPI::sum(n_local_system, communicator);

    marker                       = -1.;
    types::global_dof_index next = offset;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (in_system[i])
        marker.local_element(i) = static_cast<double>(next++);
    marker.update_ghost_values();
    const unsigned int n_local =
      n_owned + increment.get_partitioner()->n_ghost_indices();
    system_index.resize(n_local);
    for (unsigned int i = 0; i < n_local; ++i)
      system_index[i] =
        marker.local_element(i) >= 0. ?
          static_cast<types::global_dof_index>(marker.local_element(i)) :
          numbers::invalid_dof_index;

    system_owned.clear();
    system_owned.set_size(n_system);
    system_owned.add_range(offset, offset + n_local_system);
    system_relevant = system_owned;
    make_assembly_groups();
    std::vector<types::global_dof_index> rows;
    for (const AssemblyGroup &group : assembly_groups)
      rows.insert(rows.end(), group.rows.begin(), group.rows.end());
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    system_relevant.add_indices(rows.begin(), rows.end());
    system_relevant.compress();

    ghost_faces.clear();
    if (parameters.stabilisation.enabled)
      setup_ghost_penalty(touched);
    for (const FacePenalty &face : ghost_faces)
      for (const unsigned int dof : face.dofs)
        if (system_index[dof] != numbers::invalid_dof_index)
          system_relevant.add_index(system_index[dof]);
    system_relevant.compress();

    // The sparsity pattern comes from the points' supports and the
    // stabilised faces.
    DynamicSparsityPattern               dsp(system_relevant);
    std::vector<types::global_dof_index> indices;
    for (const FacePenalty &face : ghost_faces)
      {
        indices.clear();
        for (const unsigned int dof : face.dofs)
          if (system_index[dof] != numbers::invalid_dof_index)
            indices.push_back(system_index[dof]);
        std::sort(indices.begin(), indices.end());
        for (const auto row : indices)
          dsp.add_entries(row, indices.begin(), indices.end(), true);
      }
    for (const AssemblyGroup &group : assembly_groups)
      for (const auto row : group.rows)
        dsp.add_entries(row, group.rows.begin(), group.rows.end(), true);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               system_owned,
                                               communicator,
                                               system_relevant);
    system_matrix.reinit(system_owned, system_owned, dsp, communicator);
    system_rhs.reinit(system_owned, communicator);
    system_solution.reinit(system_owned, communicator);
    n_system_dofs_last = n_system;
  }



  template <int dim>
  void
  MPMSolver<dim>::make_assembly_groups()
  {
    // Order the points by their support DoFs (ties by index, so the order
    // of summation within a group is that of the points), then cut the
    // order where the support changes.
    std::vector<unsigned int> order(point_steps.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto same_support = [this](const unsigned int a,
                                     const unsigned int b) {
      const PointStep &x = point_steps[a], &y = point_steps[b];
      return x.support.n_nodes == y.support.n_nodes &&
             std::equal(x.dofs.begin(),
                        x.dofs.begin() + x.support.n_nodes * dim,
                        y.dofs.begin());
    };
    std::sort(order.begin(),
              order.end(),
              [this](const unsigned int a, const unsigned int b) {
                const PointStep &x = point_steps[a], &y = point_steps[b];
                if (x.support.n_nodes != y.support.n_nodes)
                  return x.support.n_nodes < y.support.n_nodes;
                const unsigned int n = x.support.n_nodes * dim;
                for (unsigned int k = 0; k < n; ++k)
                  if (x.dofs[k] != y.dofs[k])
                    return x.dofs[k] < y.dofs[k];
                return a < b;
              });

    assembly_groups.clear();
    std::vector<std::pair<types::global_dof_index, unsigned int>> entries;
    for (unsigned int first = 0; first < order.size();)
      {
        unsigned int last = first + 1;
        while (last < order.size() && same_support(order[first], order[last]))
          ++last;
        AssemblyGroup &group = assembly_groups.emplace_back();
        group.points.assign(order.begin() + first, order.begin() + last);
        const PointStep &step = point_steps[order[first]];
        entries.clear();
        for (unsigned int k = 0; k < step.support.n_nodes * dim; ++k)
          if (system_index[step.dofs[k]] != numbers::invalid_dof_index)
            entries.emplace_back(system_index[step.dofs[k]], k);
        std::sort(entries.begin(), entries.end());
        group.in_system.assign(step.support.n_nodes * dim, 0);
        for (const auto &[row, k] : entries)
          {
            group.rows.push_back(row);
            group.local.push_back(k);
            group.in_system[k] = 1;
          }
        // Points whose every DoF is constrained add nothing to the matrix.
        if (group.rows.empty())
          assembly_groups.pop_back();
        first = last;
      }
  }



  template <int dim>
  void
  MPMSolver<dim>::setup_ghost_penalty(const std::vector<bool> &touched)
  {
    using P = PointProperties<dim>;

    // Volume fraction of each cell filled by its points' current volumes,
    // shared with the neighbours' ghost copies.
    std::vector<double> fill(triangulation.n_active_cells(), 0.);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double volume = 0.;
          for (const auto &point : material_points.particles_in_cell(cell))
            {
              const auto properties = point.get_properties();
              volume +=
                determinant(read_tensor(properties, P::deformation_gradient)) *
                properties[P::initial_volume];
            }
          fill[cell->active_cell_index()] = volume / cell->measure();
        }
    GridTools::exchange_cell_data_to_ghosts<double, DoFHandler<dim>>(
      dof_handler,
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell) {
        return fill[cell->active_cell_index()];
      },
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
          const double value) { fill[cell->active_cell_index()] = value; });

    // A cell takes part when all its DoFs are in use.
    const auto        &partitioner = *increment.get_partitioner();
    const unsigned int n           = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs_here(n), dofs_there(n);
    const auto in_use = [&](const std::vector<types::global_dof_index> &dofs) {
      for (const auto dof : dofs)
        if (!touched[partitioner.global_to_local(dof)])
          return false;
      return true;
    };

    const QGauss<dim - 1> quadrature(2);
    const UpdateFlags     flags = update_gradients | update_normal_vectors |
                              update_JxW_values | update_quadrature_points;
    FEFaceValues<dim> here(mapping, fe, quadrature, flags);
    FEFaceValues<dim> there(mapping, fe, quadrature, flags);
    double            modulus = 0.;
    for (const auto &body : parameters.bodies)
      modulus = std::max(modulus, body.material->elastic_modulus());
    std::vector<double> normal_derivative(2 * n);
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
            // Each face once: by the lower cell id between owned cells, by
            // the lower rank across processes.
            if (neighbor->is_locally_owned() ?
                  !(cell->id() < neighbor->id()) :
                  cell->subdomain_id() > neighbor->subdomain_id())
              continue;
            if (std::min(fill[cell->active_cell_index()],
                         fill[neighbor->active_cell_index()]) >=
                parameters.stabilisation.fill_threshold)
              continue;
            neighbor->get_dof_indices(dofs_there);
            if (!in_use(dofs_there))
              continue;

            here.reinit(cell, f);
            there.reinit(neighbor, cell->neighbor_of_neighbor(f));
            const double scale = parameters.stabilisation.penalty_scale *
                                 modulus * cell->extent_in_direction(f / 2);
            FacePenalty face;
            face.matrix.reinit(2 * n, 2 * n);
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
                      face.matrix(i, j) += scale * normal_derivative[i] *
                                           normal_derivative[j] * here.JxW(q);
              }
            face.dofs.resize(2 * n);
            for (unsigned int i = 0; i < n; ++i)
              {
                face.dofs[i]     = partitioner.global_to_local(dofs_here[i]);
                face.dofs[n + i] = partitioner.global_to_local(dofs_there[i]);
              }
            ghost_faces.push_back(std::move(face));
          }
      }
  }



  template <int dim>
  bool
  MPMSolver<dim>::update_stresses()
  {
    TimerOutput::Scope scope(timer, "stress update");
    using P                 = PointProperties<dim>;
    unsigned int p          = 0;
    bool         admissible = true;
    for (const auto &point : material_points)
      {
        PointStep     &step = point_steps[p++];
        const auto    &s    = step.support;
        Tensor<2, dim> dF   = unit_symmetric_tensor<dim>();
        for (unsigned int v = 0; v < s.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            {
              const double du = increment.local_element(step.dofs[v * dim + i]);
              for (unsigned int j = 0; j < dim; ++j)
                dF[i][j] += du * s.gradients[v][j];
            }
        step.deformation_increment = dF;
        // An inverted or non-finite increment fails the Newton solve (and
        // lets the step control cut the step).
        const double jacobian = determinant(dF);
        if (!(jacobian > 0.) || !std::isfinite(jacobian))
          {
            admissible = false;
            continue;
          }
        step.deformation_increment_inverse = invert(dF);
        const auto properties              = point.get_properties();
        step.material->update(PulledBackStress<dim>::embed(dF),
                              read_symmetric(properties,
                                             P::elastic_left_cauchy_green),
                              step.update);
      }
    return Utilities::MPI::min(admissible ? 1 : 0, communicator) == 1;
  }



  template <int dim>
  std::vector<MaterialPointInfo<dim>>
  MPMSolver<dim>::point_infos() const
  {
    using P = PointProperties<dim>;
    std::vector<MaterialPointInfo<dim>> infos;
    infos.reserve(material_points.n_locally_owned_particles());
    for (const auto &point : material_points)
      {
        const auto              properties = point.get_properties();
        MaterialPointInfo<dim> &info       = infos.emplace_back();
        info.id                            = point.get_id();
        for (unsigned int d = 0; d < dim; ++d)
          info.initial_position[d] = properties[P::initial_position + d];
        info.body = layout.body == PointLayout::absent ?
                      0 :
                      static_cast<unsigned int>(properties[layout.body]);
        info.mass = properties[P::mass];
      }
    return infos;
  }



  template <int dim>
  void
  MPMSolver<dim>::assemble_external_force(const double load_factor)
  {
    TimerOutput::Scope scope(timer, "assembly");
    external_force = 0.;
    if (!force_effects.empty())
      {
        const auto                  infos = point_infos();
        std::vector<Tensor<1, dim>> forces(infos.size());
        for (const auto &effect : force_effects)
          effect->add_forces(infos, load_factor, forces);
        for (unsigned int p = 0; p < infos.size(); ++p)
          {
            const PointStep &step = point_steps[p];
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                external_force.local_element(step.dofs[v * dim + i]) +=
                  step.support.weights[v] * forces[p][i];
          }
      }
    external_force.compress(VectorOperation::add);

    double sum = 0.;
    for (unsigned int i = 0; i < locally_owned_dofs.n_elements(); ++i)
      if (system_index[i] != numbers::invalid_dof_index)
        sum += std::pow(external_force.local_element(i), 2);
    external_force_norm = std::sqrt(Utilities::MPI::sum(sum, communicator));
  }



  template <int dim>
  void
  MPMSolver<dim>::assemble_residual()
  {
    TimerOutput::Scope scope(timer, "assembly");
    const bool         updated_lagrangian =
      parameters.solver.formulation == "updated Lagrangian";
    internal_force = 0.;
    // The updated Lagrangian form keeps its mapped gradients for the matrix
    // of this iterate.
    if (updated_lagrangian)
      mapped_gradients.resize(point_steps.size());
    std::array<double, PointSupport<dim>::max_nodes * dim> forces;
    for (unsigned int p = 0; p < point_steps.size(); ++p)
      {
        const PointStep      &step = point_steps[p];
        const Tensor<1, dim> *gradients;
        Tensor<2, dim>        stress;
        if (!updated_lagrangian)
          {
            gradients = step.support.gradients.data();
            stress    = PreviouslyConvergedForm<dim>::force_stress(
              step.update,
              step.deformation_increment_inverse,
              step.initial_volume);
          }
        else
          {
            UpdatedLagrangianForm<dim>::map_gradients(
              step.support.gradients.data(),
              step.support.n_nodes,
              step.deformation_increment_inverse,
              mapped_gradients[p].data());
            gradients = mapped_gradients[p].data();
            stress    = UpdatedLagrangianForm<dim>::force_stress(
              step.update,
              step.deformation_increment_inverse,
              step.initial_volume);
          }
        const unsigned int n = step.support.n_nodes * dim;
        std::fill(forces.begin(), forces.begin() + n, 0.);
        add_point_forces(stress,
                         gradients,
                         step.support.n_nodes,
                         forces.data());
        for (unsigned int k = 0; k < n; ++k)
          internal_force.local_element(step.dofs[k]) += forces[k];
      }
    // Ghost stabilisation acts on the displacement increment.
    Vector<double> face_increment, face_force;
    for (const FacePenalty &face : ghost_faces)
      {
        face_increment.reinit(face.dofs.size());
        face_force.reinit(face.dofs.size());
        for (unsigned int i = 0; i < face.dofs.size(); ++i)
          face_increment[i] = increment.local_element(face.dofs[i]);
        face.matrix.vmult(face_force, face_increment);
        for (unsigned int i = 0; i < face.dofs.size(); ++i)
          internal_force.local_element(face.dofs[i]) += face_force[i];
      }
    internal_force.compress(VectorOperation::add);

    for (unsigned int i = 0; i < locally_owned_dofs.n_elements(); ++i)
      if (system_index[i] != numbers::invalid_dof_index)
        system_rhs[system_index[i]] =
          external_force.local_element(i) - internal_force.local_element(i);
    system_rhs.compress(VectorOperation::insert);
    residual_norm = system_rhs.l2_norm();
    // Without external loads (a prescribed displacement), the residual is
    // measured against the internal forces, which carry the reactions.
    if (external_force_norm == 0.)
      reference_force_norm = internal_force.l2_norm();
  }



  template <int dim>
  void
  MPMSolver<dim>::assemble_matrix()
  {
    TimerOutput::Scope scope(timer, "assembly");
    system_matrix                   = 0.;
    constexpr unsigned int max_dofs = PointSupport<dim>::max_nodes * dim;
    std::vector<double>    local_matrix(max_dofs * max_dofs);
    const bool             updated_lagrangian =
      parameters.solver.formulation == "updated Lagrangian";
    std::array<double, max_dofs> row_values;
    for (const AssemblyGroup &group : assembly_groups)
      {
        // The group's matrix over all its support's DoFs; the rows and
        // columns in the linear system are picked when it is added.
        const unsigned int n_nodes =
          point_steps[group.points.front()].support.n_nodes;
        const unsigned int n_all = n_nodes * dim;
        std::fill(local_matrix.begin(),
                  local_matrix.begin() + n_all * n_all,
                  0.);
        for (const unsigned int p : group.points)
          {
            const PointStep &step = point_steps[p];
            if (!updated_lagrangian)
              add_point_stiffness(PreviouslyConvergedForm<dim>::tangent(
                                    *step.material,
                                    step.update,
                                    step.deformation_increment_inverse,
                                    step.initial_volume),
                                  step.support.gradients.data(),
                                  n_nodes,
                                  group.in_system.data(),
                                  local_matrix.data());
            else
              add_point_stiffness(UpdatedLagrangianForm<dim>::tangent(
                                    *step.material,
                                    step.update,
                                    step.deformation_increment_inverse,
                                    step.initial_volume),
                                  mapped_gradients[p].data(),
                                  n_nodes,
                                  group.in_system.data(),
                                  local_matrix.data());
          }
        const unsigned int n = group.rows.size();
        for (unsigned int a = 0; a < n; ++a)
          {
            const double *row = &local_matrix[group.local[a] * n_all];
            for (unsigned int b = 0; b < n; ++b)
              row_values[b] = row[group.local[b]];
            system_matrix.add(group.rows[a],
                              n,
                              group.rows.data(),
                              row_values.data(),
                              /*elide_zero_values=*/false,
                              /*col_indices_are_sorted=*/true);
          }
      }
    for (const FacePenalty &face : ghost_faces)
      for (unsigned int i = 0; i < face.dofs.size(); ++i)
        if (system_index[face.dofs[i]] != numbers::invalid_dof_index)
          for (unsigned int j = 0; j < face.dofs.size(); ++j)
            if (system_index[face.dofs[j]] != numbers::invalid_dof_index &&
                face.matrix(i, j) != 0.)
              system_matrix.add(system_index[face.dofs[i]],
                                system_index[face.dofs[j]],
                                face.matrix(i, j));
    system_matrix.compress(VectorOperation::add);
  }



  template <int dim>
  void
  MPMSolver<dim>::solve_linear_system(const bool estimate_condition)
  {
    TimerOutput::Scope scope(timer, "linear solve");
    system_solution = 0.;
    if (parameters.solver.linear_solver == "direct")
      {
        SolverControl                                  control(1, 0);
        TrilinosWrappers::SolverDirect::AdditionalData data(false,
                                                            "Amesos_Klu");
        TrilinosWrappers::SolverDirect                 solver(control, data);
        solver.initialize(system_matrix);
        solver.solve(system_solution, system_rhs);
        if (estimate_condition)
          {
            // |A|_F times a lower bound of |A^-1|_2 from inverse iteration
            // with the factorisation already made.
            TrilinosWrappers::MPI::Vector x(system_owned, communicator),
              y(system_owned, communicator);
            x                   = 1. / std::sqrt(double(x.size()));
            double inverse_norm = 0.;
            for (unsigned int k = 0; k < 3; ++k)
              {
                solver.solve(y, x);
                inverse_norm = y.l2_norm();
                x            = y;
                x /= inverse_norm;
              }
            const double condition =
              system_matrix.frobenius_norm() * inverse_norm;
            worst_condition = std::isfinite(condition) ?
                                std::max(worst_condition, condition) :
                                std::numeric_limits<double>::infinity();
          }
      }
    else
      {
        TrilinosWrappers::PreconditionAMG                 amg;
        TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
        amg_data.elliptic              = true;
        amg_data.higher_order_elements = false;
        amg_data.smoother_sweeps       = 2;
        amg.initialize(system_matrix, amg_data);
        SolverControl                 control(1000,
                              parameters.solver.linear_tolerance *
                                system_rhs.l2_norm());
        TrilinosWrappers::SolverGMRES solver(control);
        solver.solve(system_matrix, system_solution, system_rhs, amg);
      }

    for (unsigned int i = 0; i < locally_owned_dofs.n_elements(); ++i)
      if (system_index[i] != numbers::invalid_dof_index)
        increment.local_element(i) += system_solution[system_index[i]];
    increment.update_ghost_values();
  }



  template <int dim>
  double
  MPMSolver<dim>::max_point_increment() const
  {
    double       largest = 0.;
    unsigned int p       = 0;
    for (auto point = material_points.begin(); point != material_points.end();
         ++point, ++p)
      {
        const PointStep &step = point_steps[p];
        Tensor<1, dim>   displacement;
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            displacement[i] += step.support.weights[v] *
                               increment.local_element(step.dofs[v * dim + i]);
        for (unsigned int d = 0; d < dim; ++d)
          largest =
            std::max(largest, std::abs(displacement[d]) / grid.cell_size[d]);
      }
    return Utilities::MPI::max(largest, communicator);
  }



  template <int dim>
  void
  MPMSolver<dim>::compute_reactions()
  {
    // R = f_int - f_ext on the constrained DoFs: the support's force on the
    // body, per face and component.
    std::fill(reactions.begin(), reactions.end(), 0.);
    for (const auto &[i, column] : reaction_dofs)
      reactions[column] +=
        internal_force.local_element(i) - external_force.local_element(i);
    Utilities::MPI::sum(reactions, communicator, reactions);

    // Global balance: the reactions carry the whole external load.
    std::vector<double> total(dim, 0.);
    for (const auto &[node, dofs] : node_dofs)
      for (unsigned int c = 0; c < dim; ++c)
        if (dofs[c] < locally_owned_dofs.n_elements())
          total[c] += external_force.local_element(dofs[c]);
    Utilities::MPI::sum(total, communicator, total);
    double load = 0., imbalance = 0.;
    for (unsigned int c = 0; c < dim; ++c)
      {
        double sum = total[c];
        for (unsigned int f = 0; f < 2 * dim; ++f)
          sum += reactions[f * dim + c];
        load += total[c] * total[c];
        imbalance += sum * sum;
      }
    if (load > 0. && !reaction_columns.empty())
      max_reaction_imbalance =
        std::max(max_reaction_imbalance, std::sqrt(imbalance / load));
  }



  template <int dim>
  void
  MPMSolver<dim>::update_material_points(const unsigned int load_step)
  {
    TimerOutput::Scope scope(timer, "point update");
    using P                   = PointProperties<dim>;
    const bool update_domains = basis_type == BasisType::gimp &&
                                parameters.material_points.update_domains;

    std::string  left_grid;
    unsigned int p = 0;
    for (auto &point : material_points)
      {
        const PointStep  &step       = point_steps[p++];
        const auto       &s          = step.support;
        ArrayView<double> properties = point.get_properties();

        Point<dim> position = point.get_location();
        for (unsigned int v = 0; v < s.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            position[i] +=
              s.weights[v] * increment.local_element(step.dofs[v * dim + i]);

        const Tensor<2, 3> F =
          PulledBackStress<dim>::embed(step.deformation_increment) *
          read_tensor(properties, P::deformation_gradient);
        write_tensor(F, properties, P::deformation_gradient);
        write_symmetric(step.update.elastic_left_cauchy_green,
                        properties,
                        P::elastic_left_cauchy_green);
        write_symmetric(step.update.kirchhoff_stress,
                        properties,
                        P::kirchhoff_stress);
        if (layout.plastic_multiplier != PointLayout::absent)
          properties[layout.plastic_multiplier] +=
            step.update.plastic_multiplier;

        if (update_domains)
          {
            // lp = lp0 U_ii with U the right stretch tensor of F = R U.
            const SymmetricTensor<2, 3> U =
              symmetrize(transpose(F) * F); // C = U^2
            const auto eigen = eigenvectors(U);
            for (unsigned int d = 0; d < dim; ++d)
              {
                double stretch = 0.;
                for (unsigned int a = 0; a < 3; ++a)
                  stretch += std::sqrt(eigen[a].first) * eigen[a].second[d] *
                             eigen[a].second[d];
                // At most h/2: a domain then spans at most three nodes.
                properties[P::domain_half_length + d] =
                  std::min(properties[P::initial_domain_half_length + d] *
                             stretch,
                           0.5 * grid.cell_size[d]);
              }
          }

        bool finite = true;
        for (unsigned int d = 0; d < dim; ++d)
          finite = finite && std::isfinite(position[d]);
        if ((!finite || !grid.contains(position)) && left_grid.empty())
          {
            Point<dim> initial;
            for (unsigned int d = 0; d < dim; ++d)
              initial[d] = properties[P::initial_position + d];
            std::ostringstream message;
            message << "Load step " << load_step << ": material point "
                    << point.get_id() << " (initially at " << initial
                    << ") moved to (" << position
                    << "), outside the background grid [" << grid.lower
                    << "] - [" << grid.upper << "].";
            left_grid = message.str();
          }
        point.set_location(position);
      }

    const auto messages = Utilities::MPI::all_gather(communicator, left_grid);
    for (const auto &message : messages)
      if (!message.empty())
        throw std::runtime_error(message);

    const auto n_before = material_points.n_global_particles();
    material_points.sort_particles_into_subdomains_and_cells();
    AssertThrow(material_points.n_global_particles() == n_before,
                ExcMessage("Material points were lost while sorting them "
                           "into cells in load step " +
                           std::to_string(load_step) + "."));
  }



  template <int dim>
  double
  MPMSolver<dim>::column_error(const double load_factor) const
  {
    // The paper's eq. 13 with sigma_a = -lambda rho_0 g (l0 - Z).
    using P           = PointProperties<dim>;
    const auto  &body = parameters.bodies[0];
    const double height =
      body.upper_corner[dim - 1] - body.lower_corner[dim - 1];
    const double weight = body.density * std::abs(parameters.gravity[dim - 1]);
    double       local[2] = {0., 0.};
    for (const auto &point : material_points)
      {
        const auto   properties = point.get_properties();
        const double J =
          determinant(read_tensor(properties, P::deformation_gradient));
        const double sigma =
          read_symmetric(properties, P::kirchhoff_stress)[dim - 1][dim - 1] / J;
        const double Z = properties[P::initial_position + dim - 1] -
                         body.lower_corner[dim - 1];
        const double exact = -load_factor * weight * (height - Z);
        local[0] += std::abs(sigma - exact) * properties[P::initial_volume];
        local[1] += properties[P::initial_volume];
      }
    double global[2];
    Utilities::MPI::sum(ArrayView<const double>(local, 2),
                        communicator,
                        ArrayView<double>(global, 2));
    return global[0] / (weight * height * global[1]);
  }



  template <int dim>
  void
  MPMSolver<dim>::write_points(const double       load_factor,
                               const unsigned int load_step)
  {
    TimerOutput::Scope scope(timer, "output");
    using P                   = PointProperties<dim>;
    static const char *axis[] = {"x", "y", "z"};

    // The fields the scene asks for, among those its effects produce.
    const auto &requested = parameters.output.fields;
    const auto  wanted    = [&](const std::string &field) {
      return std::find(requested.begin(), requested.end(), "all") !=
               requested.end() ||
             std::find(requested.begin(), requested.end(), field) !=
               requested.end();
    };
    const bool displacement = wanted("displacement"),
               initial = wanted("initial_position"), stress = wanted("stress"),
               von_mises = wanted("von_mises_stress"),
               plastic   = wanted("plastic_multiplier") &&
                         layout.plastic_multiplier != PointLayout::absent,
               volume = wanted("volume"), rank = wanted("rank"),
               body = wanted("body") && layout.body != PointLayout::absent;

    std::vector<std::string> names;
    std::vector<bool>        is_vector;
    for (unsigned int d = 0; d < dim && displacement; ++d)
      names.push_back("displacement"), is_vector.push_back(true);
    for (unsigned int d = 0; d < dim && initial; ++d)
      names.push_back("initial_position"), is_vector.push_back(true);
    for (unsigned int i = 0; i < 3 && stress; ++i)
      for (unsigned int j = i; j < 3; ++j)
        {
          names.push_back(std::string("stress_") + axis[i] + axis[j]);
          is_vector.push_back(false);
        }
    for (const auto &[name, on] : std::vector<std::pair<std::string, bool>>{
           {"von_mises_stress", von_mises},
           {"plastic_multiplier", plastic},
           {"volume", volume},
           {"rank", rank},
           {"body", body}})
      if (on)
        names.push_back(name), is_vector.push_back(false);

    point_output.begin(material_points.n_locally_owned_particles(),
                       names,
                       is_vector);
    const double this_rank = Utilities::MPI::this_mpi_process(communicator);
    std::vector<double> values(names.size());
    unsigned int        p = 0;
    for (const auto &point : material_points)
      {
        const auto   properties = point.get_properties();
        const double J =
          determinant(read_tensor(properties, P::deformation_gradient));
        const SymmetricTensor<2, 3> sigma =
          read_symmetric(properties, P::kirchhoff_stress) / J;
        unsigned int c = 0;
        for (unsigned int d = 0; d < dim && displacement; ++d)
          values[c++] =
            point.get_location()[d] - properties[P::initial_position + d];
        for (unsigned int d = 0; d < dim && initial; ++d)
          values[c++] = properties[P::initial_position + d];
        for (unsigned int i = 0; i < 3 && stress; ++i)
          for (unsigned int j = i; j < 3; ++j)
            values[c++] = sigma[i][j];
        if (von_mises)
          {
            const SymmetricTensor<2, 3> s = deviator(sigma);
            values[c++]                   = std::sqrt(1.5 * (s * s));
          }
        if (plastic)
          values[c++] = properties[layout.plastic_multiplier];
        if (volume)
          values[c++] = J * properties[P::initial_volume];
        if (rank)
          values[c++] = this_rank;
        if (body)
          values[c++] = properties[layout.body] + 1;
        point_output.set_point(p++, point.get_location(), values);
      }
    point_output.write(load_factor, load_step);
  }



  template <int dim>
  void
  MPMSolver<dim>::measure_final_state()
  {
    using P           = PointProperties<dim>;
    const auto  &body = parameters.bodies[0];
    const double height =
      body.upper_corner[dim - 1] - body.lower_corner[dim - 1];
    const double weight = body.density * std::abs(parameters.gravity[dim - 1]);
    double       mass = 0., tension = -std::numeric_limits<double>::max(),
           deviation = 0.;
    Point<dim> initial_min, initial_max, final_min, final_max;
    for (unsigned int d = 0; d < dim; ++d)
      {
        initial_min[d] = final_min[d] = std::numeric_limits<double>::max();
        initial_max[d] = final_max[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &point : material_points)
      {
        const auto   properties = point.get_properties();
        const double J =
          determinant(read_tensor(properties, P::deformation_gradient));
        const double vertical =
          read_symmetric(properties, P::kirchhoff_stress)[dim - 1][dim - 1] / J;
        mass += properties[P::mass];
        tension = std::max(tension, vertical);
        if (parameters.output.analytical_solution == "column")
          {
            const double Z = properties[P::initial_position + dim - 1] -
                             body.lower_corner[dim - 1];
            deviation = std::max(deviation,
                                 std::abs(vertical + weight * (height - Z)) /
                                   (weight * height));
          }
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double X = properties[P::initial_position + d];
            const double x = point.get_location()[d];
            initial_min[d] = std::min(initial_min[d], X);
            initial_max[d] = std::max(initial_max[d], X);
            final_min[d]   = std::min(final_min[d], x);
            final_max[d]   = std::max(final_max[d], x);
          }
      }
    final_state.total_mass = Utilities::MPI::sum(mass, communicator);
    final_state.max_tensile_vertical_stress =
      Utilities::MPI::max(tension, communicator);
    final_state.max_column_deviation =
      Utilities::MPI::max(deviation, communicator);
    for (unsigned int d = 0; d < dim; ++d)
      {
        final_state.initial_min[d] =
          Utilities::MPI::min(initial_min[d], communicator);
        final_state.initial_max[d] =
          Utilities::MPI::max(initial_max[d], communicator);
        final_state.final_min[d] =
          Utilities::MPI::min(final_min[d], communicator);
        final_state.final_max[d] =
          Utilities::MPI::max(final_max[d], communicator);
      }
  }



  template <int dim>
  void
  MPMSolver<dim>::write_summary(const double wall_time)
  {
    measure_final_state();
    const double max_tensile_stress = final_state.max_tensile_vertical_stress;
    const double total_mass         = final_state.total_mass;
    const auto   times = timer.get_summary_data(TimerOutput::total_wall_time);
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    const double peak_memory_mb =
      Utilities::MPI::max(memory.VmHWM / 1024., communicator);
    const auto phase_time = [&](const std::string &phase) {
      return times.count(phase) ? times.at(phase) : 0.;
    };
    const double point_evaluations =
      double(material_points.n_global_particles()) * residual_evaluations;
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::ostringstream json;
    json << std::setprecision(10);
    json << "{\n"
         << "  \"scene\": \"" << parameters.scene.name << "\",\n"
         << "  \"dimension\": " << dim << ",\n"
         << "  \"processes\": " << Utilities::MPI::n_mpi_processes(communicator)
         << ",\n"
         << "  \"bodies\": [";
    for (unsigned int b = 0; b < parameters.bodies.size(); ++b)
      json << (b ? ", " : "") << '"' << parameters.bodies[b].description()
           << '"';
    json << "],\n"
         << "  \"effects\": [";
    const auto effects = effect_descriptions();
    for (unsigned int e = 0; e < effects.size(); ++e)
      json << (e ? ", " : "") << '"' << effects[e] << '"';
    json << "],\n"
         << "  \"basis\": \"" << parameters.material_points.basis << "\",\n"
         << "  \"material_points\": " << material_points.n_global_particles()
         << ",\n"
         << "  \"grid_dofs\": " << dof_handler.n_dofs() << ",\n"
         << "  \"system_dofs_last_step\": " << n_system_dofs_last << ",\n"
         << "  \"load_steps\": " << parameters.solver.n_load_steps << ",\n"
         << "  \"newton_iterations\": " << total_newton_iterations << ",\n";
    if (last_error >= 0.)
      json << "  \"error_sigma_zz\": " << last_error << ",\n";
    json << "  \"load_steps_taken\": " << accepted_load_steps << ",\n"
         << "  \"load_step_cuts\": " << n_cuts << ",\n"
         << "  \"largest_point_increment_in_cells\": "
         << largest_point_increment << ",\n"
         << "  \"max_reaction_imbalance\": " << max_reaction_imbalance << ",\n"
         << "  \"max_tensile_vertical_stress\": " << max_tensile_stress << ",\n"
         << "  \"total_mass\": " << total_mass << ",\n";
    if (parameters.solver.estimate_condition)
      json << "  \"worst_condition_estimate\": " << worst_condition << ",\n"
           << "  \"smallest_reciprocal_condition_estimate\": "
           << (worst_condition > 0. ? 1. / worst_condition : 0.) << ",\n";
    json << "  \"formulation\": \"" << parameters.solver.formulation << "\",\n"
         << "  \"residual_evaluations\": " << residual_evaluations << ",\n"
         << "  \"microseconds_per_point_evaluation\": "
         << 1e6 * (phase_time("stress update") + phase_time("assembly")) /
              point_evaluations
         << ",\n"
         << "  \"linear_solve_share\": "
         << phase_time("linear solve") / wall_time << ",\n"
         << "  \"peak_memory_mb\": " << peak_memory_mb << ",\n";
    json << "  \"wall_time\": " << wall_time << ",\n"
         << "  \"wall_time_per_phase\": {";
    bool first = true;
    for (const auto &phase : phase_names)
      if (times.count(phase))
        {
          json << (first ? "\n" : ",\n") << "    \"" << phase
               << "\": " << times.at(phase);
          first = false;
        }
    json << "\n  }\n}\n";
    write_file_atomically(parameters.scene.output_directory + "/summary.json",
                          json.str());
  }



  template <int dim>
  void
  MPMSolver<dim>::print_test_summary()
  {
    using P = PointProperties<dim>;
    // The lowest ids of each process, merged on rank 0.
    std::vector<std::pair<types::particle_index, std::vector<double>>> local;
    for (const auto &point : material_points)
      {
        const auto   properties = point.get_properties();
        const double J =
          determinant(read_tensor(properties, P::deformation_gradient));
        std::vector<double> values;
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(properties[P::initial_position + d]);
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(point.get_location()[d] -
                           properties[P::initial_position + d]);
        const SymmetricTensor<2, 3> tau =
          read_symmetric(properties, P::kirchhoff_stress);
        values.push_back(tau[dim - 1][dim - 1] / J);
        values.push_back(tau[0][0] / J);
        local.emplace_back(point.get_id(), values);
      }
    // The points nearest to the probe positions (smallest distance, then
    // smallest id), found among all processes' points.
    std::vector<std::pair<types::particle_index, std::vector<double>>> probed;
    for (const auto &probe : parameters.testing.probes)
      {
        AssertThrow(probe.size() == dim,
                    ExcMessage("Parameter 'Testing/Probes': each position "
                               "needs one coordinate per dimension."));
        std::tuple<double, types::particle_index, std::vector<double>> nearest(
          std::numeric_limits<double>::max(), 0, {});
        for (const auto &[id, values] : local)
          {
            double distance = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              distance += std::pow(values[d] - probe[d], 2);
            nearest = std::min(nearest, std::make_tuple(distance, id, values));
          }
        const auto all  = Utilities::MPI::all_gather(communicator, nearest);
        const auto best = *std::min_element(all.begin(), all.end());
        probed.emplace_back(std::get<1>(best), std::get<2>(best));
      }
    std::sort(local.begin(), local.end());
    if (local.size() > parameters.testing.n_printed_points)
      local.resize(parameters.testing.n_printed_points);
    const auto gathered = Utilities::MPI::gather(communicator, local, 0);
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;

    std::vector<std::pair<types::particle_index, std::vector<double>>> all;
    for (const auto &part : gathered)
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    if (all.size() > parameters.testing.n_printed_points)
      all.resize(parameters.testing.n_printed_points);
    all.insert(all.end(), probed.begin(), probed.end());

    for (const auto &line : test_lines)
      std::cout << line << '\n';
    std::cout << "observed Newton order near the solution >= 1.7 in every "
                 "step: "
              << (min_newton_order >= 1.7 ? "yes" : "NO") << '\n';
    std::cout << "material points: " << material_points.n_global_particles()
              << ", total Newton iterations: " << total_newton_iterations
              << ", load-step cuts: " << n_cuts << '\n';
    char buffer[160];
    std::snprintf(buffer,
                  sizeof(buffer),
                  "total mass: %.8e (initial %.8e)\n",
                  final_state.total_mass,
                  initial_mass);
    std::cout << buffer;
    if (!reaction_columns.empty() && !force_effects.empty())
      std::cout << "reactions balance the load to 1e-8 in every step: "
                << (max_reaction_imbalance < 1e-8 ? "yes" : "NO") << '\n';
    static const char *axis[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      "extent in %s: initial points [%.4f, %.4f], final "
                      "[%.4f, %.4f]\n",
                      axis[d],
                      final_state.initial_min[d],
                      final_state.initial_max[d],
                      final_state.final_min[d],
                      final_state.final_max[d]);
        std::cout << buffer;
      }
    if (parameters.testing.reference_extent.size() == dim)
      {
        double distance = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          distance = std::max(distance,
                              std::abs(final_state.final_max[d] -
                                       parameters.testing.reference_extent[d]));
        std::cout << "final extent within "
                  << parameters.testing.reference_tolerance
                  << " m of the reference: "
                  << (distance <= parameters.testing.reference_tolerance ?
                        "yes" :
                        "NO")
                  << '\n';
      }
    std::snprintf(buffer,
                  sizeof(buffer),
                  "largest vertical stress (tension positive): %.4e\n",
                  final_state.max_tensile_vertical_stress);
    std::cout << buffer;
    if (parameters.output.analytical_solution == "column")
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      "stress oscillation max |sigma_zz - exact| / "
                      "(rho_0 g l0): %.4e\n",
                      final_state.max_column_deviation);
        std::cout << buffer;
      }
    if (parameters.solver.estimate_condition)
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      "worst condition estimate: %.0e\n",
                      worst_condition);
        std::cout << buffer;
      }
    static const char *face_names[] = {"x-", "x+", "y-", "y+", "z-", "z+"};
    for (const unsigned int c : reaction_columns)
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      "final reaction on face %s, component %s: %.6e\n",
                      face_names[c / dim],
                      axis[c % dim],
                      reactions[c]);
        std::cout << buffer;
      }
    const int digits = parameters.testing.significant_digits;
    for (const auto &[id, values] : all)
      {
        std::cout << "point " << id << ": X =";
        for (unsigned int d = 0; d < dim; ++d)
          std::cout << ' ' << std::setprecision(digits) << values[d];
        std::cout << ", u =";
        char buffer[40];
        for (unsigned int d = 0; d < dim; ++d)
          {
            std::snprintf(
              buffer, sizeof(buffer), " %.*e", digits - 1, values[dim + d]);
            std::cout << buffer;
          }
        std::snprintf(
          buffer, sizeof(buffer), "%.*e", digits - 1, values[2 * dim]);
        std::cout << ", sigma_vertical = " << buffer;
        std::snprintf(
          buffer, sizeof(buffer), "%.*e", digits - 1, values[2 * dim + 1]);
        std::cout << ", sigma_xx = " << buffer << '\n';
      }
    std::cout << std::flush;
  }



  template <int dim>
  typename MPMSolver<dim>::NewtonOutcome
  MPMSolver<dim>::solve_load_step(const double         previous_load_factor,
                                  const double         load_factor,
                                  const unsigned int   load_step,
                                  std::vector<double> &residuals)
  {
    const bool is_root = Utilities::MPI::this_mpi_process(communicator) == 0;
    residuals.clear();
    increment = 0.;
    // Prescribed faces move by their share of this step (ghosts included).
    for (const auto &[dof, displacement] : prescribed_dofs)
      increment.local_element(dof) =
        (load_factor - previous_load_factor) * displacement;
    assemble_external_force(load_factor);
    for (unsigned int iteration = 0;; ++iteration)
      {
        if (!update_stresses())
          return NewtonOutcome::inverted_point;
        assemble_residual();
        const double reference =
          external_force_norm > 0. ?
            external_force_norm :
            (reference_force_norm > 0. ? reference_force_norm : 1.);
        residuals.push_back(residual_norm / reference);
        if (is_root)
          newton_file << load_step << ',' << iteration << ','
                      << std::setprecision(6) << residuals.back() << '\n';
        if (!std::isfinite(residuals.back()))
          return NewtonOutcome::not_finite;
        if (residuals.back() < parameters.solver.tolerance)
          return NewtonOutcome::converged;
        if (residuals.back() >
            parameters.solver.divergence_factor * residuals.front())
          return NewtonOutcome::diverged;
        if (iteration == parameters.solver.max_iterations)
          return NewtonOutcome::iteration_limit;
        assemble_matrix();
        solve_linear_system(parameters.solver.estimate_condition &&
                            iteration == 0);
      }
  }



  template <int dim>
  std::vector<std::string>
  MPMSolver<dim>::effect_descriptions() const
  {
    static const char       *faces[] = {"x-", "x+", "y-", "y+", "z-", "z+"};
    std::vector<std::string> list;
    for (const auto &effect : force_effects)
      list.push_back(effect->description());
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (parameters.grid.face_conditions[f] != "none")
        {
          std::ostringstream text;
          text << "grid face " << faces[f] << ": "
               << parameters.grid.face_conditions[f];
          if (parameters.grid.face_conditions[f].rfind("prescribed", 0) == 0)
            text << " (" << parameters.grid.face_displacements[f] << ") m";
          if (parameters.grid.face_has_region[f])
            text << " in [" << parameters.grid.face_regions[f].first << "] - ["
                 << parameters.grid.face_regions[f].second << "]";
          list.push_back(text.str());
        }
    if (parameters.stabilisation.enabled)
      list.push_back("ghost stabilisation: penalty scale " +
                     std::to_string(parameters.stabilisation.penalty_scale) +
                     ", fill threshold " +
                     std::to_string(parameters.stabilisation.fill_threshold));
    if (basis_type == BasisType::gimp &&
        parameters.material_points.update_domains)
      list.push_back("GIMP domain update with the stretch");
    return list;
  }



  template <int dim>
  void
  MPMSolver<dim>::run()
  {
    Timer wall_timer(communicator);
    wall_timer.start();
    const auto &output_directory = parameters.scene.output_directory;
    const bool  is_root = Utilities::MPI::this_mpi_process(communicator) == 0;
    if (is_root)
      std::filesystem::create_directories(output_directory);
    MPI_Barrier(communicator);

    make_grid();
    setup_dofs();
    create_material_points();
    if (!force_effects.empty())
      {
        const auto infos = point_infos();
        for (const auto &effect : force_effects)
          effect->initialize(infos, parameters.bodies, grid, communicator);
      }

    pcout << "Scene '" << parameters.scene.name << "' (" << dim << "D) on "
          << Utilities::MPI::n_mpi_processes(communicator) << " process(es)\n"
          << "  grid: " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " DoFs\n"
          << "  material points: " << material_points.n_global_particles()
          << " (" << parameters.material_points.basis << ")\n"
          << "  bodies:\n";
    for (const auto &body : parameters.bodies)
      pcout << "    " << body.description() << '\n';
    pcout << "  effects:\n";
    for (const auto &effect : effect_descriptions())
      pcout << "    " << effect << '\n';
    pcout << std::flush;

    static const char *face_names[] = {
      "xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
    static const char *axis_names[] = {"x", "y", "z"};
    const bool column = parameters.output.analytical_solution == "column";
    if (is_root)
      {
        steps_file.open(output_directory + "/steps.csv");
        newton_file.open(output_directory + "/newton.csv");
        steps_file << "step,load_factor,load_increment,converged,"
                      "newton_iterations,relative_residual,system_dofs";
        if (column)
          steps_file << ",error_sigma_zz";
        for (const unsigned int c : reaction_columns)
          steps_file << ",reaction_" << face_names[c / dim] << '_'
                     << axis_names[c % dim];
        for (const auto &phase : phase_names)
          {
            std::string column_name = phase;
            std::replace(column_name.begin(), column_name.end(), ' ', '_');
            steps_file << ",time_" << column_name;
          }
        steps_file << '\n';
        newton_file << "step,iteration,relative_residual\n";
      }
    if (parameters.output.interval > 0)
      write_points(0., 0);

    static const char            *outcome_names[] = {"converged",
                                                     "iteration limit",
                                                     "diverged",
                                                     "non-finite residual",
                                                     "inverted point",
                                                     "point increment too large"};
    std::map<std::string, double> previous_times;
    const double        nominal_step = 1. / parameters.solver.n_load_steps;
    double              step_size    = nominal_step;
    double              load_factor  = 0.;
    unsigned int        load_step    = 0;
    bool                new_state    = true;
    std::vector<double> residuals;
    std::ostringstream  failures;
    while (load_factor < 1.)
      {
        // The last step lands exactly on the full load.
        const double start = load_factor;
        const double target =
          (load_factor + step_size > 1. - 1e-12) ? 1. : load_factor + step_size;
        if (new_state)
          {
            evaluate_basis();
            number_system_dofs();
            new_state = false;
          }
        NewtonOutcome outcome =
          solve_load_step(start, target, load_step + 1, residuals);
        // A converged step that moves a point by more than the allowed
        // fraction of a cell is cut too: the basis of the step is that of
        // its start, and the load path is followed more closely.
        double point_increment = 0.;
        if (outcome == NewtonOutcome::converged)
          {
            point_increment = max_point_increment();
            if (parameters.solver.step_control &&
                point_increment > parameters.solver.maximum_point_increment)
              outcome = NewtonOutcome::increment_too_large;
          }
        const unsigned int iterations = residuals.size() - 1;
        total_newton_iterations += iterations;
        residual_evaluations += residuals.size();
        const bool converged = outcome == NewtonOutcome::converged;

        std::ostringstream line;
        line << "step " << std::setw(3) << load_step + 1 << "  load "
             << std::fixed << std::setprecision(4) << target;
        largest_point_increment =
          std::max(largest_point_increment,
                   outcome == NewtonOutcome::converged ? point_increment : 0.);
        if (converged)
          {
            compute_reactions();
            // Observed order of the last contraction above round-off: about
            // 2 for full Newton near the solution.
            for (unsigned int k = 1; k + 1 < residuals.size(); ++k)
              if (residuals[k] < 1e-3 && residuals[k + 1] > 1e-10)
                min_newton_order =
                  std::min(min_newton_order,
                           std::log(residuals[k + 1]) / std::log(residuals[k]));
            ++load_step;
            accepted_load_steps = load_step;
            update_material_points(load_step);
            new_state   = true;
            load_factor = target;
            if (column)
              last_error = column_error(load_factor);
            if (parameters.output.interval > 0 &&
                (load_step % parameters.output.interval == 0 ||
                 load_factor == 1.))
              write_points(load_factor, load_step);
            line << "  iterations " << iterations;
            if (column)
              {
                char buffer[32];
                std::snprintf(buffer, sizeof(buffer), "%.4e", last_error);
                line << "  error " << buffer;
              }
          }
        else
          {
            ++n_cuts;
            failures << "\n  load " << target << " (increment "
                     << target - load_factor
                     << "): " << outcome_names[static_cast<int>(outcome)]
                     << ", relative residuals:";
            for (const double r : residuals)
              failures << ' ' << r;
            line << "  " << outcome_names[static_cast<int>(outcome)]
                 << " after " << iterations << " iterations: step cut";
          }
        test_lines.push_back(line.str());
        pcout << line.str() << "  residual " << std::scientific
              << std::setprecision(2) << residuals.back() << std::endl;

        const auto times = timer.get_summary_data(TimerOutput::total_wall_time);
        if (is_root)
          {
            steps_file << load_step + (converged ? 0 : 1) << ','
                       << std::setprecision(10) << target << ','
                       << target - start << ',' << (converged ? 1 : 0) << ','
                       << iterations << ',' << residuals.back() << ','
                       << n_system_dofs_last;
            // A cut attempt has no error or reactions: empty fields.
            if (column)
              {
                steps_file << ',';
                if (converged)
                  steps_file << last_error;
              }
            for (const unsigned int c : reaction_columns)
              {
                steps_file << ',';
                if (converged)
                  steps_file << reactions[c];
              }
            for (const auto &phase : phase_names)
              {
                const double now = times.count(phase) ? times.at(phase) : 0.;
                steps_file << ',' << now - previous_times[phase];
                previous_times[phase] = now;
              }
            steps_file << std::endl;
            newton_file.flush();
          }

        if (converged)
          {
            if (parameters.solver.step_control &&
                iterations <= parameters.solver.easy_iterations)
              step_size = std::min(2. * step_size, nominal_step);
          }
        else
          {
            std::ostringstream message;
            message << "Load step " << load_step + 1 << " (from load factor "
                    << load_factor << " to " << target << "): Newton "
                    << outcome_names[static_cast<int>(outcome)] << '.';
            if (!parameters.solver.step_control)
              throw std::runtime_error(message.str() +
                                       " Relative residuals:" + failures.str());
            step_size /= 2.;
            if (step_size < parameters.solver.minimum_step)
              throw std::runtime_error(
                message.str() +
                " The load increment would fall below 'Solver/Minimum load "
                "step' = " +
                std::to_string(parameters.solver.minimum_step) +
                ". Attempts:" + failures.str());
          }
      }

    wall_timer.stop();
    write_summary(wall_timer.wall_time());
    if (parameters.testing.enabled)
      print_test_summary();
    else
      timer.print_summary();
  }



  template <int dim>
  void
  run_scene(ParameterHandler &prm, const MPI_Comm communicator)
  {
    Parameters::All<dim> parameters;
    parameters.parse_parameters(prm);
    MPMSolver<dim> solver(parameters,
                          EffectRegistry::create_enabled<dim>(prm),
                          communicator);
    solver.run();
  }



  template class MPMSolver<2>;
  template class MPMSolver<3>;
  template void
  run_scene<2>(ParameterHandler &, const MPI_Comm);
  template void
  run_scene<3>(ParameterHandler &, const MPI_Comm);
} // namespace impm
