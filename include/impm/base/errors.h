#ifndef impm_base_errors_h
#define impm_base_errors_h

#include <mpi.h>

#include <exception>
#include <stdexcept>
#include <string>

namespace impm
{
  /**
   * @brief An error that every process raises at the same point of a run:
   * a mistake in the scene (every process reads the same scene), a failed
   * load step (Newton's outcome is global), or a local failure that a
   * collective check (throw_if_any_failed()) has made known to all.
   *
   * `main()` reports such an error once, from rank 0, and every process
   * exits normally. Any other exception reaching `main()` on more than one
   * process is treated as local to the process that raised it: that process
   * reports it and aborts the communicator, so that no other process waits
   * for it in a collective operation.
   */
  class CollectiveError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };



  /**
   * @brief A mistake in the scene or on the command line: a value outside
   * its range, entries that contradict each other, a missing file. Its
   * message is one line naming the entry, the value and what is allowed.
   */
  class InputError : public CollectiveError
  {
  public:
    using CollectiveError::CollectiveError;
  };



  /**
   * @brief A load step that cannot be solved: its Newton solve failed at
   * the smallest load increment the step control allows (or at once, with
   * the control off). Every process raises it together. It carries the
   * load factor of the last converged step, which a strength reduction
   * reads as how far the trial carried the scene's load.
   */
  class LoadStepFailure : public CollectiveError
  {
  public:
    /**
     * @brief Constructor.
     * @param message The one-line report (step, outcome, residuals).
     * @param converged_load_factor The load factor of the last converged
     *   step (0 if none converged).
     */
    LoadStepFailure(const std::string &message,
                    const double       converged_load_factor)
      : CollectiveError(message)
      , converged_load_factor(converged_load_factor)
    {}

    /** The load factor of the last converged step. */
    double converged_load_factor;
  };



  /**
   * @brief A material point that a converged load step moved outside the
   * background grid (or to a non-finite position). Every process raises it
   * together; a strength reduction counts it as a failed trial.
   */
  class PointLeftGrid : public CollectiveError
  {
  public:
    using CollectiveError::CollectiveError;
  };



  /**
   * @brief The collective check before a collective operation: if
   * @p local_error is not empty on any process, every process throws a
   * CollectiveError with the message of the lowest such rank (prefixed by
   * the rank on more than one process, if @p name_process). Must be called
   * by all processes of @p communicator.
   */
  void
  throw_if_any_failed(const std::string &local_error,
                      const MPI_Comm     communicator,
                      const bool         name_process = true);



  /**
   * @brief Run @p action on every process of @p communicator; an exception
   * on any process becomes a CollectiveError on all of them (see
   * throw_if_any_failed()). For work that some processes may fail alone
   * (writing files, local checks) and that is followed by a collective
   * operation.
   */
  template <typename Action>
  void
  run_collectively(const MPI_Comm communicator, const Action &action)
  {
    std::string local_error;
    try
      {
        action();
      }
    catch (const CollectiveError &)
      {
        // Raised on every process already.
        throw;
      }
    catch (const std::exception &exception)
      {
        local_error = exception.what();
        if (local_error.empty())
          local_error = "unnamed error";
      }
    throw_if_any_failed(local_error, communicator);
  }



  /**
   * @brief The message of @p exception as one line for the user: deal.II's
   * exceptions are reduced to their explanation (no source file, function
   * or condition), other exceptions to their text, runs of white space to
   * one blank.
   */
  std::string
  one_line_message(const std::exception &exception);



  /**
   * @brief @p bytes for a message, in the decimal unit that suits them, to
   * three digits ("156 kB", "2.16e+290 PB").
   */
  std::string
  bytes_in_words(const double bytes);



  /**
   * @brief @p value for a message, to six significant digits without
   * trailing zeros ("1e-05", "0.01", "2.5e+10", "inf"). std::to_string()
   * prints six decimals, which turns a time step of 1e-7 s into
   * "0.000000".
   */
  std::string
  number_text(const double value);



  /**
   * @brief @p text with every run of white space (line breaks included)
   * replaced by one blank, and none at either end.
   */
  std::string
  collapse_white_space(const std::string &text);
} // namespace impm

#endif
