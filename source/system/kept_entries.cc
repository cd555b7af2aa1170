#include <deal.II/base/exceptions.h>

#include <impm/system/kept_entries.h>

#include <string>

namespace impm
{
  void
  KeptEntries::record(const Epetra_CrsMatrix &matrix)
  {
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n_entries = 0;
        double *values    = nullptr;
        // A view, not a copy: the addresses are those of the matrix's
        // values (Epetra hands them out from a const matrix).
        const int error = matrix.ExtractMyRowView(row, n_entries, values);
        AssertThrow(error == 0,
                    dealii::ExcMessage("Trilinos error " +
                                       std::to_string(error) +
                                       " while reading a matrix row."));
        for (int k = 0; k < n_entries; ++k)
          if (values[k] != 0.)
            entries.emplace_back(values + k, values[k]);
      }
    recorded = true;
  }
} // namespace impm
