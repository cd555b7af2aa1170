#ifndef impm_system_off_process_rows_h
#define impm_system_off_process_rows_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>

#include <map>
#include <memory>
#include <vector>

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
   * The rows' pattern is fixed from one setup to the next, so it is sent to
   * the owners once, when the system is set up: reinit() sends it,
   * add_received_to() puts what this process received into its own rows'
   * pattern (so the system matrix is made from this process's rows alone,
   * without deal.II's own machinery for off-process rows), and connect()
   * finds where each received entry lives in the system matrix. add_to()
   * then sends only the values, and each owner adds them at those
   * addresses. (Trilinos' Export of a matrix sends the indices with every
   * exchange and looks each entry up again: 1.9 ms per assembly on the 3D
   * quarter collapse on 2 processes, 6 % of the run.)
   *
   * On one process, or when no process writes to rows of another, nothing
   * is created (active() is false).
   */
  class OffProcessRows
  {
  public:
    /**
     * @brief Start a setup: take the rows of @p pattern (rows this process
     * assembles that other processes own, with their columns; the system's
     * rows are numbered contiguously per process in the order of the
     * ranks, this process's being @p owned) and send their structure to
     * their owners. Collective.
     */
    void
    reinit(const IndexSet               &owned,
           const DynamicSparsityPattern &pattern,
           const MPI_Comm                communicator);

    /**
     * @brief Add the rows other processes sent to reinit() to @p
     * own_pattern, the pattern of this process's own rows, from which the
     * system matrix is then made.
     */
    void
    add_received_to(DynamicSparsityPattern &own_pattern) const;

    /**
     * @brief Finish the setup once @p matrix is made: make the rows' own
     * matrix and find each received entry in @p matrix. Collective.
     */
    void
    connect(const TrilinosWrappers::SparseMatrix &matrix);

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
     * @brief Add the rows to their owners' rows of @p matrix, the matrix
     * given to connect() (its pattern unchanged since). Collective.
     */
    void
    add_to(TrilinosWrappers::SparseMatrix &matrix) const;

  private:
    /**
     * A message of reinit(): for each row, its global index, its number of
     * entries and their global columns, in ascending order.
     */
    using Structure = std::vector<int>;

    /**
     * Where this process's rows go: the owner, and the addresses in `rows`
     * of the values it is sent, in the order of the structure sent to it.
     */
    struct Destination
    {
      unsigned int                process;
      std::vector<const double *> values;
    };

    /**
     * What another process sends: the addresses in this process's matrix
     * at which its values are added, in the order they come.
     */
    struct Source
    {
      unsigned int          process;
      std::vector<double *> targets;
    };

    /** Between reinit() and connect(): the structures sent and received. */
    std::map<unsigned int, Structure> sent, received;
    /** This process alone, for the rows' maps. */
    Epetra_MpiComm self{MPI_COMM_SELF};
    /** The rows' maps: their global rows and columns. */
    std::unique_ptr<Epetra_Map> row_map, column_map;
    /** The rows and their values. */
    std::unique_ptr<Epetra_CrsMatrix> rows;
    /** The matrix of connect(), which add_to() must be given. */
    const Epetra_CrsMatrix *target_matrix = nullptr;
    /** The processes this one sends to and receives from. */
    std::vector<Destination> destinations;
    std::vector<Source>      sources;
    /** Buffers of add_to(), one per destination and one per source. */
    mutable std::vector<std::vector<double>> send_buffers, receive_buffers;
    MPI_Comm                                 communicator = MPI_COMM_NULL;
    /** Whether any process has rows to send (known from reinit()). */
    bool any_rows = false;
    /** See note_added_through_matrix(). */
    mutable bool added_through_matrix = false;
  };
} // namespace impm

#endif
