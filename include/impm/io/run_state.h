#ifndef impm_io_run_state_h
#define impm_io_run_state_h

#include <map>
#include <string>
#include <vector>

namespace impm
{
  /**
   * @brief The part of a run's state that every process holds alike and a
   * checkpoint keeps beside the grid and the points: the step control, the
   * run's statistics, the records behind the output files. Named values,
   * stored as text lines "key = value" (numbers with 17 digits, so that they
   * are read back exactly).
   *
   * Each part of the run saves and loads its own keys (`save(RunState &)`
   * and `load(const RunState &)`); a missing key is an error naming it.
   */
  class RunState
  {
  public:
    /** @brief Store @p value under @p key. */
    void
    set(const std::string &key, const double value);

    /** @brief Store a text (without line breaks) under @p key. */
    void
    set(const std::string &key, const std::string &value);

    /** @brief Store a list of numbers under @p key. */
    void
    set(const std::string &key, const std::vector<double> &values);

    /** @brief The number stored under @p key. */
    double
    get_double(const std::string &key) const;

    /** @brief The text stored under @p key. */
    const std::string &
    get_string(const std::string &key) const;

    /** @brief The list of numbers stored under @p key. */
    std::vector<double>
    get_list(const std::string &key) const;

    /** @brief The whole state as text. */
    std::string
    to_text() const;

    /** @brief The state held by @p text (from to_text()); @p source names
     *  it in errors. */
    static RunState
    from_text(const std::string &text, const std::string &source);

  private:
    std::map<std::string, std::string> values;
    std::string                        source;
  };
} // namespace impm

#endif
