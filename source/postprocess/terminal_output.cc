#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/contact/rigid_contact.h>
#include <impm/postprocess/column_solution.h>
#include <impm/postprocess/postprocessor.h>
#include <impm/postprocess/progress_clock.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tuple>

namespace impm
{
  namespace
  {
    /** A point's id and its printed values: X, u, sigma_vertical, sigma_xx
     *  (and in axisymmetry the hoop stress). */
    using PointValues = std::pair<types::particle_index, std::vector<double>>;

    /**
     * @brief What a run prints on the terminal: a line per load-step attempt
     * as it happens or, in test mode ('Testing/Enabled'), the summary a test
     * compares, the same on any number of processes: the attempts' lines
     * (their forces and lengths in the summary's scales, see
     * StepRecord::log_line(const MeasureScales &)), the run's totals and
     * checks, the final state, and the points with the lowest ids and those
     * nearest the probes. Outside test mode each line ends with the progress
     * (ProgressClock: the time reached, the share of the run done, the
     * attempt's wall time and an estimate of the time left), and the run
     * with one line of totals; 'Output/Terminal interval' N prints only
     * every N-th converged step's line (failed attempts and the last step
     * always); with 'Output/Quiet' (--quiet) only that last line is
     * printed. No wall time is ever part of the test summary.
     */
    template <int dim>
    class TerminalOutput : public Postprocessor<dim>
    {
    public:
      /** @brief The energy balance's largest error before the checkpoint
       *  (the totals name the whole run's). */
      void
      resume(const RunContext<dim> &, const RunState &state) override
      {
        try
          {
            largest_energy_error = state.get_double("terminal.energy error");
            largest_energy_error_step = static_cast<unsigned int>(
              state.get_double("terminal.energy error step"));
          }
        catch (const CollectiveError &)
          {} // a checkpoint written before 2026-11-29 holds none
      }

      void
      save(const RunContext<dim> &, RunState &state) const override
      {
        state.set("terminal.energy error", largest_energy_error);
        state.set("terminal.energy error step",
                  static_cast<double>(largest_energy_error_step));
      }

      void
      after_step(const RunContext<dim> &context,
                 const StepRecord      &record,
                 const RunStatistics<dim> &) override
      {
        if (context.testing.enabled)
          log_lines.push_back(record.log_line(scales(context)));
        else if (Utilities::MPI::this_mpi_process(context.communicator) == 0)
          {
            if (record.converged())
              for (const StepMeasure &measure : record.measures)
                if (measure.column == "energy_error" &&
                    !(std::abs(measure.value) <= largest_energy_error))
                  {
                    largest_energy_error      = std::abs(measure.value);
                    largest_energy_error_step = record.step_number;
                  }
            const std::string progress = clock.after(record);
            const bool        shown =
              !record.converged() || record.last ||
              record.step_number % context.output.terminal_interval == 0;
            if (!context.output.quiet && shown)
              std::cout << record.log_line() << "  residual " << std::scientific
                        << std::setprecision(2)
                        << record.newton.final_residual() << std::defaultfloat
                        << progress << std::endl;
          }
      }

      void
      finish(const RunContext<dim>    &context,
             const RunStatistics<dim> &statistics) override
      {
        if (!context.testing.enabled)
          {
            if (Utilities::MPI::this_mpi_process(context.communicator) == 0)
              print_totals(context, statistics);
            return;
          }
        const auto   points    = printed_points(context);
        const double deviation = context.output.analytical_solution ==
                                     Parameters::AnalyticalSolution::column ?
                                   ColumnSolution<dim>::max_deviation(context) :
                                   -1.;
        if (Utilities::MPI::this_mpi_process(context.communicator) != 0)
          return;
        print_run(context, statistics, deviation);
        print_points(context, points);
        std::cout << std::flush;
      }

    private:
      /**
       * @brief The run's last line outside test mode: "Finished 'column':
       * 50 load steps (2 cuts), 102 Newton iterations, wall time 1.21 s
       * (resumed runs included); files in output/".
       */
      void
      print_totals(const RunContext<dim>    &context,
                   const RunStatistics<dim> &statistics) const
      {
        std::cout << "Finished '" << context.parameters.scene.name
                  << "': " << statistics.n_converged_steps << " load steps ("
                  << statistics.n_cuts
                  << (statistics.n_cuts == 1 ? " cut), " : " cuts), ")
                  << statistics.total_newton_iterations << " Newton iterations"
                  << (statistics.line_search_evaluations > 0 ?
                        " (and " +
                          std::to_string(statistics.line_search_evaluations) +
                          " line-search residuals)" :
                        std::string())
                  << ", wall time " << format_duration(statistics.wall_time);
        // A scene with inertia: the energy balance's largest error, which
        // the warnings on standard error report as it happens.
        if (largest_energy_error >= 0.)
          {
            const double percent = 100. * largest_energy_error;
            char         text[32];
            std::snprintf(text,
                          sizeof(text),
                          percent >= 10. ? "%.0f" :
                          percent >= 1.  ? "%.1f" :
                                           "%.2g",
                          percent);
            std::cout << ", energy balance error at most " << text
                      << " % (step " << largest_energy_error_step << ")";
          }
        std::cout << "; files in " << context.parameters.scene.output_directory
                  << "/" << std::endl;
      }

      /** The summary's scales: L and S L^(dim-1) of the scene's Testing
       *  subsection. */
      static MeasureScales
      scales(const RunContext<dim> &context)
      {
        const auto &testing = context.testing;
        return {testing.reference_length,
                testing.reference_stress *
                  std::pow(testing.reference_length, static_cast<int>(dim) - 1),
                testing.reference_stress *
                  std::pow(testing.reference_length, static_cast<int>(dim))};
      }

      /** The values of the points to print (on rank 0; collective). */
      std::vector<PointValues>
      printed_points(const RunContext<dim> &context) const;

      /** Print the log lines, totals, checks and final state. */
      void
      print_run(const RunContext<dim>    &context,
                const RunStatistics<dim> &statistics,
                const double              column_deviation) const;

      /** Print the final force on each rigid body (scenes with rigid
       *  bodies), in the scales @p force and @p length. */
      void
      print_rigid_bodies(const RunContext<dim> &context,
                         const double           force,
                         const double           length) const;

      /** Print one line per point. */
      void
      print_points(const RunContext<dim>          &context,
                   const std::vector<PointValues> &points) const;

      /** The test summary's lines per attempt. */
      std::vector<std::string> log_lines;
      /** The largest relative error of the energy balance over the run's
       *  converged steps (negative: none measured), and its step. */
      double       largest_energy_error      = -1.;
      unsigned int largest_energy_error_step = 0;
      /** The attempts' wall times and the estimate of the time left. */
      ProgressClock clock;
    };



    template <int dim>
    std::vector<PointValues>
    TerminalOutput<dim>::printed_points(const RunContext<dim> &context) const
    {
      const auto              &testing = context.testing;
      std::vector<PointValues> local;
      for (const auto &point : context.material_points.particles())
        {
          const PointState<dim>       state(point.get_properties());
          const Point<dim>            X   = state.initial_position();
          const double                J   = state.jacobian();
          const SymmetricTensor<2, 3> tau = state.kirchhoff_stress();
          std::vector<double>         values;
          for (unsigned int d = 0; d < dim; ++d)
            values.push_back(X[d]);
          for (unsigned int d = 0; d < dim; ++d)
            values.push_back(point.get_location()[d] - X[d]);
          values.push_back(tau[dim - 1][dim - 1] / J);
          values.push_back(tau[0][0] / J);
          if (context.parameters.grid.axisymmetric)
            values.push_back(tau[2][2] / J);
          local.emplace_back(point.get_id(), values);
        }
      // The points nearest to the probe positions (smallest distance, then
      // smallest id), found among all processes' points.
      std::vector<PointValues> probed;
      for (const auto &probe : testing.probes)
        {
          std::tuple<double, types::particle_index, std::vector<double>>
            nearest(std::numeric_limits<double>::max(), 0, {});
          for (const auto &[id, values] : local)
            {
              double distance = 0.;
              for (unsigned int d = 0; d < dim; ++d)
                distance += std::pow(values[d] - probe[d], 2);
              nearest =
                std::min(nearest, std::make_tuple(distance, id, values));
            }
          const auto all =
            Utilities::MPI::all_gather(context.communicator, nearest);
          const auto best = *std::min_element(all.begin(), all.end());
          probed.emplace_back(std::get<1>(best), std::get<2>(best));
        }
      // The lowest ids of each process, merged on rank 0.
      std::sort(local.begin(), local.end());
      if (local.size() > testing.n_printed_points)
        local.resize(testing.n_printed_points);
      const auto gathered =
        Utilities::MPI::gather(context.communicator, local, 0);
      std::vector<PointValues> all;
      for (const auto &part : gathered)
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(), all.end());
      if (all.size() > testing.n_printed_points)
        all.resize(testing.n_printed_points);
      all.insert(all.end(), probed.begin(), probed.end());
      return all;
    }



    template <int dim>
    void
    TerminalOutput<dim>::print_rigid_bodies(const RunContext<dim> &context,
                                            const double           force,
                                            const double           length) const
    {
      const RigidContact<dim> *contact =
        context.couplings.template find<RigidContact<dim>>();
      if (contact == nullptr)
        return;
      char buffer[160];
      for (unsigned int k = 0; k < contact->bodies().size(); ++k)
        {
          const auto &body_force = contact->body_forces()[k];
          std::cout << "final force on " << contact->bodies()[k].name << ":";
          for (unsigned int d = 0; d < dim; ++d)
            {
              std::snprintf(buffer,
                            sizeof(buffer),
                            " %s %.6f",
                            Names::axes[d],
                            body_force.total[d] / force);
              std::cout << buffer;
            }
          std::snprintf(buffer,
                        sizeof(buffer),
                        ", normal part %.6f, friction part %.6f, %u probes "
                        "in contact, %u slipping\n",
                        body_force.normal.norm() / force,
                        body_force.tangential.norm() / force,
                        body_force.n_contacts,
                        body_force.n_slipping);
          std::cout << buffer;
          const auto &body = contact->bodies()[k];
          if (body.force_components.empty())
            continue;
          std::cout << "final displacement of " << body.name
                    << " (force-driven):";
          for (const unsigned int d : body.force_components)
            {
              std::snprintf(buffer,
                            sizeof(buffer),
                            " %s %.6f",
                            Names::axes[d],
                            contact->pushed_displacement(k)[d] / length);
              std::cout << buffer;
            }
          std::cout << '\n';
        }
    }



    template <int dim>
    void
    TerminalOutput<dim>::print_run(const RunContext<dim>    &context,
                                   const RunStatistics<dim> &statistics,
                                   const double column_deviation) const
    {
      const auto  &state  = statistics.final_state;
      const double length = context.testing.reference_length;
      const double stress = context.testing.reference_stress;
      const double force  = scales(context).force;
      for (const auto &line : log_lines)
        std::cout << line << '\n';
      // No pair of residuals near the solution (a step converged in one or
      // two iterations, or at round-off) leaves the order unmeasured.
      const double minimum_order = context.testing.minimum_newton_order;
      std::cout << "observed Newton order near the solution >= "
                << minimum_order << " in every step"
                << (context.couplings.template find<RigidContact<dim>>() !=
                        nullptr ?
                      " (pairs of iterates between which a contact changed "
                      "state not counted)" :
                      "")
                << ": "
                << (!NewtonRecord::is_measured(statistics.min_newton_order) ?
                      "not measured" :
                    statistics.min_newton_order >= minimum_order ? "yes" :
                                                                   "NO")
                << '\n';
      const auto &testing = context.testing;
      if (testing.check_tangent)
        std::cout
          << "every assembled matrix agrees with central differences "
             "of the internal force to 1e-6: "
          << (statistics.max_tangent_difference < 0. ?
                "not checked" :
              statistics.max_tangent_difference <= 1e-6 ?
                "yes" :
                "NO (" + number_text(statistics.max_tangent_difference) + ")")
          << (statistics.tangent_columns_across_kinks > 0 ?
                " (" + std::to_string(statistics.tangent_columns_across_kinks) +
                  (statistics.tangent_columns_across_kinks == 1 ? " column" :
                                                                  " columns") +
                  " whose perturbation changed a contact's state not "
                  "compared)" :
                std::string())
          << '\n';
      std::cout << "scales: L = " << testing.reference_length
                << " m, S = " << testing.reference_stress
                << " Pa; extents and displacements in L, stresses in S, "
                   "reactions in S L"
                << (dim == 3 ? "^2" : "") << '\n';
      std::cout << "material points: "
                << context.material_points.n_global_points()
                << ", total Newton iterations: "
                << statistics.total_newton_iterations
                << ", load-step cuts: " << statistics.n_cuts;
      if (statistics.line_search_evaluations > 0)
        std::cout << ", line-search residuals: "
                  << statistics.line_search_evaluations;
      std::cout << '\n';
      char buffer[160];
      std::snprintf(buffer,
                    sizeof(buffer),
                    "total mass: %.8e (initial %.8e)\n",
                    state.total_mass,
                    context.material_points.initial_mass());
      std::cout << buffer;
      const auto &reaction_columns = context.grid.reaction_columns();
      // The load is carried by the faces' reactions or by couplings that
      // hold the material (rigid bodies, springs).
      bool carried_by_couplings = false;
      for (const auto &coupling : context.couplings.list())
        for (unsigned int d = 0; d < dim; ++d)
          carried_by_couplings =
            carried_by_couplings || coupling->holds_material(d);
      if ((!reaction_columns.empty() || carried_by_couplings) &&
          context.has_force_effects)
        std::cout << "reactions balance the load to 1e-8 in every step: "
                  << (statistics.max_reaction_imbalance < 1e-8 ? "yes" : "NO")
                  << '\n';
      for (unsigned int d = 0; d < dim; ++d)
        {
          std::snprintf(buffer,
                        sizeof(buffer),
                        "extent in %s: initial points [%.6f, %.6f], final "
                        "[%.6f, %.6f]\n",
                        Names::axes[d],
                        state.initial_min[d] / length,
                        state.initial_max[d] / length,
                        state.current_min[d] / length,
                        state.current_max[d] / length);
          std::cout << buffer;
        }
      if (testing.reference_extent.size() == dim)
        {
          double distance = 0.;
          for (unsigned int d = 0; d < dim; ++d)
            distance = std::max(distance,
                                std::abs(state.current_max[d] -
                                         testing.reference_extent[d]));
          std::cout << "final extent within " << testing.reference_tolerance
                    << " m of the reference: "
                    << (distance <= testing.reference_tolerance ? "yes" : "NO")
                    << '\n';
        }
      std::snprintf(buffer,
                    sizeof(buffer),
                    "largest vertical stress (tension positive): %.6f\n",
                    state.max_tensile_vertical_stress / stress);
      std::cout << buffer;
      if (column_deviation >= 0.)
        {
          std::snprintf(buffer,
                        sizeof(buffer),
                        "stress oscillation max |sigma_zz - exact| / "
                        "(rho_0 g l0): %.4e\n",
                        column_deviation);
          std::cout << buffer;
        }
      if (context.solver.estimate_condition)
        {
          std::snprintf(buffer,
                        sizeof(buffer),
                        "worst condition estimate: %.0e\n",
                        statistics.worst_condition);
          std::cout << buffer;
        }
      for (const unsigned int c : reaction_columns)
        {
          std::snprintf(buffer,
                        sizeof(buffer),
                        "final reaction on face %s, component %s: %.6f\n",
                        Names::faces[c / dim],
                        Names::axes[c % dim],
                        statistics.last_reactions[c] / force);
          std::cout << buffer;
        }
      print_rigid_bodies(context, force, length);
    }



    template <int dim>
    void
    TerminalOutput<dim>::print_points(
      const RunContext<dim>          &context,
      const std::vector<PointValues> &points) const
    {
      const auto  &testing = context.testing;
      const int    digits  = testing.significant_digits;
      const double length  = testing.reference_length;
      const double stress  = testing.reference_stress;
      char         buffer[64];
      for (const auto &[id, values] : points)
        {
          std::cout << "point " << id << ": X =";
          for (unsigned int d = 0; d < dim; ++d)
            std::cout << ' ' << std::setprecision(digits) << values[d];
          std::cout << ", u =";
          for (unsigned int d = 0; d < dim; ++d)
            {
              std::snprintf(buffer,
                            sizeof(buffer),
                            " %.*f",
                            digits,
                            values[dim + d] / length);
              std::cout << buffer;
            }
          // The stresses (in axisymmetry the hoop stress last).
          const char *names[] = {"sigma_vertical", "sigma_xx", "sigma_hoop"};
          for (unsigned int k = 0; 2 * dim + k < values.size(); ++k)
            {
              std::snprintf(buffer,
                            sizeof(buffer),
                            "%.*f",
                            digits,
                            values[2 * dim + k] / stress);
              std::cout << ", " << names[k] << " = " << buffer;
            }
          std::cout << '\n';
        }
    }
  } // namespace
  IMPM_REGISTER_POSTPROCESSOR(TerminalOutput, "terminal output", true)
} // namespace impm
