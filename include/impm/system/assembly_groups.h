#ifndef impm_system_assembly_groups_h
#define impm_system_assembly_groups_h

#include <deal.II/base/types.h>

#include <impm/basis/basis_functions.h>
#include <impm/points/point_step.h>

#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Points whose stiffness is summed in one dense local matrix on
   * one support and added to the system matrix once (fixed during a load
   * step): the points of one support and those whose supports it holds
   * (make_assembly_groups()).
   */
  struct AssemblyGroup
  {
    /** Indices into the point steps of the group's points, ascending. */
    std::vector<unsigned int> points;
    /** Number of nodes of the group's support. */
    unsigned int n_nodes = 0;
    /** Local indices of the support's DoFs in the nodal vectors, node by
     *  node (as PointStep::dofs). */
    std::vector<unsigned int> dofs;
    /** If some point's support is smaller than the group's: for each
     *  point in turn, the position of each node of its support in the
     *  group's support; empty if every point has the group's support. */
    std::vector<unsigned char> node_positions;
    /** Positions in dofs of the DoFs in the linear system, in the order of
     *  rows. */
    std::vector<unsigned int> local;
    /** Their indices in the linear system, ascending. */
    std::vector<types::global_dof_index> rows;
    /** For each DoF of the support, whether it is in the linear system. */
    std::vector<unsigned char> in_system;
  };

  /**
   * @brief Group the points of a load step: order them by support, cut the
   * order into runs of one support, and let each run join the largest run
   * whose support (a box of at most 3 nodes per direction) holds its own.
   * The sparsity pattern stays that of the supports alone, and a deformed
   * GIMP body, where nearly every point has a support of its own, adds
   * about one block per node instead of one per point. Standard MPM's
   * supports are cells and never hold one another.
   *
   * @param point_steps The points' supports and DoFs.
   * @param index_in_system Per local DoF its index in the linear system, or
   *   numbers::invalid_dof_index.
   * @param grid The Cartesian grid of the supports' node indices.
   */
  template <int dim>
  std::vector<AssemblyGroup>
  make_assembly_groups(
    const PointSteps<dim>                      &point_steps,
    const std::vector<types::global_dof_index> &index_in_system,
    const CartesianGrid<dim>                   &grid);
} // namespace impm

#endif
