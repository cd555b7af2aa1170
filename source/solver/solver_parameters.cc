#include <impm/base/errors.h>
#include <impm/solver/solver_parameters.h>

// The scene's 'Solver' section: load stepping, Newton and the linear solver.
namespace impm
{
  namespace Parameters
  {
    namespace
    {
      /** The statement of equilibrium, the load steps and Newton. */
      void
      declare_newton_entries(ParameterHandler &prm)
      {
        prm.declare_entry("Formulation",
                          "previously converged",
                          Patterns::Selection(
                            "previously converged|updated Lagrangian"),
                          "Statement of equilibrium: previously converged "
                          "(the paper's eq. 9-10: the pulled-back stress on "
                          "the start-of-step grid) or updated Lagrangian "
                          "(eq. 7-8: Cauchy stress with the basis gradients "
                          "mapped to the current configuration in every "
                          "iteration). Both give the same iterates up to "
                          "round-off. The "
                          "paper reports about 5 % less time for the first; "
                          "here both cost the same within the measurement "
                          "scatter (doc/benchmarks).");
        prm.declare_entry("Load steps",
                          "50",
                          Patterns::Integer(1),
                          "Number of equal load steps (>= 1).");
        prm.declare_entry("Tolerance",
                          "1e-9",
                          Patterns::Double(1e-15, 1.),
                          "Newton converges when |r| / |f_ext| on the free "
                          "degrees of freedom falls below this (1e-15 to 1).");
        prm.declare_entry("Absolute tolerance",
                          "0",
                          Patterns::Double(0.),
                          "Newton also converges when |r| (in N, per unit "
                          "thickness in 2D) falls below this (0: off; >= 0). "
                          "For loads so small next to the internal forces "
                          "that round-off in f_int, about 1e-15 |f_int|, "
                          "exceeds 'Tolerance' |f_ext|; a step that fails "
                          "there says so. Without it, |r| below the internal "
                          "force of a strain of 64 machine epsilons (E_max "
                          "times the points' volume to the power (D-1)/D) "
                          "is converged: the stresses' own round-off.");
        prm.declare_entry("Maximum iterations",
                          "20",
                          Patterns::Integer(1, 1000),
                          "Newton iterations allowed per load step; a step "
                          "that needs more stops the run with an error.");
      }

      /** The linear solver and its tolerances. */
      void
      declare_linear_solver_entries(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Linear solver",
          "automatic",
          Patterns::Selection("automatic|direct|MUMPS|GMRES with AMG"),
          "automatic (direct while the load step's system has "
          "at most 'AMG coarse size' rows, GMRES with AMG above: "
          "from there GMRES with a multilevel AMG is the faster "
          "in 2D and 3D, doc/benchmarks), "
          "direct (Trilinos Amesos KLU, a serial "
          "factorisation), MUMPS (Trilinos Amesos MUMPS, a "
          "factorisation shared by the processes) or GMRES "
          "with AMG (Trilinos ML, the rigid-body modes (translations "
          "and rotations) as near null space).");
        prm.declare_entry("Linear tolerance",
                          "1e-12",
                          Patterns::Double(1e-16, 1e-2),
                          "Relative residual of the iterative linear solver "
                          "(with 'Adaptive linear tolerance', the tightest it "
                          "is asked for).");
        prm.declare_entry("Adaptive linear tolerance",
                          "true",
                          Patterns::Bool(),
                          "Iterative linear solver only: solve to min(eta, "
                          "max(0.1 r, Tolerance / (2 r))), r the Newton "
                          "iteration's relative residual, but not below "
                          "'Linear tolerance', eta the 'Largest linear "
                          "tolerance' (cheap far from the solution, "
                          "still quadratic near it); false: always to 'Linear "
                          "tolerance'.");
        prm.declare_entry(
          "Largest linear tolerance",
          "1e-2",
          Patterns::Double(1e-16, 0.5),
          "With 'Adaptive linear tolerance': the loosest relative residual an "
          "iterative solve is asked for, far from the solution (at least "
          "'Linear tolerance'). 0.1 let Newton wander where Mohr-Coulomb "
          "points change return region: the footing at h = 0.0625 m took "
          "11,025 Newton iterations and 446 s with 0.1, 467 and 16 s with "
          "1e-2 (doc/benchmarks/parallel_and_solvers.md).");
        prm.declare_entry(
          "Line search",
          "false",
          Patterns::Bool(),
          "Backtracking along each Newton correction: when the iterate it "
          "reaches has an inverted point, a non-finite value, or a relative "
          "residual that has not fallen by 1e-4 of the step (Armijo's "
          "condition), the step is halved, up to 5 times (each one "
          "residual evaluation, no matrix); if none is enough, the step "
          "of the smallest residual is kept. A full step across which a "
          "contact changed state is taken whole (the residual jumps where "
          "the contact's state switches). For scenes whose Newton "
          "iterations cycle where points change return region (a plastic "
          "flow, the Mohr-Coulomb corners, a tension cut-off) instead of "
          "converging; false: the full correction always.");
        prm.declare_entry("Linear iterations",
                          "1000",
                          Patterns::Integer(1),
                          "Iterations allowed to the iterative linear solver "
                          "per solve; a solve that needs more fails the "
                          "Newton solve (and the step is cut).");
        prm.declare_entry(
          "AMG reuse factor",
          "2",
          Patterns::Double(0.),
          "GMRES with AMG, systems of more than 'AMG coarse size' rows "
          "(smaller ones ML factorises whole, anew for every solve): the "
          "multigrid hierarchy "
          "built for a load step's matrix preconditions its following Newton "
          "iterations until a solve needs more than this factor times the "
          "iterations of the solve right after the hierarchy was built (at "
          "least 10), "
          "then it is rebuilt; a solve that fails with a kept hierarchy is "
          "repeated with a new one. 0: a new hierarchy for every solve.");
        prm.declare_entry(
          "AMG aggregation threshold",
          "0",
          Patterns::Double(0., 1.),
          "GMRES with AMG: ML's aggregation drops the connections of a row "
          "weaker than this fraction of its diagonal before it builds the "
          "aggregates (deal.II's default is 1e-4). 0 keeps them all: on the "
          "3D quarter collapse at h = 0.5 m the linear solve took 0.8 of its "
          "time with 1e-4 (8 % more GMRES iterations, a cheaper hierarchy); "
          "in 2D it is within the noise (doc/benchmarks/parallel_and_solvers.md).");
        prm.declare_entry(
          "AMG coarse size",
          "500",
          Patterns::Integer(1),
          "GMRES with AMG: ML coarsens until a level has at most this many "
          "rows and solves that level with a direct solver (deal.II's "
          "setting is 2000). A system no larger is factorised whole, anew "
          "for every solve, and 'automatic' solves it with KLU. 500: a 3D "
          "system of 1,252 DoFs took 7.6 ms per solve against 58 ms with "
          "2000 (and 55 ms with KLU); above 2,000 rows the value changes little "
          "(doc/benchmarks/parallel_and_solvers.md). tests/iterative_solver_refinement "
          "sets 50 so that every grid from h = 1 m on gets a multilevel "
          "hierarchy.");
        prm.declare_entry(
          "Direct rescue size",
          "20000",
          Patterns::Integer(0),
          "'automatic' only: a GMRES solve that fails on a system of at most "
          "this many rows is done again with KLU (the run's last lines say "
          "how often); a larger one fails, and the load step is cut. 0: "
          "never. Without ghost stabilisation the collapse at h = 0.5 m "
          "cut two steps after GMRES ran out of iterations on its nearly "
          "singular systems (doc/benchmarks/parallel_and_solvers.md).");
      }

      /** The load-step control and the condition estimate. */
      void
      declare_step_control_entries(ParameterHandler &prm)
      {
        prm.declare_entry("Step control",
                          "true",
                          Patterns::Bool(),
                          "Automatic load-step control: a step whose Newton "
                          "solve fails (iteration limit, divergence, a "
                          "non-finite value, an inverted point) is restarted "
                          "from the last converged state with half the load "
                          "increment; easy steps grow it again (and runs of "
                          "steady ones, 'Steady steps before growth'), up to "
                          "the nominal 1/(Load steps). If false, a failed "
                          "step stops the run.");
        prm.declare_entry("Minimum load step",
                          "1e-4",
                          Patterns::Double(1e-12, 1.),
                          "Smallest load increment, as a fraction of the "
                          "total load (1e-12 to 1); a step that fails at this "
                          "size stops the run with its residual history. "
                          "Where the nominal step 1/(Load steps) is not "
                          "above it (an explicit run of many steps), the "
                          "smallest is 1/1024 of the nominal step instead, "
                          "so that a step can still be cut.");
        prm.declare_entry("Divergence factor",
                          "1e4",
                          Patterns::Double(1.),
                          "A Newton solve has diverged when its relative "
                          "residual exceeds this multiple of the step's first "
                          "residual (>= 1).");
        prm.declare_entry("Easy step iterations",
                          "4",
                          Patterns::Integer(1),
                          "A step converged in at most this many Newton "
                          "iterations doubles the next load increment (up to "
                          "the nominal one).");
        prm.declare_entry("Steady steps before growth",
                          "3",
                          Patterns::Integer(0),
                          "After a cut: once this many steps in a row have "
                          "converged at the cut increment, the next is "
                          "doubled even if none was easy (scenes whose steps "
                          "all need more than 'Easy step iterations' stay "
                          "at the cut size otherwise); each such doubling "
                          "that fails doubles the number needed for the next "
                          "one. 0: only easy steps grow the increment.");
        prm.declare_entry("Maximum point increment",
                          "1",
                          Patterns::Double(0.),
                          "With step control: a converged step that moves a "
                          "point by more than this many cell sizes in one "
                          "direction is cut, so that the load path is followed "
                          "and no point outruns the basis of its step (> 0).");
        prm.declare_entry("Estimate condition number",
                          "false",
                          Patterns::Bool(),
                          "Estimate the 2-norm condition number of the first "
                          "matrix of every load step (three extra direct "
                          "solves; direct solver only); the worst goes to "
                          "summary.json.");
      }

    } // namespace



    void
    Solver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      declare_newton_entries(prm);
      declare_linear_solver_entries(prm);
      declare_step_control_entries(prm);
      prm.leave_subsection();
    }

    void
    Solver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      formulation               = static_cast<Formulation>(selection_index(
        formulation_names, "Solver/Formulation", prm.get("Formulation")));
      n_load_steps              = prm.get_integer("Load steps");
      tolerance                 = prm.get_double("Tolerance");
      absolute_tolerance        = prm.get_double("Absolute tolerance");
      max_iterations            = prm.get_integer("Maximum iterations");
      linear_solver             = static_cast<LinearSolverType>(selection_index(
        linear_solver_names, "Solver/Linear solver", prm.get("Linear solver")));
      linear_tolerance          = prm.get_double("Linear tolerance");
      linear_iterations         = prm.get_integer("Linear iterations");
      adaptive_linear_tolerance = prm.get_bool("Adaptive linear tolerance");
      largest_linear_tolerance  = prm.get_double("Largest linear tolerance");
      if (largest_linear_tolerance < linear_tolerance)
        throw InputError(
          "Solver/Largest linear tolerance = " +
          prm.get("Largest linear tolerance") +
          " is below Solver/Linear tolerance = " + prm.get("Linear tolerance") +
          "; allowed: from 'Linear tolerance' to 0.5.");
      amg_reuse_factor          = prm.get_double("AMG reuse factor");
      amg_aggregation_threshold = prm.get_double("AMG aggregation threshold");
      amg_coarse_size           = prm.get_integer("AMG coarse size");
      direct_rescue_size        = prm.get_integer("Direct rescue size");
      step_control              = prm.get_bool("Step control");
      line_search               = prm.get_bool("Line search");
      minimum_step              = prm.get_double("Minimum load step");
      divergence_factor         = prm.get_double("Divergence factor");
      easy_iterations           = prm.get_integer("Easy step iterations");
      steady_steps              = prm.get_integer("Steady steps before growth");
      maximum_point_increment   = prm.get_double("Maximum point increment");
      estimate_condition        = prm.get_bool("Estimate condition number");
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace impm
