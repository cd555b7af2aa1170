#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <deal.II/numerics/vector_tools.h>

#include <impm/core/mpm_solver.h>
#include <impm/core/run.h>
#include <impm/mechanics/pulled_back_stress.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

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
  MPMSolver<dim>::MPMSolver(const Parameters::All<dim> &parameters,
                            std::unique_ptr<Material>   material_model,
                            const MPI_Comm              communicator)
    : parameters(parameters)
    , material(std::move(material_model))
    , communicator(communicator)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(communicator) == 0 &&
              !parameters.testing.enabled)
    , timer(communicator, pcout, TimerOutput::never, TimerOutput::wall_times)
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

    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    for (unsigned int face = 0; face < 2 * dim; ++face)
      {
        const std::string &condition = parameters.grid.face_conditions[face];
        if (condition == "none")
          continue;
        std::vector<bool> mask(dim, condition == "fixed");
        mask[face / 2] = true;
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 face,
                                                 Functions::ZeroFunction<dim>(
                                                   dim),
                                                 constraints,
                                                 ComponentMask(mask));
      }
    constraints.close();

    increment.reinit(locally_owned_dofs, locally_relevant_dofs, communicator);
    internal_force.reinit(increment);
    external_force.reinit(increment);

    // Map each grid node to the local indices of its DoFs.
    node_dofs.clear();
    const auto &partitioner = *increment.get_partitioner();
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
    using P = PointProperties<dim>;
    material_points.initialize(triangulation, mapping, P::n_properties);

    const auto        &body       = parameters.body;
    const unsigned int n          = body.points_per_direction;
    unsigned int       n_per_cell = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_per_cell *= n;

    double cell_volume = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      cell_volume *= grid.cell_size[d];
    const double volume = cell_volume / n_per_cell;

    std::vector<double> properties(P::n_properties, 0.);
    for (unsigned int i = 0; i < 3; ++i)
      {
        properties[P::deformation_gradient + 4 * i]  = 1.;
        properties[P::elastic_left_cauchy_green + i] = 1.;
      }
    properties[P::initial_volume] = volume;
    properties[P::mass]           = body.density * volume;
    for (unsigned int d = 0; d < dim; ++d)
      {
        properties[P::domain_half_length + d] = grid.cell_size[d] / (2. * n);
        properties[P::initial_domain_half_length + d] =
          grid.cell_size[d] / (2. * n);
      }

    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Structured index of the cell gives ids independent of the
          // partition.
          std::uint64_t cell_index = 0;
          Point<dim>    cell_lower;
          for (int d = dim - 1; d >= 0; --d)
            {
              const unsigned int i = static_cast<unsigned int>(std::floor(
                (cell->center()[d] - grid.lower[d]) / grid.cell_size[d]));
              cell_index           = cell_index * grid.n_cells[d] + i;
              cell_lower[d]        = grid.node_coordinate(d, i);
            }
          for (unsigned int q = 0; q < n_per_cell; ++q)
            {
              Point<dim>   position, reference;
              unsigned int rest   = q;
              bool         inside = true;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  reference[d] = (rest % n + 0.5) / n;
                  rest /= n;
                  position[d] =
                    cell_lower[d] + reference[d] * grid.cell_size[d];
                  inside = inside && position[d] > body.lower_corner[d] &&
                           position[d] < body.upper_corner[d];
                }
              if (!inside)
                continue;
              for (unsigned int d = 0; d < dim; ++d)
                properties[P::initial_position + d] = position[d];
              material_points.insert_particle(position,
                                              reference,
                                              cell_index * n_per_cell + q,
                                              cell,
                                              ArrayView<const double>(
                                                properties));
            }
        }
    material_points.update_cached_numbers();
    AssertThrow(material_points.n_global_particles() > 0,
                ExcMessage("The body (subsection 'Body') contains no "
                           "material points: no point position of the grid's "
                           "cells lies inside its box."));
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

    // Owned DoFs in the system: touched and not constrained, numbered
    // contiguously per process.
    const unsigned int      n_owned = locally_owned_dofs.n_elements();
    std::vector<bool>       in_system(n_owned);
    types::global_dof_index n_local_system = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        in_system[i] =
          marker.local_element(i) > 0. &&
          !constraints.is_constrained(locally_owned_dofs.nth_index_in_set(i));
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
    std::vector<types::global_dof_index> rows;
    for (const PointStep &step : point_steps)
      for (unsigned int k = 0; k < step.support.n_nodes * dim; ++k)
        if (system_index[step.dofs[k]] != numbers::invalid_dof_index)
          rows.push_back(system_index[step.dofs[k]]);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    system_relevant.add_indices(rows.begin(), rows.end());
    system_relevant.compress();

    // The sparsity pattern comes from the points' supports.
    DynamicSparsityPattern               dsp(system_relevant);
    std::vector<types::global_dof_index> indices;
    for (const PointStep &step : point_steps)
      {
        indices.clear();
        for (unsigned int k = 0; k < step.support.n_nodes * dim; ++k)
          if (system_index[step.dofs[k]] != numbers::invalid_dof_index)
            indices.push_back(system_index[step.dofs[k]]);
        std::sort(indices.begin(), indices.end());
        for (const auto row : indices)
          dsp.add_entries(row, indices.begin(), indices.end(), true);
      }
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
  MPMSolver<dim>::update_stresses()
  {
    TimerOutput::Scope scope(timer, "stress update");
    using P        = PointProperties<dim>;
    unsigned int p = 0;
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
        step.deformation_increment         = dF;
        step.deformation_increment_inverse = invert(dF);
        const auto properties              = point.get_properties();
        material->update(PulledBackStress<dim>::embed(dF),
                         read_symmetric(properties,
                                        P::elastic_left_cauchy_green),
                         step.update);
      }
  }



  template <int dim>
  void
  MPMSolver<dim>::assemble_external_force(const double load_factor)
  {
    TimerOutput::Scope scope(timer, "assembly");
    using P        = PointProperties<dim>;
    external_force = 0.;
    if (parameters.gravity.enabled)
      {
        const Tensor<1, dim> g = load_factor * parameters.gravity.acceleration;
        unsigned int         p = 0;
        for (const auto &point : material_points)
          {
            const PointStep &step = point_steps[p++];
            const double     mass = point.get_properties()[P::mass];
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                external_force.local_element(step.dofs[v * dim + i]) +=
                  step.support.weights[v] * mass * g[i];
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
    using P        = PointProperties<dim>;
    internal_force = 0.;
    unsigned int p = 0;
    for (const auto &point : material_points)
      {
        const PointStep &step       = point_steps[p++];
        const auto       properties = point.get_properties();
        const double     Jn =
          determinant(read_tensor(properties, P::deformation_gradient));
        // f_int = sum_p P~ grad S V^n, V^n = J_n V^0.
        const Tensor<2, dim> stress =
          PulledBackStress<dim>::stress(step.update.kirchhoff_stress,
                                        step.deformation_increment_inverse,
                                        Jn) *
          (Jn * properties[P::initial_volume]);
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          {
            const Tensor<1, dim> force = stress * step.support.gradients[v];
            for (unsigned int i = 0; i < dim; ++i)
              internal_force.local_element(step.dofs[v * dim + i]) += force[i];
          }
      }
    internal_force.compress(VectorOperation::add);

    for (unsigned int i = 0; i < locally_owned_dofs.n_elements(); ++i)
      if (system_index[i] != numbers::invalid_dof_index)
        system_rhs[system_index[i]] =
          external_force.local_element(i) - internal_force.local_element(i);
    system_rhs.compress(VectorOperation::insert);
    residual_norm = system_rhs.l2_norm();
  }



  template <int dim>
  void
  MPMSolver<dim>::assemble_matrix()
  {
    TimerOutput::Scope scope(timer, "assembly");
    using P                         = PointProperties<dim>;
    system_matrix                   = 0.;
    constexpr unsigned int max_dofs = PointSupport<dim>::max_nodes * dim;
    std::array<types::global_dof_index, max_dofs> rows;
    std::array<unsigned int, max_dofs>            local;
    std::array<double, max_dofs>                  values;
    Tensor<4, 3>                                  C;
    unsigned int                                  p = 0;
    for (const auto &point : material_points)
      {
        const PointStep &step       = point_steps[p++];
        const auto      &s          = step.support;
        const auto       properties = point.get_properties();
        const double     Jn =
          determinant(read_tensor(properties, P::deformation_gradient));
        material->tangent(step.update, dim, C);
        const Tensor<4, dim> A =
          PulledBackStress<dim>::tangent(C,
                                         step.update.kirchhoff_stress,
                                         step.deformation_increment_inverse,
                                         Jn);
        const double volume = Jn * properties[P::initial_volume];

        unsigned int n = 0;
        for (unsigned int k = 0; k < s.n_nodes * dim; ++k)
          if (system_index[step.dofs[k]] != numbers::invalid_dof_index)
            {
              rows[n]    = system_index[step.dofs[k]];
              local[n++] = k;
            }
        // B[v][i][k][q] = grad_v[j] A[i][j][k][q] V, then K = B grad_w[q].
        for (unsigned int a = 0; a < n; ++a)
          {
            const unsigned int v = local[a] / dim, i = local[a] % dim;
            Tensor<2, dim>     B;
            for (unsigned int j = 0; j < dim; ++j)
              B += s.gradients[v][j] * A[i][j];
            B *= volume;
            for (unsigned int b = 0; b < n; ++b)
              {
                const unsigned int w = local[b] / dim, k = local[b] % dim;
                values[b] = B[k] * s.gradients[w];
              }
            system_matrix.add(rows[a], n, rows.data(), values.data());
          }
      }
    system_matrix.compress(VectorOperation::add);
  }



  template <int dim>
  void
  MPMSolver<dim>::solve_linear_system()
  {
    TimerOutput::Scope scope(timer, "linear solve");
    system_solution = 0.;
    if (parameters.solver.linear_solver == "direct")
      {
        SolverControl                                  control(1, 0);
        TrilinosWrappers::SolverDirect::AdditionalData data(false,
                                                            "Amesos_Klu");
        TrilinosWrappers::SolverDirect                 solver(control, data);
        solver.solve(system_matrix, system_solution, system_rhs);
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
        properties[P::plastic_multiplier] += step.update.plastic_multiplier;

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
      AssertThrow(message.empty(), ExcMessage(message));

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
    const auto  &body = parameters.body;
    const double height =
      body.upper_corner[dim - 1] - body.lower_corner[dim - 1];
    const double weight =
      body.density * std::abs(parameters.gravity.acceleration[dim - 1]);
    double local[2] = {0., 0.};
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

    std::vector<std::string> names;
    std::vector<bool>        is_vector;
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("displacement"), is_vector.push_back(true);
    for (unsigned int d = 0; d < dim; ++d)
      names.push_back("initial_position"), is_vector.push_back(true);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        {
          names.push_back(std::string("stress_") + axis[i] + axis[j]);
          is_vector.push_back(false);
        }
    for (const char *name :
         {"von_mises_stress", "plastic_multiplier", "volume", "rank"})
      names.push_back(name), is_vector.push_back(false);

    point_output.begin(material_points.n_locally_owned_particles(),
                       names,
                       is_vector);
    const double        rank = Utilities::MPI::this_mpi_process(communicator);
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
        for (unsigned int d = 0; d < dim; ++d)
          values[c++] =
            point.get_location()[d] - properties[P::initial_position + d];
        for (unsigned int d = 0; d < dim; ++d)
          values[c++] = properties[P::initial_position + d];
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            values[c++] = sigma[i][j];
        const SymmetricTensor<2, 3> s = deviator(sigma);
        values[c++]                   = std::sqrt(1.5 * (s * s));
        values[c++]                   = properties[P::plastic_multiplier];
        values[c++]                   = J * properties[P::initial_volume];
        values[c++]                   = rank;
        point_output.set_point(p++, point.get_location(), values);
      }
    point_output.write(load_factor, load_step);
    ++n_output_steps;
  }



  template <int dim>
  void
  MPMSolver<dim>::write_summary(const double wall_time)
  {
    const auto times = timer.get_summary_data(TimerOutput::total_wall_time);
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::ostringstream json;
    json << std::setprecision(10);
    json << "{\n"
         << "  \"scene\": \"" << parameters.scene.name << "\",\n"
         << "  \"dimension\": " << dim << ",\n"
         << "  \"processes\": " << Utilities::MPI::n_mpi_processes(communicator)
         << ",\n"
         << "  \"material\": \"" << material->description() << "\",\n"
         << "  \"basis\": \"" << parameters.material_points.basis << "\",\n"
         << "  \"material_points\": " << material_points.n_global_particles()
         << ",\n"
         << "  \"grid_dofs\": " << dof_handler.n_dofs() << ",\n"
         << "  \"system_dofs_last_step\": " << n_system_dofs_last << ",\n"
         << "  \"load_steps\": " << parameters.solver.n_load_steps << ",\n"
         << "  \"newton_iterations\": " << total_newton_iterations << ",\n";
    if (last_error >= 0.)
      json << "  \"error_sigma_zz\": " << last_error << ",\n";
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
        values.push_back(
          read_symmetric(properties, P::kirchhoff_stress)[dim - 1][dim - 1] /
          J);
        local.emplace_back(point.get_id(), values);
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

    for (const auto &line : test_lines)
      std::cout << line << '\n';
    std::cout << "observed Newton order near the solution >= 1.7 in every "
                 "step: "
              << (min_newton_order >= 1.7 ? "yes" : "NO") << '\n';
    std::cout << "material points: " << material_points.n_global_particles()
              << ", total Newton iterations: " << total_newton_iterations
              << '\n';
    for (const auto &[id, values] : all)
      {
        std::cout << "point " << id << ": X =";
        for (unsigned int d = 0; d < dim; ++d)
          std::cout << ' ' << std::setprecision(6) << values[d];
        std::cout << ", u =";
        char buffer[32];
        for (unsigned int d = 0; d < dim; ++d)
          {
            std::snprintf(buffer, sizeof(buffer), " %.5e", values[dim + d]);
            std::cout << buffer;
          }
        std::snprintf(buffer, sizeof(buffer), "%.5e", values[2 * dim]);
        std::cout << ", sigma_vertical = " << buffer << '\n';
      }
    std::cout << std::flush;
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

    pcout << "Scene '" << parameters.scene.name << "' (" << dim << "D) on "
          << Utilities::MPI::n_mpi_processes(communicator) << " process(es)\n"
          << "  grid: " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " DoFs\n"
          << "  material points: " << material_points.n_global_particles()
          << " (" << parameters.material_points.basis << ")\n"
          << "  material: " << material->description() << '\n'
          << "  effects: " << (parameters.gravity.enabled ? "gravity, " : "")
          << "grid-face constraints" << std::endl;

    const bool column = parameters.output.analytical_solution == "column";
    if (is_root)
      {
        steps_file.open(output_directory + "/steps.csv");
        newton_file.open(output_directory + "/newton.csv");
        steps_file << "step,load_factor,newton_iterations,relative_residual,"
                      "system_dofs";
        if (column)
          steps_file << ",error_sigma_zz";
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

    std::map<std::string, double> previous_times;
    const unsigned int            n_steps = parameters.solver.n_load_steps;
    for (unsigned int load_step = 1; load_step <= n_steps; ++load_step)
      {
        const double load_factor = static_cast<double>(load_step) / n_steps;
        evaluate_basis();
        number_system_dofs();
        increment = 0.;
        assemble_external_force(load_factor);

        std::vector<double> residuals;
        unsigned int        iteration = 0;
        for (;; ++iteration)
          {
            update_stresses();
            assemble_residual();
            const double reference =
              external_force_norm > 0. ? external_force_norm : 1.;
            residuals.push_back(residual_norm / reference);
            if (is_root)
              newton_file << load_step << ',' << iteration << ','
                          << std::setprecision(6) << residuals.back() << '\n';
            if (!std::isfinite(residuals.back()) ||
                iteration == parameters.solver.max_iterations)
              {
                std::ostringstream message;
                message << "Load step " << load_step << " (load factor "
                        << load_factor << "): Newton "
                        << (std::isfinite(residuals.back()) ?
                              "did not converge within " +
                                std::to_string(iteration) + " iterations" :
                              std::string("diverged (non-finite residual)"))
                        << ". Relative residuals:";
                for (const double r : residuals)
                  message << ' ' << r;
                if (is_root)
                  newton_file.flush();
                AssertThrow(false, ExcMessage(message.str()));
              }
            if (residuals.back() < parameters.solver.tolerance)
              break;
            assemble_matrix();
            solve_linear_system();
          }
        total_newton_iterations += iteration;
        // Observed order of the last contraction above round-off, where the
        // iterate is near the solution: about 2 for full Newton.
        for (unsigned int k = 1; k + 1 < residuals.size(); ++k)
          if (residuals[k] < 1e-2 && residuals[k + 1] > 1e-10)
            min_newton_order =
              std::min(min_newton_order,
                       std::log(residuals[k + 1]) / std::log(residuals[k]));
        update_material_points(load_step);

        if (column)
          last_error = column_error(load_factor);
        if (parameters.output.interval > 0 &&
            (load_step % parameters.output.interval == 0 ||
             load_step == n_steps))
          write_points(load_factor, load_step);

        std::ostringstream line;
        line << "step " << std::setw(3) << load_step << "  load " << std::fixed
             << std::setprecision(4) << load_factor << "  iterations "
             << iteration;
        if (column)
          {
            char buffer[32];
            std::snprintf(buffer, sizeof(buffer), "%.4e", last_error);
            line << "  error " << buffer;
          }
        test_lines.push_back(line.str());
        pcout << line.str() << "  residual " << std::scientific
              << std::setprecision(2) << residuals.back() << std::endl;

        const auto times = timer.get_summary_data(TimerOutput::total_wall_time);
        if (is_root)
          {
            steps_file << load_step << ',' << std::setprecision(10)
                       << load_factor << ',' << iteration << ','
                       << residuals.back() << ',' << n_system_dofs_last;
            if (column)
              steps_file << ',' << last_error;
            for (const auto &phase : phase_names)
              {
                const double now = times.count(phase) ? times.at(phase) : 0.;
                steps_file << ',' << now - previous_times[phase];
                previous_times[phase] = now;
              }
            steps_file << std::endl;
            newton_file.flush();
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
    prm.enter_subsection("Material");
    std::unique_ptr<Material> material = MaterialRegistry::create(prm);
    prm.leave_subsection();
    MPMSolver<dim> solver(parameters, std::move(material), communicator);
    solver.run();
  }



  template class MPMSolver<2>;
  template class MPMSolver<3>;
  template void
  run_scene<2>(ParameterHandler &, const MPI_Comm);
  template void
  run_scene<3>(ParameterHandler &, const MPI_Comm);
} // namespace impm
