#include <deal.II/base/exceptions.h>

#include <impm/system/off_process_rows.h>

#include <Epetra_CrsGraph.h>

#include <string>
#include <vector>

namespace impm
{
  void
  OffProcessRows::reinit(const IndexSet                       &owned,
                         const IndexSet                       &relevant,
                         const DynamicSparsityPattern         &pattern,
                         const TrilinosWrappers::SparseMatrix &matrix,
                         const MPI_Comm                        communicator)
  {
    exporter.reset();
    rows.reset();
    row_map.reset();

    IndexSet others = relevant;
    others.subtract_set(owned);
    std::vector<int> global_rows, lengths;
    for (const auto row : others)
      if (pattern.row_length(row) > 0)
        {
          global_rows.push_back(static_cast<int>(row));
          lengths.push_back(static_cast<int>(pattern.row_length(row)));
        }
    if (Utilities::MPI::max(global_rows.empty() ? 0u : 1u, communicator) == 0u)
      return;

    // The rows of several processes may be the same row of a third: the
    // map is not one-to-one, which an export source may be.
    const Epetra_CrsMatrix &system = matrix.trilinos_matrix();
    row_map                        = std::make_unique<Epetra_Map>(-1,
                                           static_cast<int>(global_rows.size()),
                                           global_rows.data(),
                                           0,
                                           system.Comm());
    Epetra_CrsGraph  graph(Copy, *row_map, lengths.data(), true);
    std::vector<int> columns;
    for (const int row : global_rows)
      {
        columns.clear();
        for (auto entry = pattern.begin(row); entry != pattern.end(row);
             ++entry)
          columns.push_back(static_cast<int>(entry->column()));
        const int error =
          graph.InsertGlobalIndices(row,
                                    static_cast<int>(columns.size()),
                                    columns.data());
        AssertThrow(error == 0,
                    ExcMessage("Trilinos error " + std::to_string(error) +
                               " while making the off-process rows."));
      }
    int error = graph.FillComplete(system.DomainMap(), system.RangeMap());
    AssertThrow(error == 0,
                ExcMessage("Trilinos error " + std::to_string(error) +
                           " while completing the off-process rows."));
    rows     = std::make_unique<Epetra_CrsMatrix>(Copy, graph);
    exporter = std::make_unique<Epetra_Export>(*row_map, system.RowMap());
  }



  void
  OffProcessRows::zero()
  {
    added_through_matrix = false;
    if (rows != nullptr)
      rows->PutScalar(0.);
  }



  void
  OffProcessRows::add_to(TrilinosWrappers::SparseMatrix &matrix) const
  {
    if (rows == nullptr)
      return;
    // deal.II exposes the Epetra matrix as const; its compress() exports
    // its own off-process entries into it the same way.
    Epetra_CrsMatrix &system =
      const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
    const int error = system.Export(*rows, *exporter, Add);
    AssertThrow(error == 0,
                ExcMessage("Trilinos error " + std::to_string(error) +
                           " while sending the off-process rows."));
  }
} // namespace impm
