#include <deal.II/base/utilities.h>

#include <impm/io/atomic_file.h>
#include <impm/postprocess/postprocessor.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace impm
{
  namespace
  {
    /**
     * @p text as a JSON string: quoted, with the quote, the backslash and
     * the control characters escaped (RFC 8259, section 7); other bytes
     * (UTF-8) as they are.
     */
    std::string
    quoted(const std::string &text)
    {
      std::string result = "\"";
      for (const char c : text)
        switch (c)
          {
            case '"':
              result += "\\\"";
              break;
            case '\\':
              result += "\\\\";
              break;
            case '\n':
              result += "\\n";
              break;
            case '\t':
              result += "\\t";
              break;
            case '\r':
              result += "\\r";
              break;
            default:
              if (static_cast<unsigned char>(c) < 0x20)
                {
                  char escape[8];
                  std::snprintf(escape,
                                sizeof(escape),
                                "\\u%04x",
                                static_cast<unsigned int>(c));
                  result += escape;
                }
              else
                result += c;
          }
      return result + "\"";
    }



    /** @p value as a JSON number (10 digits), or null if not finite (JSON
     *  has no NaN or infinity). */
    std::string
    number(const double value)
    {
      if (!std::isfinite(value))
        return "null";
      std::ostringstream out;
      out << std::setprecision(10) << value;
      return out.str();
    }



    /** Write @p items as a JSON list of strings. */
    void
    write_string_list(std::ostream &json, const std::vector<std::string> &items)
    {
      json << '[';
      for (unsigned int i = 0; i < items.size(); ++i)
        json << (i ? ", " : "") << quoted(items[i]);
      json << ']';
    }



    /**
     * @brief `summary.json`: the scene, its size, the run's totals, its
     * final state and the wall time per phase, written whole at the end.
     */
    template <int dim>
    class SummaryFile : public Postprocessor<dim>
    {
    public:
      void
      finish(const RunContext<dim>    &context,
             const RunStatistics<dim> &statistics) override
      {
        const auto &parameters = context.parameters;
        const auto  times =
          context.timer.get_summary_data(TimerOutput::total_wall_time);
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        const double peak_memory_mb =
          Utilities::MPI::max(memory.VmHWM / 1024., context.communicator);
        const auto phase_time = [&](const std::string &phase) {
          return times.count(phase) ? times.at(phase) : 0.;
        };
        const auto n_points = context.material_points.n_global_points();
        if (Utilities::MPI::this_mpi_process(context.communicator) != 0)
          return;

        std::vector<std::string> bodies;
        for (const auto &body : parameters.bodies)
          bodies.push_back(body.description());
        std::ostringstream json;
        json << std::setprecision(10);
        json << "{\n"
             << "  \"scene\": " << quoted(parameters.scene.name) << ",\n"
             << "  \"dimension\": " << dim << ",\n"
             << "  \"processes\": "
             << Utilities::MPI::n_mpi_processes(context.communicator) << ",\n"
             << "  \"bodies\": ";
        write_string_list(json, bodies);
        json << ",\n  \"effects\": ";
        write_string_list(json, context.effect_descriptions);
        json << ",\n"
             << "  \"basis\": "
             << quoted(basis_name(parameters.material_points.basis)) << ",\n"
             << "  \"material_points\": " << n_points << ",\n"
             << "  \"grid_dofs\": " << context.grid.get_dof_handler().n_dofs()
             << ",\n"
             << "  \"system_dofs_last_step\": "
             << statistics.system_dofs_last_step << ",\n"
             << "  \"load_steps\": " << context.solver.n_load_steps << ",\n"
             << "  \"newton_iterations\": "
             << statistics.total_newton_iterations << ",\n";
        for (const StepMeasure &measure : statistics.last_measures)
          json << "  " << quoted(measure.column) << ": "
               << number(measure.value) << ",\n";
        json << "  \"load_steps_taken\": " << statistics.n_converged_steps
             << ",\n"
             << "  \"load_step_cuts\": " << statistics.n_cuts << ",\n"
             << "  \"largest_point_increment_in_cells\": "
             << number(statistics.largest_point_increment) << ",\n"
             << "  \"max_reaction_imbalance\": "
             << number(statistics.max_reaction_imbalance) << ",\n"
             << "  \"max_tensile_vertical_stress\": "
             << number(statistics.final_state.max_tensile_vertical_stress)
             << ",\n"
             << "  \"total_mass\": "
             << number(statistics.final_state.total_mass) << ",\n";
        if (context.solver.estimate_condition)
          json << "  \"worst_condition_estimate\": "
               << number(statistics.worst_condition) << ",\n"
               << "  \"smallest_reciprocal_condition_estimate\": "
               << number(statistics.worst_condition > 0. ?
                           1. / statistics.worst_condition :
                           0.)
               << ",\n";
        json << "  \"formulation\": "
             << quoted(Parameters::formulation_names[static_cast<unsigned int>(
                  context.solver.formulation)])
             << ",\n"
             << "  \"residual_evaluations\": "
             << statistics.residual_evaluations << ",\n"
             << "  \"microseconds_per_point_evaluation\": "
             << number(1e6 *
                       (phase_time("stress update") + phase_time("assembly")) /
                       (double(n_points) * statistics.residual_evaluations))
             << ",\n"
             << "  \"linear_solve_share\": "
             << number(phase_time("linear solve") / statistics.wall_time)
             << ",\n"
             << "  \"peak_memory_mb\": " << number(peak_memory_mb) << ",\n"
             << "  \"wall_time\": " << number(statistics.wall_time) << ",\n"
             << "  \"wall_time_per_phase\": {";
        bool first = true;
        for (const auto &phase : solver_phases)
          if (times.count(phase))
            {
              json << (first ? "\n" : ",\n") << "    " << quoted(phase) << ": "
                   << number(times.at(phase));
              first = false;
            }
        json << "\n  }\n}\n";
        write_file_atomically(parameters.scene.output_directory +
                                "/summary.json",
                              json.str());
      }
    };
  } // namespace
  IMPM_REGISTER_POSTPROCESSOR(SummaryFile, "summary file", true)
} // namespace impm
