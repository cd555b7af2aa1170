#include <deal.II/base/utilities.h>

#include <impm/base/names.h>
#include <impm/io/log_file.h>
#include <impm/postprocess/postprocessor.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>

namespace impm
{
  namespace
  {
    /** Whether this process writes the run's shared files. */
    bool
    is_root(const MPI_Comm communicator)
    {
      return Utilities::MPI::this_mpi_process(communicator) == 0;
    }



    /**
     * @brief A CSV file of the run in the output directory, written by rank
     * 0: its header at the start, then its rows after every attempt, flushed
     * whole.
     */
    template <int dim>
    class CsvFile : public Postprocessor<dim>
    {
    public:
      /**
       * @brief The file @p file_name in the output directory, with the
       * header @p fixed_header unless write_header() is overridden.
       */
      explicit CsvFile(const std::string &file_name,
                       const std::string &fixed_header = "")
        : file_name(file_name)
        , fixed_header(fixed_header)
      {}

      void
      start(const RunContext<dim> &context) override
      {
        if (!is_root(context.communicator))
          return;
        file.open(context.parameters.scene.output_directory + '/' + file_name);
        write_header(context, file.stream());
        file.stream() << '\n';
        file.flush();
      }

      void
      resume(const RunContext<dim> &context, const RunState &state) override
      {
        if (!is_root(context.communicator))
          return;
        file.reopen(context.parameters.scene.output_directory + '/' + file_name,
                    static_cast<std::streamoff>(
                      state.get_double(file_name + ".size")));
      }

      void
      save(const RunContext<dim> &context, RunState &state) const override
      {
        // Rank 0 writes the state.
        if (is_root(context.communicator))
          state.set(file_name + ".size", static_cast<double>(file.size()));
      }

      void
      after_step(const RunContext<dim> &context,
                 const StepRecord      &record,
                 const RunStatistics<dim> &) override
      {
        if (!is_root(context.communicator))
          return;
        write_rows(context, record, file.stream());
        file.flush();
      }

    protected:
      /** Write the header (without its line end). */
      virtual void
      write_header(const RunContext<dim> &, std::ostream &out)
      {
        out << fixed_header;
      }

      /** Write the rows of the attempt @p record, each ended. */
      virtual void
      write_rows(const RunContext<dim> &context,
                 const StepRecord      &record,
                 std::ostream          &out) = 0;

    private:
      const std::string file_name;
      const std::string fixed_header;
      LogFile           file;
    };



    /**
     * @brief `steps.csv`: one row per load-step attempt with its load,
     * Newton iterations, final residual, system size, the step measures, the
     * reactions per face and component, and the time of each phase. A cut
     * attempt leaves its measures and reactions empty.
     */
    template <int dim>
    class StepsFile : public CsvFile<dim>
    {
    public:
      StepsFile()
        : CsvFile<dim>("steps.csv")
      {}

    protected:
      void
      write_header(const RunContext<dim> &context, std::ostream &out) override
      {
        out << "step,load_factor,load_increment,";
        if (context.time.in_time())
          out << "time,";
        out << "converged,newton_iterations,relative_residual,system_dofs";
        for (const std::string &column : context.step_measure_columns)
          out << ',' << column;
        for (const unsigned int c : context.grid.reaction_columns())
          out << ",reaction_" << Names::face(c / dim) << '_'
              << Names::axis(c % dim);
        for (std::string phase : solver_phases)
          {
            std::replace(phase.begin(), phase.end(), ' ', '_');
            out << ",time_" << phase;
          }
      }

      void
      write_rows(const RunContext<dim> &context,
                 const StepRecord      &record,
                 std::ostream          &out) override
      {
        const auto times =
          context.timer.get_summary_data(TimerOutput::total_wall_time);
        out << record.step_number << ',' << std::setprecision(10)
            << record.target << ',' << record.target - record.start << ',';
        if (context.time.in_time())
          out << record.end_time << ',';
        out << (record.converged() ? 1 : 0) << ','
            << record.newton.n_iterations() << ','
            << record.newton.final_residual() << ',' << record.system_dofs;
        for (unsigned int m = 0; m < context.step_measure_columns.size(); ++m)
          {
            out << ',';
            if (record.converged())
              out << record.measures[m].value;
          }
        for (const unsigned int c : context.grid.reaction_columns())
          {
            out << ',';
            if (record.converged())
              out << record.reactions[c];
          }
        for (const auto &phase : solver_phases)
          {
            const double now = times.count(phase) ? times.at(phase) : 0.;
            out << ',' << now - previous_times[phase];
            previous_times[phase] = now;
          }
        out << '\n';
      }

    private:
      std::map<std::string, double> previous_times;
    };



    /**
     * @brief `newton.csv`: the relative residual of every Newton iterate of
     * every attempt.
     */
    template <int dim>
    class NewtonFile : public CsvFile<dim>
    {
    public:
      NewtonFile()
        : CsvFile<dim>("newton.csv",
                       "step,iteration,relative_residual,linear_iterations,"
                       "linear_solve_seconds")
      {}

    protected:
      void
      write_rows(const RunContext<dim> &,
                 const StepRecord &record,
                 std::ostream     &out) override
      {
        // Each residual, and the linear solve that followed it (none after
        // the last).
        const auto &newton = record.newton;
        for (unsigned int k = 0; k < newton.residuals.size(); ++k)
          {
            out << record.step_number << ',' << k << ',' << std::setprecision(6)
                << newton.residuals[k] << ',';
            if (k < newton.linear_solves.size())
              out << newton.linear_solves[k].iterations << ','
                  << newton.linear_solves[k].seconds;
            else
              out << ',';
            out << '\n';
          }
      }
    };



  } // namespace
  IMPM_REGISTER_POSTPROCESSOR(StepsFile, "steps file", true)
  IMPM_REGISTER_POSTPROCESSOR(NewtonFile, "newton file", true)
} // namespace impm
