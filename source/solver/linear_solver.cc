#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <impm/solver/linear_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>

namespace impm
{
  namespace
  {
    /**
     * @brief What an exception's text says went wrong, in one line:
     * deal.II's "Additional information" paragraph if there is one (its
     * lines joined), else the first non-empty line.
     */
    std::string
    cause_of(const std::exception &error)
    {
      std::istringstream text(error.what());
      std::string        line, first, cause;
      bool               in_cause = false;
      while (std::getline(text, line))
        {
          const auto start = line.find_first_not_of(" \t");
          if (start == std::string::npos)
            {
              if (!cause.empty())
                break; // the end of the paragraph
              continue;
            }
          line = line.substr(start);
          if (line.find_first_not_of('-') == std::string::npos ||
              line.rfind("Stacktrace:", 0) == 0)
            {
              if (!cause.empty())
                break;
              continue;
            }
          if (in_cause)
            cause += (cause.empty() ? "" : " ") + line;
          else if (line.rfind("Additional information:", 0) == 0)
            in_cause = true;
          else if (first.empty())
            first = line;
        }
      return cause.empty() ? first : cause;
    }



    /**
     * @brief A sparse direct solver of Trilinos Amesos (KLU, a serial
     * factorisation, or MUMPS, a distributed one), with an optional
     * condition estimate from the factorisation it has made.
     */
    class DirectSolver : public LinearSolver
    {
    public:
      /**
       * @brief The Amesos solver @p amesos_name ("Amesos_Klu", ...), called
       * @p scene_name in the scene.
       */
      DirectSolver(const std::string &amesos_name,
                   const std::string &scene_name)
        : amesos_name(amesos_name)
        , scene_name(scene_name)
      {}

      /** Public: AutomaticSolver solves through it without a second
       *  report. */
      void
      try_solve(const LinearSolveRequest &request,
                LinearSolveReport        &report) override
      {
        SolverControl                                  control(1, 0);
        TrilinosWrappers::SolverDirect::AdditionalData data(false, amesos_name);
        TrilinosWrappers::SolverDirect                 solver(control, data);
        solver.initialize(request.matrix);
        request.solution = 0.;
        solver.solve(request.solution, request.rhs);
        for (unsigned int k = 0; k < request.additional_solutions.size(); ++k)
          solver.solve(*request.additional_solutions[k],
                       *request.additional_right_hand_sides[k]);
        if (!request.estimate_condition)
          return;
        // |A|_F times a lower bound of |A^-1|_2 from three steps of inverse
        // iteration with the factorisation already made.
        TrilinosWrappers::MPI::Vector x(request.rhs.locally_owned_elements(),
                                        request.rhs.get_mpi_communicator()),
          y(x);
        x                   = 1. / std::sqrt(double(x.size()));
        double inverse_norm = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          {
            solver.solve(y, x);
            inverse_norm = y.l2_norm();
            x            = y;
            x /= inverse_norm;
          }
        const double condition = request.matrix.frobenius_norm() * inverse_norm;
        report.condition_estimate = std::isfinite(condition) ?
                                      condition :
                                      std::numeric_limits<double>::infinity();
      }

    protected:
      std::string
      name() const override
      {
        return scene_name;
      }

    private:
      const std::string amesos_name;
      const std::string scene_name;
    };



    /**
     * @brief GMRES preconditioned by Trilinos ML's algebraic multigrid, to
     * the tolerance the Newton solver asks for, relative to the right-hand
     * side, in at most 'Solver/Linear iterations' iterations.
     *
     * The hierarchy built for a load step's matrix preconditions the
     * following Newton iterations of the step (the matrix is reassembled in
     * place: its values change, its pattern does not) until a solve needs
     * more than 'Solver/AMG reuse factor' times the iterations of the first
     * solve after the build, also over load steps whose setup keeps the
     * matrix; a new matrix (set_near_null_space(), called at every setup
     * that makes one) or a failed solve with a kept hierarchy builds a new
     * one. A system small enough for ML to factorise whole
     * (no more rows than its coarse size, 'Solver/AMG coarse size')
     * gets a new factorisation for every solve.
     */
    class GmresAmgSolver : public LinearSolver
    {
    public:
      /** @brief A Krylov solver with the scene's iteration limit. */
      explicit GmresAmgSolver(const Parameters::Solver &parameters)
        : coarse_size(parameters.amg_coarse_size)
        , tightest_tolerance(parameters.linear_tolerance)
        , max_iterations(parameters.linear_iterations)
        , reuse_factor(parameters.amg_reuse_factor)
        , aggregation_threshold(parameters.amg_aggregation_threshold)
      {}

      bool
      needs_near_null_space() const override
      {
        return true;
      }

      void
      set_near_null_space(NearNullSpace modes) override
      {
        // A new system: the hierarchy of the last one (which points to its
        // matrix and modes) goes first.
        amg.reset();
        near_null_space = std::move(modes);
      }

      std::string
      statistics() const override
      {
        if (n_solves == 0)
          return "";
        return "AMG hierarchy built for " + std::to_string(n_builds) + " of " +
               std::to_string(n_solves) + " GMRES solves (" +
               std::to_string(n_repeated) +
               " repeated with a new one after a kept one failed)";
      }

    protected:
      void
      try_solve(const LinearSolveRequest &request,
                LinearSolveReport        &report) override
      {
        ++n_solves;
        report.iterations = 0;
        // A kept hierarchy serves while the solves need at most this many
        // iterations; the solve that needs more is the last with it.
        const double allowed =
          reuse_factor * std::max(iterations_after_build, 10u);
        const bool kept = reuse_factor > 0. && amg != nullptr && !one_level &&
                          last_iterations <= allowed;
        if (!kept)
          build(request.matrix);
        try
          {
            // With a kept hierarchy a solve gives up at twice the allowed
            // iterations (and is repeated with a new one) rather than at
            // the iteration limit.
            // (Compared as doubles: a large factor must not overflow.)
            const unsigned int limit =
              kept ?
                static_cast<unsigned int>(
                  std::min<double>(max_iterations, std::ceil(2 * allowed))) :
                max_iterations;
            solve_all(request, limit, report);
          }
        catch (const std::exception &)
          {
            // A kept hierarchy may no longer fit the matrix: once more with
            // a new one before the solve is reported as failed.
            if (!kept)
              throw;
            ++n_repeated;
            build(request.matrix);
            solve_all(request, max_iterations, report);
          }
      }

      /**
       * @brief The solves of @p request (its right-hand side and any
       * additional ones) with the current hierarchy, in at most @p
       * iteration_limit iterations each; records the first one's iterations
       * for the reuse rule.
       */
      void
      solve_all(const LinearSolveRequest &request,
                const unsigned int        iteration_limit,
                LinearSolveReport        &report)
      {
        const unsigned int before = report.iterations;
        solve_with(*amg,
                   request.matrix,
                   request.solution,
                   request.rhs,
                   request.relative_tolerance,
                   iteration_limit,
                   report);
        last_iterations = report.iterations - before;
        if (first_solve_after_build)
          iterations_after_build = last_iterations;
        first_solve_after_build = false;
        for (unsigned int k = 0; k < request.additional_solutions.size(); ++k)
          solve_with(*amg,
                     request.matrix,
                     *request.additional_solutions[k],
                     *request.additional_right_hand_sides[k],
                     tightest_tolerance,
                     iteration_limit,
                     report);
      }

      /** @brief A new hierarchy for @p matrix. */
      void
      build(const TrilinosWrappers::SparseMatrix &matrix)
      {
        amg.reset();
        TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
        amg_data.elliptic              = true;
        amg_data.higher_order_elements = false;
        amg_data.smoother_sweeps       = 2;
        amg_data.aggregation_threshold = aggregation_threshold;
        // ML's parameters from deal.II's defaults, then the rigid-body
        // modes as the near null space. Aggregation is by row ("PDE
        // equations" = 1): a face condition removes one component of a
        // node from the system, so its rows do not come in blocks of dim.
        // On the collapse at h = 0.25 m the rotations cut the GMRES
        // iterations by 30 % (doc/benchmarks/parallel_and_solvers.md).
        Teuchos::ParameterList              ml_parameters;
        std::unique_ptr<Epetra_MultiVector> unused_modes;
        amg_data.set_parameters(ml_parameters, unused_modes, matrix);
        AssertDimension(near_null_space.n_rows,
                        matrix.local_range().second -
                          matrix.local_range().first);
        ml_parameters.set("PDE equations", 1);
        ml_parameters.set("null space: type", "pre-computed");
        ml_parameters.set("null space: dimension",
                          static_cast<int>(near_null_space.n_modes));
        ml_parameters.set("null space: vectors", near_null_space.values.data());
        ml_parameters.set("coarse: max size", static_cast<int>(coarse_size));
        // A system no larger than ML's coarse size is factorised whole: a
        // new "hierarchy" is a direct solve, no dearer than a kept one's
        // extra iterations, and exact.
        one_level =
          matrix.m() <= static_cast<types::global_dof_index>(
                          ml_parameters.get<int>("coarse: max size", 128));
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(matrix, ml_parameters);
        first_solve_after_build = true;
        ++n_builds;
      }

      /**
       * @brief GMRES on one right-hand side @p rhs from zero, to @p
       * relative_tolerance times its norm in at most @p iteration_limit
       * iterations; adds its iterations to @p report, and throws a
       * one-line message if it does not converge.
       */
      void
      solve_with(const TrilinosWrappers::PreconditionAMG &amg,
                 const TrilinosWrappers::SparseMatrix    &matrix,
                 TrilinosWrappers::MPI::Vector           &solution,
                 const TrilinosWrappers::MPI::Vector     &rhs,
                 const double                             relative_tolerance,
                 const unsigned int                       iteration_limit,
                 LinearSolveReport                       &report) const
      {
        solution = 0.;
        // A zero right-hand side (the material's residual of a first
        // iterate in which only a body's force acts) has the solution
        // zero; GMRES would break down on it.
        const double rhs_norm = rhs.l2_norm();
        if (rhs_norm == 0.)
          return;
        const double                  target = relative_tolerance * rhs_norm;
        SolverControl                 control(iteration_limit, target);
        TrilinosWrappers::SolverGMRES solver(control);
        try
          {
            solver.solve(matrix, solution, rhs, amg);
          }
        catch (const SolverControl::NoConvergence &no_convergence)
          {
            report.iterations += no_convergence.last_step;
            std::ostringstream message;
            message << "no convergence in " << no_convergence.last_step
                    << " iterations, residual " << no_convergence.last_residual
                    << " > " << target;
            throw std::runtime_error(message.str());
          }
        report.iterations += control.last_step();
      }

      std::string
      name() const override
      {
        return "GMRES with AMG";
      }

    protected:
      /** 'Solver/AMG coarse size'. */
      const unsigned int coarse_size;

    private:
      /** 'Solver/Linear tolerance': the additional right-hand sides' (see
       *  LinearSolveRequest). */
      const double       tightest_tolerance;
      const unsigned int max_iterations;
      /** 'Solver/AMG reuse factor'. */
      const double reuse_factor;
      /** 'Solver/AMG aggregation threshold'. */
      const double aggregation_threshold;
      /** The rigid-body modes of the current system. */
      NearNullSpace near_null_space;
      /** The current hierarchy (null before the first solve of a system). */
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
      /** Whether it is one level (a direct solve): then never kept. */
      bool one_level = false;
      /** Whether the next solve is the first with the current hierarchy. */
      bool first_solve_after_build = false;
      /** Krylov iterations of the first solve with the current hierarchy. */
      unsigned int iterations_after_build = 0;
      /** Krylov iterations of the last solve. */
      unsigned int last_iterations = 0;
      /** Solves, hierarchies built and solves repeated, for statistics(). */
      unsigned int n_solves = 0, n_builds = 0, n_repeated = 0;
    };



    /**
     * @brief KLU for systems of at most 'Solver/AMG coarse size' rows (ML
     * would factorise them whole: GMRES around a direct solve), GMRES with
     * a multilevel AMG for larger ones, chosen per solve. With the coarse
     * size at 500 this is faster than KLU from there on in 2D and 3D: a
     * 3D system of 1,252 DoFs takes 7.6 ms per GMRES solve against 55 ms
     * per KLU solve, the Mohr-Coulomb footing's 2D system of 1,362 DoFs
     * 2.7 s against 3.3 s per run (doc/benchmarks/parallel_and_solvers.md,
     * "The automatic choice").
     */
    class AutomaticSolver : public GmresAmgSolver
    {
    public:
      /** @brief Both solvers, with the scene's parameters. */
      explicit AutomaticSolver(const Parameters::Solver &parameters)
        : GmresAmgSolver(parameters)
        , direct("Amesos_Klu", "direct (KLU)")
        , rescue_size(parameters.direct_rescue_size)
      {}

      std::string
      statistics() const override
      {
        const std::string gmres = GmresAmgSolver::statistics();
        if (n_rescued == 0)
          return gmres;
        return gmres + "; failed GMRES solves done again with KLU: " +
               std::to_string(n_rescued);
      }

    protected:
      /**
       * KLU up to the coarse size; GMRES with AMG above, and where that
       * fails on a system of at most 'Solver/Direct rescue size' rows, KLU
       * on the same system (on every process together: a failure on one is
       * a failure on all). Without ghost stabilisation the collapse at
       * h = 0.5 m has nearly singular systems on which GMRES runs out of
       * iterations near the solution: two step cuts, 270 Newton iterations
       * against KLU's 196 without (doc/benchmarks/parallel_and_solvers.md,
       * "The rescue").
       */
      void
      try_solve(const LinearSolveRequest &request,
                LinearSolveReport        &report) override
      {
        if (request.matrix.m() <= coarse_size)
          {
            choice = "direct";
            direct.try_solve(request, report);
            return;
          }
        choice = "GMRES with AMG";
        std::exception_ptr failure;
        try
          {
            GmresAmgSolver::try_solve(request, report);
          }
        catch (const std::exception &)
          {
            failure = std::current_exception();
          }
        const bool failed_somewhere =
          Utilities::MPI::max(failure ? 1u : 0u,
                              request.rhs.get_mpi_communicator()) == 1u;
        if (!failed_somewhere)
          return;
        if (request.matrix.m() > rescue_size)
          {
            // Reported as GMRES's failure (and on the other processes as
            // one on another process).
            if (failure)
              std::rethrow_exception(failure);
            return;
          }
        ++n_rescued;
        choice = "direct, after GMRES with AMG failed";
        const unsigned int krylov_iterations = report.iterations;
        direct.try_solve(request, report);
        report.iterations = krylov_iterations;
      }

      std::string
      name() const override
      {
        return "automatic (" + choice + ")";
      }

    private:
      DirectSolver direct;
      /** 'Solver/Direct rescue size'. */
      const unsigned int rescue_size;
      /** The solver of the last solve. */
      std::string choice;
      /** Failed GMRES solves solved again with KLU. */
      unsigned int n_rescued = 0;
    };
  } // namespace



  LinearSolveReport
  LinearSolver::solve(const LinearSolveRequest &request)
  {
    LinearSolveReport report;
    Timer             timer;
    try
      {
        try_solve(request, report);
      }
    catch (const std::exception &error)
      {
        report.success = false;
        report.failure = name() + ": " + cause_of(error);
      }
    // A failure on one process is a failure on all.
    if (Utilities::MPI::min(report.success ? 1 : 0,
                            request.rhs.get_mpi_communicator()) == 0 &&
        report.success)
      {
        report.success = false;
        report.failure = name() + ": failed on another process";
      }
    report.seconds = timer.wall_time();
    return report;
  }



  std::unique_ptr<LinearSolver>
  LinearSolver::create(const Parameters::Solver &parameters)
  {
    switch (parameters.linear_solver)
      {
        case Parameters::LinearSolverType::automatic:
          return std::make_unique<AutomaticSolver>(parameters);
        case Parameters::LinearSolverType::direct:
          return std::make_unique<DirectSolver>("Amesos_Klu", "direct (KLU)");
        case Parameters::LinearSolverType::mumps:
          return std::make_unique<DirectSolver>("Amesos_Mumps", "MUMPS");
        case Parameters::LinearSolverType::gmres_amg:
          return std::make_unique<GmresAmgSolver>(parameters);
      }
    throw std::logic_error("Unknown linear solver type.");
  }
} // namespace impm
