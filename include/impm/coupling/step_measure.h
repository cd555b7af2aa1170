#ifndef impm_coupling_step_measure_h
#define impm_coupling_step_measure_h

#include <string>

namespace impm
{
  /**
   * @brief What a StepMeasure's value is: how the test summary prints it in
   * its scales (Testing/Reference length L and stress S).
   */
  enum class MeasureKind
  {
    /** A force (N; per m of thickness in 2D): printed in S L^(dim-1), to 6
     *  decimals. */
    force,
    /** A length or a displacement (m): printed in L, to 6 decimals. */
    length,
    /** A count: printed as an integer. */
    count,
    /** An energy (J; per m of thickness in 2D): printed in S L^dim, to 6
     *  decimals. */
    energy,
    /** A dimensionless number: printed as it is, to 5 significant
     *  digits. */
    number
  };

  /** @brief A value measured after a converged load step. */
  struct StepMeasure
  {
    /** Its column in steps.csv and key in summary.json. */
    std::string column;
    /** Its word in the progress log. */
    std::string label;
    /** The value. */
    double value;
    /** What it is, for the test summary's scales (not saved in
     *  checkpoints: RunStatistics::load() restores the values only). */
    MeasureKind kind = MeasureKind::number;
  };

} // namespace impm

#endif
