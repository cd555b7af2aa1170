#include <impm/base/errors.h>
#include <impm/postprocess/postprocessor.h>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace impm
{
  namespace
  {
    /**
     * The line of @p record for StepRecord::log_line(): its measures in SI
     * units if @p scales is nullptr, else in those scales.
     */
    std::string
    format_log_line(const StepRecord &record, const MeasureScales *scales)
    {
      std::ostringstream line;
      line << "step " << std::setw(3) << record.step_number << "  load "
           << std::fixed << std::setprecision(4) << record.target;
      if (record.converged())
        {
          line << "  iterations " << record.newton.n_iterations();
          for (const StepMeasure &measure : record.measures)
            {
              char buffer[32];
              if (scales == nullptr || measure.kind == MeasureKind::number)
                std::snprintf(buffer, sizeof(buffer), "%.4e", measure.value);
              else if (measure.kind == MeasureKind::count)
                std::snprintf(buffer, sizeof(buffer), "%.0f", measure.value);
              else
                std::snprintf(buffer,
                              sizeof(buffer),
                              "%.6f",
                              measure.value /
                                (measure.kind == MeasureKind::force ?
                                   scales->force :
                                 measure.kind == MeasureKind::energy ?
                                   scales->energy :
                                   scales->length));
              line << "  " << measure.label << ' ' << buffer;
            }
        }
      else
        line << "  "
             << (record.newton.outcome == NewtonOutcome::step_refused ?
                   record.newton.outcome_description() :
                   name_of(record.newton.outcome))
             << " after " << record.newton.n_iterations()
             << " iterations: step cut";
      return line.str();
    }
  } // namespace



  std::string
  StepRecord::log_line() const
  {
    return format_log_line(*this, nullptr);
  }



  std::string
  StepRecord::log_line(const MeasureScales &scales) const
  {
    return format_log_line(*this, &scales);
  }



  template <int dim>
  void
  RunStatistics<dim>::add(const StepRecord &record)
  {
    total_newton_iterations += record.newton.n_iterations();
    residual_evaluations +=
      record.newton.residuals.size() + record.newton.line_search_evaluations;
    line_search_evaluations += record.newton.line_search_evaluations;
    system_dofs_last_step = record.system_dofs;
    for (const LinearSolveReport &solve : record.newton.linear_solves)
      worst_condition = std::max(worst_condition, solve.condition_estimate);
    max_tangent_difference =
      std::max(max_tangent_difference, record.tangent_difference);
    tangent_columns_across_kinks += record.tangent_columns_across_kinks;
    if (!record.converged())
      {
        ++n_cuts;
        return;
      }
    ++n_converged_steps;
    largest_point_increment =
      std::max(largest_point_increment, record.point_increment);
    max_reaction_imbalance =
      std::max(max_reaction_imbalance, record.reaction_imbalance);
    min_newton_order =
      std::min(min_newton_order, record.newton.observed_order());
    last_reactions = record.reactions;
    last_measures  = record.measures;
  }



  template <int dim>
  void
  RunStatistics<dim>::save(RunState &state) const
  {
    state.set("statistics.converged steps",
              static_cast<double>(n_converged_steps));
    state.set("statistics.cuts", static_cast<double>(n_cuts));
    state.set("statistics.newton iterations",
              static_cast<double>(total_newton_iterations));
    state.set("statistics.residual evaluations",
              static_cast<double>(residual_evaluations));
    state.set("statistics.line search evaluations",
              static_cast<double>(line_search_evaluations));
    state.set("statistics.system dofs",
              static_cast<double>(system_dofs_last_step));
    state.set("statistics.largest point increment", largest_point_increment);
    state.set("statistics.reaction imbalance", max_reaction_imbalance);
    state.set("statistics.worst condition", worst_condition);
    state.set("statistics.newton order", min_newton_order);
    state.set("statistics.reactions", last_reactions);
    std::vector<double> values;
    std::string         names;
    for (const auto &measure : last_measures)
      {
        values.push_back(measure.value);
        names += measure.column + "|" + measure.label + "|";
      }
    state.set("statistics.measure values", values);
    state.set("statistics.measure names", names);
    state.set("statistics.wall time", wall_time);
  }



  template <int dim>
  void
  RunStatistics<dim>::load(const RunState &state)
  {
    const auto count = [&](const std::string &key) {
      return static_cast<unsigned int>(state.get_double(key));
    };
    n_converged_steps       = count("statistics.converged steps");
    n_cuts                  = count("statistics.cuts");
    total_newton_iterations = count("statistics.newton iterations");
    residual_evaluations    = count("statistics.residual evaluations");
    line_search_evaluations = count("statistics.line search evaluations");
    system_dofs_last_step   = static_cast<types::global_dof_index>(
      state.get_double("statistics.system dofs"));
    largest_point_increment =
      state.get_double("statistics.largest point increment");
    max_reaction_imbalance = state.get_double("statistics.reaction imbalance");
    worst_condition        = state.get_double("statistics.worst condition");
    min_newton_order       = state.get_double("statistics.newton order");
    last_reactions         = state.get_list("statistics.reactions");
    const auto         values = state.get_list("statistics.measure values");
    std::istringstream names(state.get_string("statistics.measure names"));
    last_measures.clear();
    for (const double value : values)
      {
        StepMeasure measure;
        std::getline(names, measure.column, '|');
        std::getline(names, measure.label, '|');
        measure.value = value;
        last_measures.push_back(measure);
      }
    wall_time = state.get_double("statistics.wall time");
  }



  template <int dim>
  void
  Postprocessor<dim>::start(const RunContext<dim> &)
  {}



  template <int dim>
  void
  Postprocessor<dim>::resume(const RunContext<dim> &, const RunState &)
  {}



  template <int dim>
  void
  Postprocessor<dim>::save(const RunContext<dim> &, RunState &) const
  {}



  template <int dim>
  void
  Postprocessor<dim>::measure_step(const RunContext<dim> &, StepRecord &)
  {}



  template <int dim>
  void
  Postprocessor<dim>::after_convergence(const RunContext<dim> &,
                                        const StepRecord &,
                                        const ConvergedStep<dim> &)
  {}



  template <int dim>
  void
  Postprocessor<dim>::after_step(const RunContext<dim> &,
                                 const StepRecord &,
                                 const RunStatistics<dim> &)
  {}



  template <int dim>
  void
  Postprocessor<dim>::finish(const RunContext<dim> &,
                             const RunStatistics<dim> &)
  {}



  template <int dim>
  void
  Postprocessor<dim>::after_failure(const RunContext<dim> &, const double)
  {}



  template <int dim>
  PostprocessorManager<dim>::PostprocessorManager(
    const RunContext<dim> &run_context)
    : context(run_context)
  {
    for (const auto &entry : PostprocessorList<dim>::entries())
      {
        if (entry.declare_parameters)
          context.prm.enter_subsection(entry.name);
        auto postprocessor = entry.create(context);
        if (entry.declare_parameters)
          context.prm.leave_subsection();
        if (postprocessor)
          postprocessors.push_back(std::move(postprocessor));
      }
    for (const auto &postprocessor : postprocessors)
      for (const std::string &column : postprocessor->step_measure_columns())
        context.step_measure_columns.push_back(column);
  }



  template <int dim>
  void
  PostprocessorManager<dim>::declare_parameters(ParameterHandler &prm)
  {
    for (const auto &entry : PostprocessorList<dim>::entries())
      if (entry.declare_parameters)
        {
          prm.enter_subsection(entry.name);
          entry.declare_parameters(prm);
          prm.leave_subsection();
        }
  }



  template <int dim>
  void
  PostprocessorManager<dim>::start()
  {
    for (const auto &postprocessor : postprocessors)
      run_collectively(context.communicator,
                       [&]() { postprocessor->start(context); });
  }



  template <int dim>
  void
  PostprocessorManager<dim>::resume(const RunState &state)
  {
    statistics.load(state);
    for (const auto &postprocessor : postprocessors)
      run_collectively(context.communicator,
                       [&]() { postprocessor->resume(context, state); });
  }



  template <int dim>
  void
  PostprocessorManager<dim>::save(RunState    &state,
                                  const double elapsed_wall_time) const
  {
    RunStatistics<dim> so_far = statistics;
    so_far.wall_time += elapsed_wall_time;
    so_far.save(state);
    for (const auto &postprocessor : postprocessors)
      postprocessor->save(context, state);
  }



  template <int dim>
  void
  PostprocessorManager<dim>::after_convergence(const StepRecord         &record,
                                               const ConvergedStep<dim> &step)
  {
    // Not wrapped in run_collectively(), which would cost a collective
    // operation per postprocessor and step: a postprocessor that writes
    // here wraps its writes itself (only the grid files do).
    for (const auto &postprocessor : postprocessors)
      postprocessor->after_convergence(context, record, step);
  }



  template <int dim>
  void
  PostprocessorManager<dim>::after_step(StepRecord &record)
  {
    if (record.converged())
      for (const auto &postprocessor : postprocessors)
        postprocessor->measure_step(context, record);
    statistics.add(record);
    // A process that fails to write stops all of them (never a hang in
    // the next collective operation).
    for (const auto &postprocessor : postprocessors)
      run_collectively(context.communicator, [&]() {
        postprocessor->after_step(context, record, statistics);
      });
  }



  template <int dim>
  void
  PostprocessorManager<dim>::finish(const double wall_time)
  {
    // A resumed run adds the time of the runs before it.
    statistics.wall_time += wall_time;
    statistics.final_state = context.material_points.measure();
    for (const auto &postprocessor : postprocessors)
      run_collectively(context.communicator,
                       [&]() { postprocessor->finish(context, statistics); });
  }



  template <int dim>
  void
  PostprocessorManager<dim>::after_failure(const double converged_load_factor)
  {
    for (const auto &postprocessor : postprocessors)
      run_collectively(context.communicator, [&]() {
        postprocessor->after_failure(context, converged_load_factor);
      });
  }



  template struct RunStatistics<2>;
  template struct RunStatistics<3>;
  template class Postprocessor<2>;
  template class Postprocessor<3>;
  template class PostprocessorManager<2>;
  template class PostprocessorManager<3>;
} // namespace impm
