#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <impm/system/off_process_rows.h>

#include <Epetra_CrsGraph.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * MPI tags of the two exchanges, apart from deal.II's (300 to about
     * 1,000) and Epetra's (24,050 to 24,099).
     */
    constexpr int structure_tag = 4216;
    constexpr int values_tag    = 4217;

    /** Throw with Trilinos' error code if @p error is not zero. */
    void
    check(const int error, const std::string &while_doing)
    {
      AssertThrow(error == 0,
                  ExcMessage("Trilinos error " + std::to_string(error) +
                             " while " + while_doing + "."));
    }



    /**
     * The positions in a row of @p matrix, whose local columns are @p
     * indices, of the global columns @p columns (ascending), into @p
     * positions; throws if one is missing. (The row's global columns are
     * sorted and merged with @p columns: no lookup in the column map's
     * hash table, which took most of the setup's time here.)
     */
    void
    positions_in_row(const Epetra_CrsMatrix           &matrix,
                     const int                        *indices,
                     const int                         n_entries,
                     const int                        *columns,
                     const int                         n_columns,
                     std::vector<std::pair<int, int>> &row_columns,
                     std::vector<int>                 &positions)
    {
      const int *global = matrix.ColMap().MyGlobalElements();
      row_columns.resize(n_entries);
      for (int k = 0; k < n_entries; ++k)
        row_columns[k] = {global[indices[k]], k};
      std::sort(row_columns.begin(), row_columns.end());
      positions.resize(n_columns);
      auto entry = row_columns.begin();
      for (int c = 0; c < n_columns; ++c)
        {
          while (entry != row_columns.end() && entry->first < columns[c])
            ++entry;
          AssertThrow(entry != row_columns.end() && entry->first == columns[c],
                      ExcMessage("An off-process entry is not in its "
                                 "owner's sparsity pattern."));
          positions[c] = entry->second;
        }
    }
  } // namespace



  void
  OffProcessRows::reinit(const IndexSet               &owned,
                         const DynamicSparsityPattern &pattern,
                         const MPI_Comm                communicator)
  {
    rows.reset();
    row_map.reset();
    column_map.reset();
    target_matrix = nullptr;
    destinations.clear();
    sources.clear();
    send_buffers.clear();
    receive_buffers.clear();
    sent.clear();
    received.clear();
    this->communicator = communicator;

    // The owners' ranges of rows.
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(communicator);
    const std::vector<types::global_dof_index> n_owned =
      Utilities::MPI::all_gather(communicator, owned.n_elements());
    std::vector<types::global_dof_index> end_rows(n_processes);
    types::global_dof_index              end = 0;
    for (unsigned int p = 0; p < n_processes; ++p)
      end_rows[p] = (end += n_owned[p]);

    for (const auto row : pattern.row_index_set())
      if (pattern.row_length(row) > 0)
        {
          AssertThrow(!owned.is_element(row), ExcInternalError());
          const unsigned int owner =
            std::upper_bound(end_rows.begin(), end_rows.end(), row) -
            end_rows.begin();
          AssertThrow(owner < n_processes, ExcInternalError());
          Structure &message = sent[owner];
          message.push_back(static_cast<int>(row));
          message.push_back(static_cast<int>(pattern.row_length(row)));
          for (auto entry = pattern.begin(row); entry != pattern.end(row);
               ++entry)
            message.push_back(static_cast<int>(entry->column()));
        }
    any_rows = Utilities::MPI::max(sent.empty() ? 0u : 1u, communicator) == 1u;
    if (!any_rows)
      return;

    // Send the structures; each process learns who sends to it, and the
    // sizes come with the messages.
    std::vector<unsigned int> targets;
    for (const auto &[process, message] : sent)
      targets.push_back(process);
    const std::vector<unsigned int> senders =
      Utilities::MPI::compute_point_to_point_communication_pattern(communicator,
                                                                   targets);
    const int                tag = structure_tag;
    std::vector<MPI_Request> requests;
    for (const auto &[process, message] : sent)
      {
        requests.emplace_back();
        AssertThrowMPI(MPI_Isend(message.data(),
                                 static_cast<int>(message.size()),
                                 MPI_INT,
                                 static_cast<int>(process),
                                 tag,
                                 communicator,
                                 &requests.back()));
      }
    for (unsigned int i = 0; i < senders.size(); ++i)
      {
        MPI_Status status;
        AssertThrowMPI(MPI_Probe(MPI_ANY_SOURCE, tag, communicator, &status));
        int size = 0;
        AssertThrowMPI(MPI_Get_count(&status, MPI_INT, &size));
        Structure &message = received[status.MPI_SOURCE];
        message.resize(size);
        AssertThrowMPI(MPI_Recv(message.data(),
                                size,
                                MPI_INT,
                                status.MPI_SOURCE,
                                tag,
                                communicator,
                                MPI_STATUS_IGNORE));
      }
    AssertThrowMPI(MPI_Waitall(static_cast<int>(requests.size()),
                               requests.data(),
                               MPI_STATUSES_IGNORE));
  }



  void
  OffProcessRows::add_received_to(DynamicSparsityPattern &own_pattern) const
  {
    std::vector<types::global_dof_index> columns;
    for (const auto &[process, message] : received)
      for (std::size_t i = 0; i < message.size(); i += 2 + message[i + 1])
        {
          columns.assign(message.begin() + i + 2,
                         message.begin() + i + 2 + message[i + 1]);
          own_pattern.add_entries(message[i],
                                  columns.begin(),
                                  columns.end(),
                                  true);
        }
  }



  void
  OffProcessRows::connect(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix &system = matrix.trilinos_matrix();
    target_matrix                  = &system;
    if (!any_rows)
      return;

    // The rows' own matrix, on this process alone (its maps need no
    // exchange: the columns are those of its rows, and the owners' rows
    // are reached by add_to(), not by Trilinos).
    std::vector<int> global_rows, lengths;
    int              first_column = std::numeric_limits<int>::max();
    int              last_column  = -1;
    for (const auto &[process, message] : sent)
      for (std::size_t i = 0; i < message.size(); i += 2 + message[i + 1])
        {
          global_rows.push_back(message[i]);
          lengths.push_back(message[i + 1]);
          if (message[i + 1] > 0)
            {
              first_column = std::min(first_column, message[i + 2]);
              last_column =
                std::max(last_column, message[i + 1 + message[i + 1]]);
            }
        }
    // The distinct columns, marked over their range (each row's are
    // sorted; a sort of all of them took 2-3 ms per setup).
    std::vector<int> columns;
    if (last_column >= first_column)
      {
        std::vector<char> used(last_column - first_column + 1, 0);
        for (const auto &[process, message] : sent)
          for (std::size_t i = 0; i < message.size(); i += 2 + message[i + 1])
            for (int k = 0; k < message[i + 1]; ++k)
              used[message[i + 2 + k] - first_column] = 1;
        for (std::size_t c = 0; c < used.size(); ++c)
          if (used[c])
            columns.push_back(first_column + static_cast<int>(c));
      }
    row_map = std::make_unique<Epetra_Map>(
      -1, static_cast<int>(global_rows.size()), global_rows.data(), 0, self);
    column_map = std::make_unique<Epetra_Map>(
      -1, static_cast<int>(columns.size()), columns.data(), 0, self);
    Epetra_CrsGraph graph(Copy, *row_map, *column_map, lengths.data(), true);
    for (const auto &[process, message] : sent)
      for (std::size_t i = 0; i < message.size(); i += 2 + message[i + 1])
        check(graph.InsertGlobalIndices(message[i],
                                        message[i + 1],
                                        const_cast<int *>(&message[i + 2])),
              "making the off-process rows");
    check(graph.FillComplete(*column_map, *row_map),
          "completing the off-process rows");
    rows = std::make_unique<Epetra_CrsMatrix>(Copy, graph);

    // Where the values sent come from, and where those received go, both
    // in the order of the structures.
    // (The rows of a node's components have the same columns, in the
    // message and in the matrix: their positions are found once.)
    const auto addresses =
      [](const Epetra_CrsMatrix &in, const Structure &message, auto &list) {
        std::vector<int>                 positions;
        std::vector<std::pair<int, int>> row_columns;
        const int                       *last_columns = nullptr;
        const int                       *last_indices = nullptr;
        int                              last_length  = -1;
        for (std::size_t i = 0; i < message.size(); i += 2 + message[i + 1])
          {
            const int local_row = in.LRID(message[i]);
            AssertThrow(local_row >= 0, ExcInternalError());
            int        n_entries = 0;
            double    *values    = nullptr;
            int       *indices   = nullptr;
            const int  n_columns = message[i + 1];
            const int *columns   = &message[i + 2];
            check(in.ExtractMyRowView(local_row, n_entries, values, indices),
                  "reading a matrix row");
            const bool same_as_last =
              last_columns != nullptr &&
              n_columns == static_cast<int>(positions.size()) &&
              n_entries == last_length &&
              std::equal(columns, columns + n_columns, last_columns) &&
              std::equal(indices, indices + n_entries, last_indices);
            if (!same_as_last)
              positions_in_row(in,
                               indices,
                               n_entries,
                               columns,
                               n_columns,
                               row_columns,
                               positions);
            for (int k = 0; k < n_columns; ++k)
              list.push_back(values + positions[k]);
            last_columns = columns;
            last_indices = indices;
            last_length  = n_entries;
          }
      };
    for (const auto &[process, message] : sent)
      {
        destinations.push_back(Destination{process, {}});
        addresses(*rows, message, destinations.back().values);
        send_buffers.emplace_back(destinations.back().values.size());
      }
    for (const auto &[process, message] : received)
      {
        sources.push_back(Source{process, {}});
        addresses(system, message, sources.back().targets);
        receive_buffers.emplace_back(sources.back().targets.size());
      }
    sent.clear();
    received.clear();
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
    AssertThrow(&matrix.trilinos_matrix() == target_matrix,
                ExcMessage("The off-process rows were made for another "
                           "matrix."));
    const int                tag = values_tag;
    std::vector<MPI_Request> requests;
    requests.reserve(destinations.size() + sources.size());
    for (unsigned int s = 0; s < sources.size(); ++s)
      {
        requests.emplace_back();
        const int error = MPI_Irecv(receive_buffers[s].data(),
                                    static_cast<int>(receive_buffers[s].size()),
                                    MPI_DOUBLE,
                                    static_cast<int>(sources[s].process),
                                    tag,
                                    communicator,
                                    &requests.back());
        AssertThrowMPI(error);
      }
    for (unsigned int d = 0; d < destinations.size(); ++d)
      {
        std::vector<double> &buffer = send_buffers[d];
        for (std::size_t k = 0; k < buffer.size(); ++k)
          buffer[k] = *destinations[d].values[k];
        requests.emplace_back();
        const int error = MPI_Isend(buffer.data(),
                                    static_cast<int>(buffer.size()),
                                    MPI_DOUBLE,
                                    static_cast<int>(destinations[d].process),
                                    tag,
                                    communicator,
                                    &requests.back());
        AssertThrowMPI(error);
      }
    // Add each source's values as they arrive.
    const unsigned int n_receives = sources.size();
    for (unsigned int done = 0; done < n_receives; ++done)
      {
        int       index = MPI_UNDEFINED;
        const int error = MPI_Waitany(static_cast<int>(n_receives),
                                      requests.data(),
                                      &index,
                                      MPI_STATUS_IGNORE);
        AssertThrowMPI(error);
        const std::vector<double *> &targets = sources[index].targets;
        const std::vector<double>   &values  = receive_buffers[index];
        for (std::size_t k = 0; k < targets.size(); ++k)
          *targets[k] += values[k];
      }
    const int error = MPI_Waitall(static_cast<int>(destinations.size()),
                                  requests.data() + n_receives,
                                  MPI_STATUSES_IGNORE);
    AssertThrowMPI(error);
  }
} // namespace impm
