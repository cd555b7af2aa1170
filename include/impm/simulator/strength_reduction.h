#ifndef impm_simulator_strength_reduction_h
#define impm_simulator_strength_reduction_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <impm/simulator/run.h>

#include <string>
#include <vector>

namespace impm
{
  namespace Parameters
  {
    /**
     * @brief The subsection `Strength reduction`: search the factor of
     * safety of a scene.
     */
    struct StrengthReduction
    {
      /** Whether the scene asks for its factor of safety. */
      bool enabled = false;
      /** The first trial factor. */
      double first_factor = 1.;
      /** The ratio between trials while no bracket is found. */
      double bracket_ratio = 1.5;
      /** The bracket's width, in F, at which the search stops. */
      double tolerance = 0.01;
      /** The most trials the search may run. */
      unsigned int maximum_trials = 30;
      /** A trial fails when a point moves farther than this, in m (0:
       *  no limit). */
      double failure_displacement = 0.;

      /** @brief Declare the subsection's entries. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read them (one line naming a value out of range). */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters



  /**
   * @brief The factor of safety of a scene by strength reduction.
   *
   * A trial runs the whole scene (its load steps, from its initial state)
   * with every body's material weakened by a factor F
   * (Material::with_reduced_strength(): c/F and tan(phi)/F, a yield stress
   * over F, Cam-clay's M through its friction angle). The trial <em>stands
   * </em> when every load step converges up to the full load, and
   * <em>fails</em> when a load step cannot be solved after the step control
   * has cut it to 'Solver/Minimum load step' (LoadStepFailure), or when a
   * point has moved farther than 'Failure displacement'. Both are needed.
   * Under load control a state past its limit has no equilibrium on the
   * load path at its geometry, so Newton's method cannot converge there;
   * but the material point method follows large deformation, and a slope
   * past its limit slides in a few load steps into a flatter shape that
   * stands (Griffiths and Lane's slope at F = 1.5, 0.2 above its factor of
   * safety, stands after moving 0.67 m, 7 % of its height). The factor of
   * safety is that of the slope as built, so a trial whose points move
   * farther than the small displacements of a standing slope has failed:
   * the limit is a length the scene names (a few per cent of the height;
   * doc/benchmarks/factor_of_safety.md measures how the factor depends on
   * it), checked after every converged step, which also stops the trial
   * there. The Newton criterion finds the limit to within the smallest
   * load step: a trial whose limit lies a fraction of it below the full
   * load may still stand.
   *
   * The search starts at 'First factor', multiplies F by 'Bracket ratio'
   * while trials stand (divides while they fail) until one stands and one
   * fails, and then bisects that bracket until it is at most 'Tolerance'
   * wide. F is reported as the bracket's midpoint, with the bracket.
   *
   * Each trial writes what the scene's Output asks for into its own
   * directory `trial_K` below the output directory, with its terminal lines
   * in `terminal.txt`; `last_stable` and `first_failed` link to the trials
   * of the final bracket (the failed trial's point files end at its last
   * converged step), and `factor_of_safety.csv` lists the trials.
   */
  template <int dim>
  class StrengthReduction
  {
  public:
    /** @brief Whether the scene in @p prm asks for a strength reduction. */
    static bool
    enabled(dealii::ParameterHandler &prm);

    /**
     * @brief Search the factor of safety of the scene in @p prm (parsed),
     * as @p options ask, on @p communicator; print one line per trial and
     * the result, and write the files described above.
     */
    static void
    run(dealii::ParameterHandler &prm,
        const RunOptions         &options,
        const MPI_Comm            communicator);

  private:
    /** @brief What one trial gave. */
    struct Trial
    {
      /** The strength reduction factor F. */
      double factor = 0.;
      /** Whether the scene's full load was carried. */
      bool stands = false;
      /** The load factor of the last converged step. */
      double load_factor = 0.;
      /** The converged load steps. */
      unsigned int converged_steps = 0;
      /** The largest displacement of a point at the last converged step,
       *  in m. */
      double largest_displacement = 0.;
      /** The trial's wall time in s. */
      double wall_time = 0.;
      /** The trial's directory, relative to the output directory. */
      std::string directory;
      /** Why it failed ("load step", "displacement"), empty if it stood. */
      std::string failure;
    };

    /** @brief Run the scene of @p prm with strengths divided by
     *  @p factor, writing into @p directory below @p output_directory. */
    static Trial
    run_trial(dealii::ParameterHandler            &prm,
              const RunOptions                    &options,
              const Parameters::StrengthReduction &search,
              const std::string                   &output_directory,
              const std::string                   &directory,
              const double                         factor,
              const MPI_Comm                       communicator);

    /**
     * @brief Refuse a scene a search cannot run (a resume, --stop-after-step,
     * inertia, a model without a strength reduction, no body that weakens),
     * one line each, before anything is written.
     */
    static void
    check_scene(dealii::ParameterHandler &prm,
                const RunOptions         &options,
                const RunParameters<dim> &settings);

    /**
     * @brief Take over the output directory @p directory for the search
     * (OutputDirectory::prepare()) and remove the trials and links of an
     * earlier search in it. Collective.
     */
    static void
    prepare_directory(const std::string        &directory,
                      const RunParameters<dim> &settings,
                      const RunOptions         &options,
                      const MPI_Comm            communicator);

    /** @brief Write `factor_of_safety.csv` in @p directory atomically
     *  (rank 0; collective). */
    static void
    write_table(const std::vector<Trial> &trials,
                const std::string        &directory,
                const MPI_Comm            communicator);

    /** @brief The terminal line of trial @p number (wall time unless
     *  @p testing). */
    static std::string
    describe(const Trial &trial, const unsigned int number, const bool testing);

    /** @brief Refuse the search (one line) when @p trial and @p previous,
     *  at different factors, failed on 'Failure displacement' in the same
     *  load step with the same largest displacement (to 1e-9): the
     *  displacement does not depend on the strength, so it is elastic and
     *  no factor can make the scene stand. */
    static void
    refuse_failure_without_strength(const Trial       &previous,
                                    const Trial       &trial,
                                    const std::string &directory);
  };
} // namespace impm

#endif
