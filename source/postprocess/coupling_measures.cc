#include <impm/postprocess/postprocessor.h>

namespace impm
{
  namespace
  {
    /**
     * @brief The couplings' values after every converged step
     * (Coupling::step_measures(): a spring's reaction, ...), as step
     * measures: in `steps.csv`, `summary.json` and the progress log.
     * Created only when a coupling of the scene has such values.
     */
    template <int dim>
    class CouplingMeasures : public Postprocessor<dim>
    {
    public:
      /** @brief Constructor. */
      explicit CouplingMeasures(const RunContext<dim> &context)
        : couplings(context.couplings)
      {}

      /** @brief Whether a coupling of @p context has step measures. */
      static bool
      wanted(const RunContext<dim> &context)
      {
        for (const auto &coupling : context.couplings.list())
          if (!coupling->step_measure_columns().empty())
            return true;
        return false;
      }

      std::vector<std::string>
      step_measure_columns() const override
      {
        std::vector<std::string> columns;
        for (const auto &coupling : couplings.list())
          for (const std::string &column : coupling->step_measure_columns())
            columns.push_back(column);
        return columns;
      }

      void
      measure_step(const RunContext<dim> &, StepRecord &record) override
      {
        for (const auto &coupling : couplings.list())
          coupling->step_measures(record.target, record.measures);
      }

    private:
      const Couplings<dim> &couplings;
    };
  } // namespace

  IMPM_REGISTER_POSTPROCESSOR(CouplingMeasures,
                              "coupling measures",
                              CouplingMeasures<dim>::wanted(context))
} // namespace impm
