#ifndef impm_system_load_step_system_h
#define impm_system_load_step_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/points/point_step.h>
#include <impm/system/assembly_groups.h>
#include <impm/system/kept_entries.h>
#include <impm/system/near_null_space.h>
#include <impm/system/off_process_rows.h>

#include <cstdint>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The linear system of one load step: the basis of every point on
   * the start-of-step grid (evaluated once per step), the compact numbering
   * of the DoFs that material touches and that no face condition holds, the
   * points grouped by support for the assembly, and the sparsity pattern,
   * matrix and vectors on that numbering.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class LoadStepSystem
  {
  public:
    /**
     * @brief Constructor.
     * @param grid The background grid.
     * @param communicator The processes that share the system.
     */
    LoadStepSystem(const BackgroundGrid<dim> &grid,
                   const MPI_Comm             communicator);

    /**
     * @brief Evaluate each point's weights and gradients on the grid (once
     * per load step) and find its support's DoFs.
     */
    void
    evaluate_basis(const MaterialPoints<dim> &material_points,
                   const BasisType            basis);

    /**
     * @brief The weights of a force on one face of point @p p's domain over
     * the nodes of its support (BasisEvaluator::face_weights()), with the
     * basis of the last evaluate_basis().
     * @param p The point's index in point_steps.
     * @param position, half_length The point's start-of-step position and
     *   domain half-lengths.
     * @param axis, sign The face.
     * @param[out] weights One per node of the point's support.
     */
    void
    face_weights(
      const unsigned int                                p,
      const Point<dim>                                 &position,
      const Tensor<1, dim>                             &half_length,
      const unsigned int                                axis,
      const double                                      sign,
      std::array<double, PointSupport<dim>::max_nodes> &weights) const;

    /**
     * @brief Which local DoFs (owned and ghost) the points of this step
     * touch, on every process that has them. Collective.
     */
    std::vector<bool>
    touched_dofs() const;

    /**
     * @brief Number the system: the owned DoFs in @p touched that no face
     * condition holds, then @p n_coupling_rows rows of the couplings'
     * unknowns (Coupling::prepare()), contiguously per process; and, for
     * a matrix (@p with_groups), group the points by support.
     * Collective.
     */
    void
    number(const std::vector<bool>      &touched,
           const types::global_dof_index n_coupling_rows,
           const bool                    with_groups = true);

    /** @brief The local DoFs the step's points touch, as number() was
     *  given them (touched_dofs() of the step's setup). */
    const std::vector<bool> &
    touched() const
    {
      return touched_in_step;
    }

    /** @brief The first row of this process's couplings' unknowns (after
     *  its nodal rows). */
    types::global_dof_index
    first_coupling_row() const
    {
      return first_row + n_nodal_rows;
    }

    /** @brief The rows this process owns. */
    const IndexSet &
    owned_rows() const
    {
      return owned;
    }

    /**
     * @brief Make the sparsity pattern, matrix and vectors from the points'
     * supports and the further dense blocks @p blocks (the couplings'), or
     * keep the matrix of the step before when it has the same rows and
     * pattern on every process (the same system): returns whether it was
     * kept. Collective.
     */
    bool
    make_pattern(
      const std::vector<std::vector<types::global_dof_index>> &blocks);

    /** @brief The per-point data of this step, in iteration order. */
    PointSteps<dim> point_steps;

    /** @brief Whether the points are rings about an axis
     *  (Grid/Axisymmetric): their supports' hoop weights then give the hoop
     *  terms. */
    bool
    axisymmetric() const
    {
      return grid.cartesian().axisymmetric;
    }
    /** @brief The points grouped by support. */
    std::vector<AssemblyGroup> assembly_groups;

    /**
     * @brief The index in the linear system of local DoF @p local (owned
     * or ghost), or numbers::invalid_dof_index.
     */
    types::global_dof_index
    system_index(const unsigned int local) const
    {
      return index_in_system[local];
    }

    /** @brief Number of DoFs in the linear system, on all processes. */
    types::global_dof_index
    n_dofs() const
    {
      return owned.size();
    }

    /**
     * @brief The Euclidean norm of @p vector over the system's DoFs.
     * Collective.
     */
    double
    norm_in_system(const NodalVector &vector) const;

    /**
     * @brief The rigid-body modes on this process's rows of the system: the
     * near null space an algebraic multigrid needs for elasticity. The
     * rotations are taken about the centre of the system's nodes and
     * scaled by their extent, so that all modes are of order one.
     * Collective.
     */
    NearNullSpace
    rigid_body_modes() const;

    /**
     * @brief Set the right-hand side to @p external - @p internal on the
     * system's DoFs and to minus the residuals @p further_rows on further
     * rows this process owns (the couplings' unknowns); returns its norm.
     * Collective.
     */
    double
    set_residual(const NodalVector &external,
                 const NodalVector &internal,
                 const std::vector<std::pair<types::global_dof_index, double>>
                   &further_rows = {});

    /**
     * @brief Add the solution to @p increment on the system's DoFs and
     * update its ghosts. Collective.
     */
    void
    add_solution_to(NodalVector &increment) const;

    /**
     * @brief Copy @p nodal (compressed) on the system's DoFs into @p
     * system_vector (a vector of the system's partition, as rhs).
     * Collective.
     */
    void
    copy_to_system(const NodalVector             &nodal,
                   TrilinosWrappers::MPI::Vector &system_vector) const;

    /**
     * @brief Add @p system_vector to @p nodal on the system's DoFs and
     * update its ghosts. Collective.
     */
    void
    add_to_nodal(const TrilinosWrappers::MPI::Vector &system_vector,
                 NodalVector                         &nodal) const;

    /**
     * @brief Free point_steps (after a converged step has advanced the
     * points; evaluate_basis() makes them anew for the next step).
     */
    void
    release_point_steps()
    {
      point_steps.release();
    }

    /**
     * @brief Start an assembly of the matrix: set it and its off-process
     * rows to the load step's constant part if keep_constant_part() has
     * recorded one since the last setup(), else to zero; in place
     * (deal.II's operator= would first compress(), an exchange with every
     * process). Returns whether the constant part is in; if not, the caller
     * adds the terms that do not change within the load step and may then
     * call keep_constant_part().
     */
    bool
    begin_matrix();

    /**
     * @brief Keep the matrix's and off-process rows' present entries as the
     * load step's constant part, for begin_matrix() to write back until the
     * next setup(). Call right after adding the constant terms to a matrix
     * that begin_matrix() zeroed. Does nothing if a row went through the
     * matrix's add() (held by Trilinos, not in place): then every assembly
     * adds the constant terms itself.
     */
    void
    keep_constant_part();

    /**
     * @brief Finish an assembly: send the off-process rows to their owners
     * and, if on any process a row went through the matrix's add() (@p
     * added_through_matrix, or DenseBlockAdder's rows that the off-process
     * rows do not hold), let deal.II's compress() exchange those. Collective.
     */
    void
    finish_matrix(const bool added_through_matrix);

    /** @brief The system matrix. */
    TrilinosWrappers::SparseMatrix matrix;
    /** @brief The matrix's rows that this process assembles and another
     *  owns, added to the matrix by finish_matrix() after each assembly. */
    OffProcessRows off_process_rows;
    /** @brief The right-hand side (the residual). */
    TrilinosWrappers::MPI::Vector rhs;
    /** @brief The solution (the Newton correction). */
    TrilinosWrappers::MPI::Vector solution;

    /** @brief Load steps whose setup() kept the matrix of the step before
     *  (the same sparsity pattern on every process). */
    unsigned int n_patterns_reused = 0;
    /** @brief All load steps' setups. */
    unsigned int n_setups = 0;

  private:
    /**
     * @brief A fingerprint of what the sparsity pattern is made of on this
     * process: the system's size and this process's rows, the distinct
     * row sets of the assembly groups and the further dense blocks (@p
     * blocks: stabilised faces, F-bar patches). Equal fingerprints give
     * equal patterns.
     */
    std::uint64_t
    pattern_fingerprint(
      const std::vector<std::vector<types::global_dof_index>> &blocks) const;

    /** See keep_constant_part(). */
    KeptEntries constant_part;

    /** The fingerprint of the pattern the matrix has (0: none yet). */
    std::uint64_t matrix_fingerprint = 0;


    const BackgroundGrid<dim> &grid;
    const MPI_Comm             communicator;
    /** The basis of the last evaluate_basis(). */
    BasisType                            basis = BasisType::gimp;
    std::vector<types::global_dof_index> index_in_system;
    /** The local DoFs the step's points touch (number()'s argument). */
    std::vector<bool> touched_in_step;
    IndexSet          owned;
    /** This process's first row. */
    types::global_dof_index first_row = 0;
    /** This process's rows of nodal DoFs (its first rows; the couplings'
     *  unknowns follow them). */
    types::global_dof_index n_nodal_rows = 0;
  };
} // namespace impm

#endif
