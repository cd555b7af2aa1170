#ifndef impm_system_kept_entries_h
#define impm_system_kept_entries_h

#include <Epetra_CrsMatrix.h>

#include <utility>
#include <vector>

namespace impm
{
  /**
   * @brief The nonzero entries of one or more Trilinos (Epetra) matrices at
   * one moment, kept as the addresses of their values and the values, so
   * that they can be written back into the same matrices later.
   *
   * The load step's system uses it for the part of the matrix that does
   * not change within a load step (the ghost penalty): assembled once after
   * the setup, recorded, and written back in place of zeros before each
   * later assembly. The addresses stay valid while the matrices keep their
   * sparsity pattern; clear() before they are rebuilt.
   */
  class KeptEntries
  {
  public:
    /** @brief Forget every entry. */
    void
    clear()
    {
      entries.clear();
      recorded = false;
    }

    /**
     * @brief Add the nonzero entries of @p matrix's local rows to those
     * kept, and mark the record as made. Its values must stay where they
     * are (no new pattern) until clear().
     */
    void
    record(const Epetra_CrsMatrix &matrix);

    /** @brief Whether record() was called since the last clear(). */
    bool
    has_record() const
    {
      return recorded;
    }

    /**
     * @brief Write the kept values back into the matrices they came from
     * (whose other entries the caller has set to zero).
     */
    void
    restore() const
    {
      for (const auto &[address, value] : entries)
        *address = value;
    }

  private:
    /** The address of each kept entry in its matrix, and its value. */
    std::vector<std::pair<double *, double>> entries;
    /** See has_record(). */
    bool recorded = false;
  };
} // namespace impm

#endif
