#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>

#include <new>
#include <sstream>

namespace impm
{
  void
  throw_if_any_failed(const std::string &local_error,
                      const MPI_Comm     communicator,
                      const bool         name_process)
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    // The lowest failed rank, or n_ranks if none failed.
    const unsigned int first_failed =
      dealii::Utilities::MPI::min(local_error.empty() ? n_ranks : rank,
                                  communicator);
    if (first_failed == n_ranks)
      return;
    int length =
      rank == first_failed ? static_cast<int>(local_error.size()) : 0;
    MPI_Bcast(&length, 1, MPI_INT, first_failed, communicator);
    std::string message =
      rank == first_failed ? local_error : std::string(length, ' ');
    MPI_Bcast(message.data(), length, MPI_CHAR, first_failed, communicator);
    if (n_ranks > 1 && name_process)
      message = "process " + std::to_string(first_failed) + ": " + message;
    throw CollectiveError(message);
  }



  std::string
  collapse_white_space(const std::string &text)
  {
    std::istringstream in(text);
    std::string        word, result;
    while (in >> word)
      result += (result.empty() ? "" : " ") + word;
    return result;
  }



  std::string
  one_line_message(const std::exception &exception)
  {
    if (dynamic_cast<const std::bad_alloc *>(&exception) != nullptr)
      return "Out of memory (a memory allocation failed).";
    if (const auto *deal_ii_exception =
          dynamic_cast<const dealii::ExceptionBase *>(&exception))
      {
        std::ostringstream info;
        deal_ii_exception->print_info(info);
        std::string message = collapse_white_space(info.str());
        if (message.empty())
          message = collapse_white_space(deal_ii_exception->get_exc_name());
        return "Internal error: " + message +
               " (run with --verbose for the full report)";
      }
    // IMPM's own messages are written for the user (a failed load step
    // lists its attempts on the lines after the first).
    const std::string message = exception.what();
    return message.empty() ? "unnamed error" : message;
  }



  std::string
  bytes_in_words(const double bytes)
  {
    const char  *units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
    double       value   = bytes;
    unsigned int unit    = 0;
    while (value >= 1000. && unit < 5)
      {
        value /= 1000.;
        ++unit;
      }
    std::ostringstream out;
    out.precision(3);
    out << value << " " << units[unit];
    return out.str();
  }



  std::string
  number_text(const double value)
  {
    std::ostringstream out;
    out.precision(6);
    out << value;
    return out.str();
  }
} // namespace impm
