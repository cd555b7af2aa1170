#ifndef impm_postprocess_column_solution_h
#define impm_postprocess_column_solution_h

#include <impm/postprocess/postprocessor.h>

#include <string>
#include <vector>

namespace impm
{
  /**
   * @brief The analytical solution of the column compacted by its weight
   * ('Output/Analytical solution = column'): the paper's eq. 13 error of the
   * vertical stress after every converged step, as the StepMeasure
   * "error_sigma_zz".
   *
   * The exact vertical stress of a point at initial height Z above the
   * column's base is sigma_a = -lambda rho_0 g (l0 - Z), with l0 the height
   * of the first body and lambda the load factor.
   */
  template <int dim>
  class ColumnSolution : public Postprocessor<dim>
  {
  public:
    std::vector<std::string>
    step_measure_columns() const override;

    void
    measure_step(const RunContext<dim> &context, StepRecord &record) override;

    /**
     * @brief Eq. 13: sum_p |sigma_p - sigma_a| V_p^0 / (rho_0 g l0 sum_p
     * V_p^0) at load factor @p load_factor.
     */
    static double
    error(const RunContext<dim> &context, const double load_factor);

    /**
     * @brief The largest |sigma_p - sigma_a| / (rho_0 g l0) at full load: the
     * stress oscillation.
     */
    static double
    max_deviation(const RunContext<dim> &context);

    /**
     * @brief An InputError if the scene @p parameters is not a column the
     * solution describes: one box body under gravity along the last axis
     * only (checked when 'Output/Analytical solution' = column).
     */
    static void
    check_scene(const Parameters::All<dim> &parameters);
  };
} // namespace impm

#endif
