#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_generator.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/grid/background_grid.h>

#include <algorithm>
#include <sstream>

namespace impm
{
  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid(const Parameters::Grid<dim> &parameters,
                                      const MPI_Comm               communicator,
                                      const std::string &checkpoint_file)
    : parameters(parameters)
    , communicator(communicator)
    , triangulation(communicator)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
  {
    make_triangulation(checkpoint_file);
    distribute_dofs();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::save(const std::string           &file_name,
                            const std::function<void()> &prepare)
  {
    prepare();
    triangulation.save(file_name);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::distribute_dofs()
  {
    dof_handler.distribute_dofs(fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
    partitioner = std::make_shared<Utilities::MPI::Partitioner>(owned_dofs,
                                                                relevant_dofs,
                                                                communicator);
    apply_face_conditions();
    map_nodes_to_dofs();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::connect_cell_weight(const CellWeight &weight)
  {
    triangulation.signals.weight.connect(weight);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::partition_by(const CellWeight &weight)
  {
    auto connection = triangulation.signals.weight.connect(weight);
    triangulation.repartition();
    connection.disconnect();
    distribute_dofs();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::repartition(const std::function<void()> &prepare,
                                   const std::function<void()> &unpack)
  {
    prepare();
    triangulation.repartition();
    unpack();
    distribute_dofs();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_triangulation(const std::string &checkpoint_file)
  {
    const auto &p = parameters;
    grid.initialize(p.lower_corner, p.upper_corner, p.n_cells);
    grid.axisymmetric = p.axisymmetric;

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
    if (checkpoint_file.empty())
      triangulation.refine_global(refinements);
    else
      {
        // The same coarse mesh, refined as saved.
        triangulation.load(checkpoint_file);
        types::global_cell_index n_cells = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n_cells *= p.n_cells[d];
        if (triangulation.n_global_active_cells() != n_cells)
          throw InputError(
            "--resume: the checkpoint's grid has " +
            std::to_string(triangulation.n_global_active_cells()) +
            " cells, the scene's 'Grid' " + std::to_string(n_cells) +
            ": resume with the scene that wrote it.");
      }
  }



  template <int dim>
  unsigned int
  BackgroundGrid<dim>::n_local_dofs() const
  {
    return partitioner->locally_owned_size() + partitioner->n_ghost_indices();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::reinit_vector(NodalVector &vector) const
  {
    vector.reinit(partitioner);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::apply_face_conditions()
  {
    using Parameters::FaceCondition;
    // Every constrained DoF is kept out of the linear system; prescribed
    // ones get their share of the displacement in each load step. A DoF on
    // two constrained faces follows the first of them, and its reaction
    // counts there.
    constraints.clear();
    constraints.reinit(relevant_dofs);
    prescribed_dofs.clear();
    prescribed_dof_faces.clear();
    reaction_dofs.clear();
    columns_with_reactions.clear();
    for (unsigned int face = 0; face < 2 * dim; ++face)
      for (unsigned int c = 0; c < dim; ++c)
        if (Parameters::constrains(parameters.face_conditions[face], face, c))
          columns_with_reactions.push_back(face * dim + c);

    const double tolerance = 1e-10;
    const auto   in_region = [&](const unsigned int face, const Point<dim> &x) {
      if (!parameters.face_has_region[face])
        return true;
      const auto &[lower, upper] = parameters.face_regions[face];
      for (unsigned int d = 0; d < dim; ++d)
        if (x[d] < lower[d] - tolerance * grid.cell_size[d] ||
            x[d] > upper[d] + tolerance * grid.cell_size[d])
          return false;
      return true;
    };

    std::vector<bool> assigned(n_local_dofs(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f))
              continue;
            const unsigned int  face      = cell->face(f)->boundary_id();
            const FaceCondition condition = parameters.face_conditions[face];
            if (condition == FaceCondition::none)
              continue;
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                if (!in_region(face, cell->face(f)->vertex(v)))
                  continue;
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    if (!Parameters::constrains(condition, face, c))
                      continue;
                    const types::global_dof_index dof =
                      cell->face(f)->vertex_dof_index(v, c);
                    const unsigned int local =
                      partitioner->global_to_local(dof);
                    if (assigned[local])
                      continue;
                    assigned[local] = true;
                    constraints.add_line(dof);
                    if (Parameters::is_prescribed(condition) &&
                        parameters.face_displacements[face][c] != 0.)
                      {
                        prescribed_dofs.emplace_back(
                          local, parameters.face_displacements[face][c]);
                        prescribed_dof_faces.push_back(face);
                      }
                    if (local < n_locally_owned_dofs())
                      reaction_dofs.emplace_back(local, face * dim + c);
                  }
              }
          }
    constraints.close();
    any_prescribed_dof =
      Utilities::MPI::logical_or(!prescribed_dofs.empty(),
                                 dof_handler.get_communicator());
  }



  template <int dim>
  void
  BackgroundGrid<dim>::map_nodes_to_dofs()
  {
    dofs_of_node.clear();
    component_of_local_dof.assign(n_local_dofs(), 0);
    position_of_local_dof.resize(n_local_dofs());
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
              const unsigned int local =
                partitioner->global_to_local(cell_dofs[i]);
              dofs_of_node[node][component] = local;
              component_of_local_dof[local] = component;
              position_of_local_dof[local]  = cell->vertex(vertex);
            }
        }
  }



  template <int dim>
  void
  BackgroundGrid<dim>::apply_prescribed_increment(const double load_increment,
                                                  NodalVector &increment) const
  {
    for (const auto &[dof, displacement] : prescribed_dofs)
      increment.local_element(dof) = load_increment * displacement;
  }



  template <int dim>
  std::vector<double>
  BackgroundGrid<dim>::local_prescribed_increment(
    const double load_increment) const
  {
    std::vector<double> increment(partitioner->locally_owned_size() +
                                    partitioner->n_ghost_indices(),
                                  0.);
    for (const auto &[dof, displacement] : prescribed_dofs)
      increment[dof] = load_increment * displacement;
    return increment;
  }



  template <int dim>
  std::vector<unsigned int>
  BackgroundGrid<dim>::prescribed_faces_without_material(
    const std::vector<bool> &touched) const
  {
    std::vector<unsigned int> faces;
    if (!any_prescribed_dof)
      return faces;
    // Per face: 1 where it has prescribed DoFs here, 2 where one of them
    // is touched; the largest over the processes.
    std::vector<unsigned int> state(2 * dim, 0);
    for (unsigned int i = 0; i < prescribed_dofs.size(); ++i)
      {
        unsigned int &face = state[prescribed_dof_faces[i]];
        face = std::max(face, touched[prescribed_dofs[i].first] ? 2u : 1u);
      }
    Utilities::MPI::max(state, dof_handler.get_communicator(), state);
    for (unsigned int face = 0; face < 2 * dim; ++face)
      if (state[face] == 1)
        faces.push_back(face);
    return faces;
  }



  template <int dim>
  typename BackgroundGrid<dim>::Reactions
  BackgroundGrid<dim>::compute_reactions(
    const NodalVector    &internal_force,
    const NodalVector    &external_force,
    const Tensor<1, dim> &rigid_body_force) const
  {
    Reactions reactions;
    reactions.by_column.assign(2 * dim * dim, 0.);
    for (const auto &[i, column] : reaction_dofs)
      reactions.by_column[column] +=
        internal_force.local_element(i) - external_force.local_element(i);
    Utilities::MPI::sum(reactions.by_column, communicator, reactions.by_column);

    // Global balance: the reactions carry the whole external load. In
    // axisymmetry only along the axis: the nodal forces' radial sum holds
    // the hoop forces, which a ring balances within itself.
    std::vector<double> total(dim, 0.);
    for (const auto &[node, dofs] : dofs_of_node)
      for (unsigned int c = 0; c < dim; ++c)
        if (dofs[c] < n_locally_owned_dofs())
          total[c] += external_force.local_element(dofs[c]);
    Utilities::MPI::sum(total, communicator, total);
    double load = 0., imbalance = 0.;
    for (unsigned int c = grid.axisymmetric ? 1 : 0; c < dim; ++c)
      {
        double sum = total[c] - rigid_body_force[c];
        for (unsigned int f = 0; f < 2 * dim; ++f)
          sum += reactions.by_column[f * dim + c];
        load += total[c] * total[c];
        imbalance += sum * sum;
      }
    if (load > 0. &&
        (!columns_with_reactions.empty() || rigid_body_force.norm() > 0.))
      reactions.imbalance = std::sqrt(imbalance / load);
    return reactions;
  }



  template <int dim>
  std::vector<std::string>
  BackgroundGrid<dim>::face_descriptions() const
  {
    std::vector<std::string> list;
    for (unsigned int f = 0; f < 2 * dim; ++f)
      {
        const auto condition = parameters.face_conditions[f];
        if (condition == Parameters::FaceCondition::none)
          continue;
        std::ostringstream text;
        text << "grid face " << Names::face(f) << ": "
             << Parameters::face_condition_names[static_cast<int>(condition)];
        if (Parameters::is_prescribed(condition))
          text << " (" << parameters.face_displacements[f] << ") m";
        if (parameters.face_has_region[f])
          text << " in [" << parameters.face_regions[f].first << "] - ["
               << parameters.face_regions[f].second << "]";
        list.push_back(text.str());
      }
    return list;
  }



  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace impm
