#ifndef impm_assembly_dense_block_adder_h
#define impm_assembly_dense_block_adder_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Adds dense blocks (all rows times all columns of one set of
   * system indices) to a Trilinos matrix whose sparsity pattern holds them.
   *
   * Rows this process owns are added in place: the block's columns, sorted
   * by their local index, are found by one merge walk along the matrix's
   * sorted row (instead of a binary search and a global-to-local lookup per
   * entry, which cost 40 % of the 3D collapse's run time). Rows of other
   * processes go through the matrix's add(). The scratch arrays are kept
   * between blocks.
   */
  class DenseBlockAdder
  {
  public:
    /**
     * @brief Add the block @p entry(a, b) on rows and columns @p indices
     * (@p n system indices, ascending; a and b index into them) to
     * @p matrix.
     */
    template <typename Entry>
    void
    add(const types::global_dof_index  *indices,
        const unsigned int              n,
        const Entry                    &entry,
        TrilinosWrappers::SparseMatrix &matrix)
    {
      // The values are changed through the row views of the (const)
      // matrix deal.II exposes.
      const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
      columns.resize(n);
      positions.resize(n);
      row_values.resize(n);
      // The block's columns in the matrix's local numbering, sorted.
      for (unsigned int b = 0; b < n; ++b)
        columns[b] = {epetra.LCID(static_cast<int>(indices[b])), b};
      std::sort(columns.begin(), columns.end());
      bool have_positions   = false;
      int  positions_length = 0;
      for (unsigned int a = 0; a < n; ++a)
        {
          const int local_row = epetra.LRID(static_cast<int>(indices[a]));
          if (local_row < 0)
            {
              for (unsigned int b = 0; b < n; ++b)
                row_values[b] = entry(a, b);
              matrix.add(indices[a],
                         n,
                         indices,
                         row_values.data(),
                         /*elide_zero_values=*/false,
                         /*col_indices_are_sorted=*/true);
              continue;
            }
          int     length         = 0;
          double *values         = nullptr;
          int    *columns_of_row = nullptr;
          epetra.ExtractMyRowView(local_row, length, values, columns_of_row);
          // Rows with the same columns follow each other (the components
          // of one node): the previous row's positions are tried first.
          bool known = have_positions && length == positions_length;
          for (unsigned int c = 0; c < n && known; ++c)
            known = columns_of_row[positions[c]] == columns[c].first;
          if (!known)
            {
              int position = 0;
              for (unsigned int c = 0; c < n; ++c)
                {
                  while (position < length &&
                         columns_of_row[position] < columns[c].first)
                    ++position;
                  // Checked in release builds too: an entry missing from
                  // the sparsity pattern must not become a write past the
                  // row.
                  AssertThrow(position < length &&
                                columns_of_row[position] == columns[c].first,
                              ExcMessage("A dense block of the stiffness has "
                                         "an entry outside the system's "
                                         "sparsity pattern."));
                  positions[c] = position;
                }
              have_positions   = true;
              positions_length = length;
            }
          for (unsigned int c = 0; c < n; ++c)
            values[positions[c]] += entry(a, columns[c].second);
        }
    }

  private:
    /** The block's columns: (local column index, position in the block). */
    std::vector<std::pair<int, unsigned int>> columns;
    /** Where each sorted column sits in the current row. */
    std::vector<int> positions;
    /** One row's values, for rows of other processes. */
    std::vector<double> row_values;
  };
} // namespace impm

#endif
