#ifndef impm_system_dense_block_adder_h
#define impm_system_dense_block_adder_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <impm/system/off_process_rows.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief A dense block kept in memory: the entry in row a and column b is
   * `values[row_offsets[a] + column_offsets[b]]`, so a block stored in any
   * layout (row- or column-major, a permuted or larger matrix) is read
   * without copying it.
   */
  struct StoredBlock
  {
    /** The block's storage. */
    const double *values;
    /** Per row of the block: where its entries start in values. */
    const unsigned int *row_offsets;
    /** Per column of the block: its offset from a row's start. */
    const unsigned int *column_offsets;
  };

  /**
   * @brief Adds dense blocks (all rows times all columns of one set of
   * system indices) to a Trilinos matrix whose sparsity pattern holds them.
   *
   * Rows this process owns are added in place: the block's columns are
   * converted to the matrix's local numbering once per block and found in
   * a row through a table from local column to position in the row, made
   * once for the rows of one node (instead of a binary search and a
   * global-to-local lookup per entry, which cost 40 % of the 3D collapse's
   * run time, or a merge walk along the row, which cost half of what
   * remained). Rows that
   * another process owns are added in place in the same way to the
   * OffProcessRows, when given, which sends them to their owners after the
   * assembly; without them (or for a row they do not hold) they go through
   * the matrix's add(). The scratch arrays are kept between blocks.
   *
   * A block is either a StoredBlock, whose entries are read in place (the
   * point stiffness and the ghost faces), or a functor entry(a, b)
   * evaluated per entry (F-bar's rank-one blocks).
   */
  class DenseBlockAdder
  {
  public:
    /**
     * @brief Add the block @p entry(a, b) on rows and columns @p indices
     * (@p n system indices, ascending; a and b index into them) to
     * @p matrix, its rows owned by other processes to @p off_process_rows
     * if that is active.
     */
    template <typename Entry>
    void
    add(const types::global_dof_index  *indices,
        const unsigned int              n,
        const Entry                    &entry,
        TrilinosWrappers::SparseMatrix &matrix,
        const OffProcessRows           &off_process_rows)
    {
      add_rows(indices, n, entry, matrix, off_process_rows);
    }

    /**
     * @brief Add the stored block @p block on rows and columns @p indices
     * (@p n system indices, ascending) to @p matrix, its rows owned by other
     * processes to @p off_process_rows if that is active.
     */
    void
    add(const types::global_dof_index  *indices,
        const unsigned int              n,
        const StoredBlock              &block,
        TrilinosWrappers::SparseMatrix &matrix,
        const OffProcessRows           &off_process_rows)
    {
      add_rows(
        indices,
        n,
        [&](const unsigned int a, const unsigned int b) {
          return block.values[block.row_offsets[a] + block.column_offsets[b]];
        },
        matrix,
        off_process_rows);
    }

  private:
    /**
     * The scratch of the rows of one block in one Epetra matrix (the owned
     * rows, or the off-process ones, whose column numbering differs).
     */
    struct InPlaceRows
    {
      /** The block's columns in the matrix's local numbering (-1 if not
       *  a column of it); made at the block's first row in this matrix. */
      std::vector<int> columns;
      /** Where each column sits in the last row. */
      std::vector<int> positions;
      /** Per local column of the matrix: its position in the last row
       *  that had it (or -1); valid only where the row confirms it. */
      std::vector<int> position_of_column;
      /** Whether columns are made, and positions are those of a row of
       *  length positions_length. */
      bool have_columns = false, have_positions = false;
      int  positions_length = 0;

      /** Forget the last block's columns and positions. */
      void
      start(const unsigned int n)
      {
        columns.resize(n);
        positions.resize(n);
        have_columns   = false;
        have_positions = false;
      }

      /**
       * Add row @p a of the block to local row @p local_row of @p target;
       * @p entry(a, b) is the block's entry.
       */
      template <typename Entry>
      void
      add_row(const Epetra_CrsMatrix        &target,
              const int                      local_row,
              const types::global_dof_index *indices,
              const unsigned int             a,
              const Entry                   &entry)
      {
        const unsigned int n = columns.size();
        if (!have_columns)
          {
            for (unsigned int b = 0; b < n; ++b)
              columns[b] = target.LCID(static_cast<int>(indices[b]));
            have_columns = true;
          }
        int     length         = 0;
        double *values         = nullptr;
        int    *columns_of_row = nullptr;
        target.ExtractMyRowView(local_row, length, values, columns_of_row);
        // Rows with the same columns follow each other (the components of
        // one node): the previous row's positions are tried first.
        bool known = have_positions && length == positions_length;
        for (unsigned int c = 0; c < n && known; ++c)
          known = columns_of_row[positions[c]] == columns[c];
        if (!known)
          {
            // Each column's position in the row, through a table over the
            // matrix's columns (no search: a GIMP row in 3D has 375
            // entries, a point's block 81). Entries left from other rows
            // are told apart by reading the row back.
            if (position_of_column.size() !=
                static_cast<std::size_t>(target.NumMyCols()))
              position_of_column.assign(target.NumMyCols(), -1);
            for (int k = 0; k < length; ++k)
              position_of_column[columns_of_row[k]] = k;
            for (unsigned int c = 0; c < n; ++c)
              {
                const int column = columns[c];
                const int position =
                  column < 0 ? -1 : position_of_column[column];
                // Checked in release builds too: an entry missing from the
                // sparsity pattern must not become a write past the row.
                AssertThrow(position >= 0 && position < length &&
                              columns_of_row[position] == column,
                            ExcMessage("A dense block of the stiffness has "
                                       "an entry outside the system's "
                                       "sparsity pattern."));
                positions[c] = position;
              }
            have_positions   = true;
            positions_length = length;
          }
        const int *position = positions.data();
        for (unsigned int b = 0; b < n; ++b)
          values[position[b]] += entry(a, b);
      }
    };

    /** Add the block's rows, its entries given by @p entry(a, b). */
    template <typename Entry>
    void
    add_rows(const types::global_dof_index  *indices,
             const unsigned int              n,
             const Entry                    &entry,
             TrilinosWrappers::SparseMatrix &matrix,
             const OffProcessRows           &off_process_rows)
    {
      // The values are changed through the row views of the (const)
      // matrices.
      const Epetra_CrsMatrix &owned_rows = matrix.trilinos_matrix();
      const Epetra_CrsMatrix *other_rows =
        off_process_rows.active() ? &off_process_rows.matrix() : nullptr;
      owned.start(n);
      other.start(n);
      for (unsigned int a = 0; a < n; ++a)
        {
          const int row       = static_cast<int>(indices[a]);
          int       local_row = owned_rows.LRID(row);
          if (local_row >= 0)
            {
              owned.add_row(owned_rows, local_row, indices, a, entry);
              continue;
            }
          if (other_rows != nullptr && (local_row = other_rows->LRID(row)) >= 0)
            {
              other.add_row(*other_rows, local_row, indices, a, entry);
              continue;
            }
          off_process_rows.note_added_through_matrix();
          row_values.resize(n);
          for (unsigned int b = 0; b < n; ++b)
            row_values[b] = entry(a, b);
          matrix.add(indices[a],
                     n,
                     indices,
                     row_values.data(),
                     /*elide_zero_values=*/false,
                     /*col_indices_are_sorted=*/true);
        }
    }

    /** The scratch of the owned rows and of the off-process rows. */
    InPlaceRows owned, other;
    /** One row's values, for rows added through the matrix's add(). */
    std::vector<double> row_values;
  };
} // namespace impm

#endif
