#include <deal.II/base/utilities.h>

#include <impm/base/version.h>
#include <impm/io/atomic_file.h>
#include <impm/postprocess/postprocessor.h>

#include <nlohmann/json.hpp>

#include <string>

namespace impm
{
  namespace
  {
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

        // nlohmann::json quotes and escapes the strings (a scene's name
        // may hold a quote or a backslash; bytes that are not UTF-8 become
        // U+FFFD), writes a non-finite number as null and keeps the order
        // of the keys (ordered_json).
        nlohmann::ordered_json json;
        json["scene"]           = parameters.scene.name;
        json["impm_version"]    = Version::impm;
        json["impm_revision"]   = Version::revision;
        json["deal_ii_version"] = Version::deal_ii;
        json["dimension"]       = dim;
        json["processes"] =
          Utilities::MPI::n_mpi_processes(context.communicator);
        json["bodies"] = nlohmann::ordered_json::array();
        for (const auto &body : parameters.bodies)
          json["bodies"].push_back(body.description());
        json["effects"]         = context.effect_descriptions;
        json["basis"]           = basis_name(parameters.material_points.basis);
        json["material_points"] = n_points;
        json["grid_dofs"]       = context.grid.get_dof_handler().n_dofs();
        json["system_dofs_last_step"] = statistics.system_dofs_last_step;
        json["load_steps"]            = context.solver.n_load_steps;
        json["newton_iterations"]     = statistics.total_newton_iterations;
        for (const StepMeasure &measure : statistics.last_measures)
          json[measure.column] = measure.value;
        json["load_steps_taken"] = statistics.n_converged_steps;
        json["load_step_cuts"]   = statistics.n_cuts;
        json["largest_point_increment_in_cells"] =
          statistics.largest_point_increment;
        json["max_reaction_imbalance"] = statistics.max_reaction_imbalance;
        json["max_tensile_vertical_stress"] =
          statistics.final_state.max_tensile_vertical_stress;
        json["total_mass"] = statistics.final_state.total_mass;
        if (context.solver.estimate_condition)
          {
            json["worst_condition_estimate"] = statistics.worst_condition;
            json["smallest_reciprocal_condition_estimate"] =
              statistics.worst_condition > 0. ?
                1. / statistics.worst_condition :
                0.;
          }
        json["formulation"] =
          Parameters::formulation_names[static_cast<unsigned int>(
            context.solver.formulation)];
        json["residual_evaluations"]    = statistics.residual_evaluations;
        json["line_search_evaluations"] = statistics.line_search_evaluations;
        json["microseconds_per_point_evaluation"] =
          1e6 * (phase_time("stress update") + phase_time("assembly")) /
          (double(n_points) * statistics.residual_evaluations);
        json["linear_solve_share"] =
          phase_time("linear solve") / statistics.wall_time;
        json["peak_memory_mb"]      = peak_memory_mb;
        json["wall_time"]           = statistics.wall_time;
        json["wall_time_per_phase"] = nlohmann::ordered_json::object();
        for (const auto &phase : solver_phases)
          if (times.count(phase))
            json["wall_time_per_phase"][phase] = times.at(phase);
        write_file_atomically(
          parameters.scene.output_directory + "/summary.json",
          json.dump(
            2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) +
            "\n");
      }
    };
  } // namespace
  IMPM_REGISTER_POSTPROCESSOR(SummaryFile, "summary file", true)
} // namespace impm
