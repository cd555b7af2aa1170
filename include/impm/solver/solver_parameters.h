#ifndef impm_solver_solver_parameters_h
#define impm_solver_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <impm/core/parameters.h>

namespace impm
{
  namespace Parameters
  {
    /** @brief Load stepping, Newton and the linear solver. */
    struct Solver
    {
      /** Previously converged (eq. 9-10) or updated Lagrangian (eq. 7-8,
       * with mapped derivatives): the same iterates, different cost. */
      Formulation formulation;
      /** Number of equal load steps. */
      unsigned int n_load_steps;
      /** Convergence when |r| / |f_ext| falls below this. */
      double tolerance;
      /** Newton also converges when the residual norm falls below this
       *  (N; 0: off). */
      double absolute_tolerance = 0.;
      /** Newton iterations allowed per load step. */
      unsigned int max_iterations;
      /** Direct (Amesos KLU) or GMRES with AMG (Trilinos ML). */
      LinearSolverType linear_solver;
      /** Relative tolerance of the iterative linear solver. */
      double linear_tolerance;
      /** Iterations allowed to the iterative linear solver per solve. */
      unsigned int linear_iterations;
      /** Tie the linear tolerance to the Newton residual. */
      bool adaptive_linear_tolerance;
      /** The loosest linear tolerance the adaptive choice gives. */
      double largest_linear_tolerance;
      /** Keep the AMG hierarchy while the Krylov iterations stay below this
       *  factor times those right after it was built (0: never keep). */
      double amg_reuse_factor;
      /** ML's aggregation threshold (the connections weaker than this
       *  fraction of the diagonal are dropped before aggregation). */
      double amg_aggregation_threshold;
      /** ML coarsens until a level has at most this many rows and solves
       *  that level directly. */
      unsigned int amg_coarse_size;
      /** 'automatic': the largest system whose failed GMRES solve KLU
       *  repeats (0: none). */
      unsigned int direct_rescue_size;
      /** Cut failed load steps and grow easy ones (else a failure stops). */
      bool step_control;
      /** Halve a Newton correction that does not lower the residual. */
      bool line_search = false;
      /** Smallest load increment, as a fraction of the total load. */
      double minimum_step;
      /** A step has failed when the residual exceeds this times its first. */
      double divergence_factor;
      /** A step that needs at most this many iterations may grow the next. */
      unsigned int easy_iterations;
      /** After a cut, grow after this many converged steps in a row (0:
       *  only easy steps grow). */
      unsigned int steady_steps;
      /** Largest point displacement of one step, in cells (step control). */
      double maximum_point_increment;
      /** Estimate the condition number of each step's first matrix. */
      bool estimate_condition;

      /** @brief Declare the entries in subsection "Solver". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace impm

#endif
