#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/core/point_properties.h>
#include <impm/core/scene_checks.h>
#include <impm/io/atomic_file.h>
#include <impm/io/output_directory.h>
#include <impm/simulator/mpm_solver.h>
#include <impm/simulator/strength_reduction.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace impm
{
  namespace Parameters
  {
    void
    StrengthReduction::declare_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Bool;
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;
      prm.enter_subsection("Strength reduction");
      prm.declare_entry(
        "Enabled",
        "false",
        Bool(),
        "Search the scene's factor of safety F: run the scene with every "
        "body's strength divided by trial factors (c/F and tan(phi)/F, a "
        "yield stress over F, Cam-clay's M through its friction angle) until "
        "one trial carries the full load and one fails (a load step that "
        "cannot be solved at 'Solver/Minimum load step'), then bisect. Each "
        "trial writes into trial_K below the output directory; "
        "factor_of_safety.csv lists them.");
      prm.declare_entry("First factor",
                        "1",
                        Double(1e-6, 1e6),
                        "The first trial factor F (> 0).");
      prm.declare_entry("Bracket ratio",
                        "1.5",
                        Double(1.001, 100.),
                        "While no trial has stood or none has failed, the "
                        "next factor is the last one times this ratio (after "
                        "a trial that stood) or over it (after one that "
                        "failed).");
      prm.declare_entry("Tolerance",
                        "0.01",
                        Double(1e-6, 1e6),
                        "The search stops when the largest factor that stood "
                        "and the smallest that failed differ by at most this "
                        "much; F is reported as their mean.");
      prm.declare_entry(
        "Failure displacement",
        "0",
        Double(0.),
        "A trial fails when a point has moved farther than this from its "
        "initial position, in m (0: no limit), checked after every converged "
        "load step: a material point slope past its limit slides into a "
        "flatter shape that stands, so a load step without equilibrium "
        "alone finds a factor too high. Choose it well above the "
        "displacements of the standing slope (a few per cent of its "
        "height).");
      prm.declare_entry("Maximum trials",
                        "30",
                        Integer(1, 1000),
                        "The most trials the search runs; beyond, it stops "
                        "with an error that gives the bracket reached.");
      prm.leave_subsection();
    }



    void
    StrengthReduction::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Strength reduction");
      enabled              = prm.get_bool("Enabled");
      first_factor         = prm.get_double("First factor");
      bracket_ratio        = prm.get_double("Bracket ratio");
      tolerance            = prm.get_double("Tolerance");
      maximum_trials       = prm.get_integer("Maximum trials");
      failure_displacement = prm.get_double("Failure displacement");
      prm.leave_subsection();
    }
  } // namespace Parameters



  namespace
  {
    /**
     * The terminal lines of rank 0 go to a file while a trial runs (the
     * terminal shows one line per trial), and come back at the end of the
     * scope, also when the trial throws.
     */
    class TerminalToFile
    {
    public:
      TerminalToFile(const std::string &path, const bool active)
      {
        if (!active)
          return;
        file.open(path);
        if (!file)
          throw std::runtime_error("Cannot write " + path + ".");
        saved = std::cout.rdbuf(file.rdbuf());
      }

      ~TerminalToFile()
      {
        if (saved != nullptr)
          std::cout.rdbuf(saved);
      }

      TerminalToFile(const TerminalToFile &) = delete;
      TerminalToFile &
      operator=(const TerminalToFile &) = delete;

    private:
      std::ofstream   file;
      std::streambuf *saved = nullptr;
    };



    /** The largest distance of a point from its initial position. */
    template <int dim>
    double
    largest_displacement(const MaterialPoints<dim> &points,
                         const MPI_Comm             communicator)
    {
      double largest = 0.;
      for (const auto &point : points.particles())
        {
          const PointState<dim> state(point.get_properties());
          largest =
            std::max(largest,
                     point.get_location().distance(state.initial_position()));
        }
      return Utilities::MPI::max(largest, communicator);
    }



    /** @p value with @p digits decimals. */
    std::string
    fixed(const double value, const int digits)
    {
      std::ostringstream out;
      out << std::fixed << std::setprecision(digits) << value;
      return out.str();
    }
  } // namespace



  template <int dim>
  bool
  StrengthReduction<dim>::enabled(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Strength reduction");
    const bool result = prm.get_bool("Enabled");
    prm.leave_subsection();
    return result;
  }



  template <int dim>
  typename StrengthReduction<dim>::Trial
  StrengthReduction<dim>::run_trial(dealii::ParameterHandler &prm,
                                    const RunOptions         &options,
                                    const Parameters::StrengthReduction &search,
                                    const std::string &output_directory,
                                    const std::string &directory,
                                    const double       factor,
                                    const MPI_Comm     communicator)
  {
    RunParameters<dim> settings;
    settings.parse_parameters(prm);
    settings.scene.scene.file             = options.scene_file;
    settings.scene.scene.output_directory = output_directory + "/" + directory;
    // The trial's directory is new, and its terminal.txt is opened before
    // the run takes the directory over: kept there, not refused.
    settings.scene.scene.overwrite_existing_output = true;
    for (auto &body : settings.scene.bodies)
      body.material = body.material->with_reduced_strength(factor);

    Trial trial;
    trial.factor    = factor;
    trial.directory = directory;
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    run_collectively(communicator, [&]() {
      if (root)
        std::filesystem::create_directories(
          settings.scene.scene.output_directory);
    });
    dealii::Timer timer(communicator);
    timer.start();
    {
      TerminalToFile terminal(settings.scene.scene.output_directory +
                                "/terminal.txt",
                              root);
      MPMSolver<dim> solver(settings,
                            prm,
                            EffectRegistry::create_enabled<dim>(prm),
                            communicator);
      if (search.failure_displacement > 0.)
        solver.set_stop_condition([&]() -> std::string {
          const double moved =
            largest_displacement(solver.points(), communicator);
          if (moved <= search.failure_displacement)
            return "";
          std::ostringstream reason;
          reason << "a point moved " << moved
                 << " m, more than 'Strength reduction/Failure displacement' "
                 << "= " << search.failure_displacement << " m";
          return reason.str();
        });
      try
        {
          solver.run();
          trial.stands      = solver.stopped_by_condition().empty();
          trial.load_factor = solver.converged_load_factor();
          if (!trial.stands)
            trial.failure = "displacement";
        }
      catch (const LoadStepFailure &failure)
        {
          trial.stands      = false;
          trial.failure     = "load step";
          trial.load_factor = failure.converged_load_factor;
          if (root)
            std::cout << "Error: " << one_line_message(failure) << std::endl;
        }
      catch (const PointLeftGrid &failure)
        {
          // The sliding mass ran out of the grid: it did not stand.
          trial.stands      = false;
          trial.failure     = "left the grid";
          trial.load_factor = solver.converged_load_factor();
          if (root)
            std::cout << "Error: " << one_line_message(failure) << std::endl;
        }
      trial.converged_steps = solver.last_converged_step();
      trial.largest_displacement =
        largest_displacement(solver.points(), communicator);
    }
    timer.stop();
    trial.wall_time = timer.wall_time();
    return trial;
  }



  template <int dim>
  void
  StrengthReduction<dim>::check_scene(dealii::ParameterHandler &prm,
                                      const RunOptions         &options,
                                      const RunParameters<dim> &settings)
  {
    if (options.resume)
      throw InputError("A strength reduction cannot be resumed: its trials "
                       "are whole runs of the scene (run it again).");
    if (options.stop_after_step > 0)
      throw InputError("--stop-after-step cannot stop a strength reduction's "
                       "trials: each must run to its end or its failure.");
    prm.enter_subsection("Inertia");
    const bool inertia = prm.get_bool("Enabled");
    prm.leave_subsection();
    if (inertia)
      throw InputError("'Strength reduction/Enabled' = 'true' needs a "
                       "quasi-static scene: its failure criterion is a load "
                       "step without equilibrium; disable 'Inertia/Enabled'.");
    // The failure criterion reads the points' displacement, which points
    // held where they were seeded never show.
    if (!settings.scene.material_points.move_points)
      throw InputError(
        "'Strength reduction/Enabled' = 'true' needs 'Material points/Move "
        "points' = true: a trial fails when the points' displacement does "
        "not settle, and points held where they were seeded show none.");
    // Every body's material must say how it weakens (a model that does not
    // throws here), and one at least must weaken: an elastic model comes
    // back unchanged, description and all.
    bool weakens = false;
    for (const auto &body : settings.scene.bodies)
      weakens =
        weakens || body.material->with_reduced_strength(2.)->description() !=
                     body.material->description();
    if (!weakens)
      throw InputError("Strength reduction: no body's material has a "
                       "strength to reduce (the bodies are elastic), so no "
                       "trial could fail.");
    // A prescribed motion moves the material whatever its strength: a
    // trial fails only when the motion is beyond the material's reach.
    const auto refuse_motion = [](const std::string &entry) {
      throw InputError(
        "Strength reduction: '" + entry +
        "' prescribes a motion, which moves the material whatever its "
        "strength, so no factor of safety follows from it; load the scene "
        "by forces (gravity, a traction, a force-driven rigid body).");
    };
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (settings.scene.grid.face_displacements[f].norm() > 0.)
        refuse_motion("Grid/Displacement " + Names::face(f));
    for (const auto &body : settings.scene.rigid_bodies)
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (body.displacement[d] != 0. &&
              std::find(body.force_components.begin(),
                        body.force_components.end(),
                        d) == body.force_components.end())
            refuse_motion(body.name + "/Displacement");
        if (body.rotation_angle != 0.)
          refuse_motion(body.name + "/Rotation");
      }
  }



  template <int dim>
  void
  StrengthReduction<dim>::prepare_directory(const std::string        &directory,
                                            const RunParameters<dim> &settings,
                                            const RunOptions         &options,
                                            const MPI_Comm communicator)
  {
    const Parameters::Scene &scene = settings.scene.scene;
    OutputDirectory::prepare(directory,
                             scene.name,
                             options.scene_file,
                             scene.overwrite_existing_output ?
                               OutputDirectory::ExistingRun::overwrite :
                               OutputDirectory::ExistingRun::refuse,
                             communicator);
    // OutputDirectory::prepare() removes the trials and links of an
    // earlier search (not those it did not write).
  }



  template <int dim>
  void
  StrengthReduction<dim>::write_table(const std::vector<Trial> &trials,
                                      const std::string        &directory,
                                      const MPI_Comm            communicator)
  {
    run_collectively(communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      std::ostringstream table;
      table << "trial,factor,stands,failure,load_factor,converged_steps,"
               "largest_displacement,wall_time,directory\n";
      for (std::size_t k = 0; k < trials.size(); ++k)
        table << k + 1 << ',' << fixed(trials[k].factor, 8) << ','
              << (trials[k].stands ? 1 : 0) << ',' << trials[k].failure << ','
              << fixed(trials[k].load_factor, 8) << ','
              << trials[k].converged_steps << ','
              << trials[k].largest_displacement << ','
              << fixed(trials[k].wall_time, 3) << ',' << trials[k].directory
              << '\n';
      write_file_atomically(directory + "/factor_of_safety.csv", table.str());
    });
  }



  template <int dim>
  std::string
  StrengthReduction<dim>::describe(const Trial       &trial,
                                   const unsigned int number,
                                   const bool         testing)
  {
    std::ostringstream line;
    line << "trial " << std::setw(2) << number
         << ": F = " << fixed(trial.factor, 6)
         << (trial.stands ? "  stands" : "  fails (" + trial.failure + ")")
         << "  (load " << fixed(trial.load_factor, 4) << ", "
         << trial.converged_steps << " steps, largest displacement "
         << std::setprecision(4) << trial.largest_displacement << " m)";
    if (!testing)
      line << "  " << fixed(trial.wall_time, 1) << " s";
    return line.str();
  }



  template <int dim>
  void
  StrengthReduction<dim>::refuse_failure_without_strength(
    const Trial       &previous,
    const Trial       &trial,
    const std::string &directory)
  {
    if (trial.stands || previous.stands || trial.failure != "displacement" ||
        previous.failure != "displacement" ||
        previous.load_factor != trial.load_factor ||
        std::abs(previous.largest_displacement - trial.largest_displacement) >
          1e-9 * trial.largest_displacement)
      return;
    std::ostringstream message;
    message << "Strength reduction: the trials at F = "
            << fixed(previous.factor, 6)
            << " and F = " << fixed(trial.factor, 6)
            << " failed alike (a point moved " << trial.largest_displacement
            << " m by the load factor " << trial.load_factor
            << " in both): the displacement does not depend on the "
               "strength, so it is elastic; raise 'Strength reduction/"
               "Failure displacement' above it or stiffen the material (see "
               "factor_of_safety.csv in '"
            << directory << "').";
    throw CollectiveError(message.str());
  }



  template <int dim>
  void
  StrengthReduction<dim>::run(dealii::ParameterHandler &prm,
                              const RunOptions         &options,
                              const MPI_Comm            communicator)
  {
    Parameters::StrengthReduction search;
    search.parse_parameters(prm);
    RunParameters<dim> settings;
    settings.parse_parameters(prm);
    SceneChecks::check(settings.scene, communicator);
    check_scene(prm, options, settings);
    const std::string directory = settings.scene.scene.output_directory;
    prepare_directory(directory, settings, options, communicator);

    const bool root    = Utilities::MPI::this_mpi_process(communicator) == 0;
    const bool testing = settings.testing.enabled;
    // --quiet: the result line only.
    dealii::ConditionalOStream out(std::cout, root && !settings.output.quiet);
    dealii::ConditionalOStream result_out(std::cout, root);
    out << "Strength reduction of scene '" << settings.scene.scene.name << "' ("
        << dim
        << "D): c/F and tan(phi)/F, trials until one stands and one fails, "
        << "then bisection to a bracket of " << search.tolerance << std::endl;

    // The trials, and the largest that stood and the smallest that failed
    // (the bracket, once both exist).
    std::vector<Trial>         trials;
    std::optional<std::size_t> stable, failed;
    const auto factor_of = [&](const std::optional<std::size_t> &k) {
      return trials[*k].factor;
    };
    dealii::Timer total(communicator);
    total.start();
    double factor = search.first_factor;
    while (!(stable && failed &&
             factor_of(failed) - factor_of(stable) <= search.tolerance))
      {
        if (stable && failed)
          factor = 0.5 * (factor_of(stable) + factor_of(failed));
        if (trials.size() >= search.maximum_trials)
          throw CollectiveError(
            "The strength reduction ran 'Maximum trials' = " +
            std::to_string(search.maximum_trials) + " trials without " +
            (!stable ? "one that stood (the smallest factor tried, " +
                         fixed(factor_of(failed), 6) + ", failed)" :
             !failed ? "one that failed (the largest factor tried, " +
                         fixed(factor_of(stable), 6) + ", stood)" :
                       "reaching the tolerance (the bracket is [" +
                         fixed(factor_of(stable), 6) + ", " +
                         fixed(factor_of(failed), 6) + "])") +
            "; see factor_of_safety.csv in '" + directory + "'.");
        char name[32];
        std::snprintf(name, sizeof(name), "trial_%02zu", trials.size() + 1);
        trials.push_back(run_trial(
          prm, options, search, directory, name, factor, communicator));
        const Trial &trial = trials.back();
        write_table(trials, directory, communicator);
        out << describe(trial, trials.size(), testing) << std::endl;
        if (trials.size() > 1)
          refuse_failure_without_strength(trials[trials.size() - 2],
                                          trial,
                                          directory);
        std::optional<std::size_t> &end = trial.stands ? stable : failed;
        if (!end ||
            (trial.stands ? factor > factor_of(end) : factor < factor_of(end)))
          end = trials.size() - 1;
        if (!stable || !failed)
          factor = trial.stands ? factor * search.bracket_ratio :
                                  factor / search.bracket_ratio;
        // A trial that stands at or above a factor that failed: the
        // outcome is not monotonic in F, and no bracket can be trusted.
        else if (factor_of(stable) >= factor_of(failed))
          throw CollectiveError(
            "The strength reduction is not monotonic: the scene stands at "
            "F = " +
            fixed(factor_of(stable), 6) +
            " but fails at F = " + fixed(factor_of(failed), 6) +
            " (see factor_of_safety.csv in '" + directory +
            "'); refine the load steps or lower 'Solver/Minimum load step'.");
      }
    total.stop();

    run_collectively(communicator, [&]() {
      if (!root)
        return;
      namespace fs = std::filesystem;
      fs::create_directory_symlink(trials[*stable].directory,
                                   directory + "/last_stable");
      fs::create_directory_symlink(trials[*failed].directory,
                                   directory + "/first_failed");
    });
    result_out << "Factor of safety: F = "
               << fixed(0.5 * (factor_of(stable) + factor_of(failed)), 4)
               << " (stands at F = " << fixed(factor_of(stable), 4)
               << ", fails at F = " << fixed(factor_of(failed), 4) << "; "
               << trials.size() << " trials";
    if (!testing)
      result_out << ", " << fixed(total.wall_time(), 1) << " s";
    result_out << ")" << std::endl;
  }



  template class StrengthReduction<2>;
  template class StrengthReduction<3>;
} // namespace impm
