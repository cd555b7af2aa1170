#ifndef impm_system_off_process_rows_h
#define impm_system_off_process_rows_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Export.h>
#include <Epetra_Map.h>

#include <memory>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The rows of the system matrix that this process assembles but
   * another process owns (those of the nodes on the partition's boundary),
   * kept as a Trilinos matrix of their own with their sparsity pattern, so
   * that the assembly adds to them in place as it does to its own rows
   * (DenseBlockAdder); add_to() then sends them to their owners once per
   * assembly.
   *
   * Without it such rows go through the matrix's add(), which in Epetra
   * looks every entry up in a sorted list of the process's off-process
   * entries: on the 3D quarter collapse on 2 processes that was 19 % of the
   * run time of the process whose rows border the other's, and the other
   * process waited for it.
   *
   * On one process, or when no process writes to rows of another, nothing
   * is created (active() is false).
   */
  class OffProcessRows
  {
  public:
    /**
     * @brief Make the rows of @p pattern (whose rows are @p relevant)
     * that are not in @p owned, with their columns, and the export to
     * the owners of @p matrix's rows. Call after @p matrix has been made
     * from the distributed @p pattern; collective.
     */
    void
    reinit(const IndexSet                       &owned,
           const IndexSet                       &relevant,
           const DynamicSparsityPattern         &pattern,
           const TrilinosWrappers::SparseMatrix &matrix,
           const MPI_Comm                        communicator);

    /** @brief Whether any process has rows of another to send. */
    bool
    active() const
    {
      return rows != nullptr;
    }

    /** @brief Set every entry to zero (before an assembly). */
    void
    zero();

    /**
     * @brief Note that a row these rows do not hold went through the
     * system matrix's add() (DenseBlockAdder's way for such a row), so that
     * the matrix needs deal.II's compress(); until the next zero().
     */
    void
    note_added_through_matrix() const
    {
      added_through_matrix = true;
    }

    /** @brief Whether note_added_through_matrix() was called since zero(). */
    bool
    any_added_through_matrix() const
    {
      return added_through_matrix;
    }

    /**
     * @brief The rows, for adding to in place (their values are changed
     * through the matrix's row views). Only if active().
     */
    const Epetra_CrsMatrix &
    matrix() const
    {
      return *rows;
    }

    /**
     * @brief Add the rows to their owners' rows of @p matrix (whose
     * pattern holds them), before its compress(). Collective.
     */
    void
    add_to(TrilinosWrappers::SparseMatrix &matrix) const;

  private:
    /** The row map: this process's off-process rows. */
    std::unique_ptr<Epetra_Map> row_map;
    /** The rows and their values. */
    std::unique_ptr<Epetra_CrsMatrix> rows;
    /** From the row map to the system matrix's row map. */
    std::unique_ptr<Epetra_Export> exporter;
    /** See note_added_through_matrix(). */
    mutable bool added_through_matrix = false;
  };
} // namespace impm

#endif
