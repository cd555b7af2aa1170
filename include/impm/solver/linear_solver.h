#ifndef impm_solver_linear_solver_h
#define impm_solver_linear_solver_h

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <impm/core/parameters.h>

#include <memory>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The linear solver of the Newton iterations, chosen once from the
   * scene's 'Solver/Linear solver'.
   *
   * To add a solver: a value of Parameters::LinearSolverType with its name in
   * Parameters::linear_solver_names, a class derived from this one in
   * linear_solver.cc, and its case in create().
   */
  class LinearSolver
  {
  public:
    /**
     * @brief The solver the scene names.
     * @param parameters The scene's solver parameters (type, tolerance).
     * The processes are those of the system's vectors.
     */
    static std::unique_ptr<LinearSolver>
    create(const Parameters::Solver &parameters);

    virtual ~LinearSolver() = default;

    /**
     * @brief Solve @p matrix @p solution = @p rhs.
     * @param estimate_condition Also estimate the condition number of
     * @p matrix, where the solver can (see condition_estimate()).
     */
    virtual void
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector        &solution,
          const TrilinosWrappers::MPI::Vector  &rhs,
          const bool                            estimate_condition) = 0;

    /**
     * @brief The condition estimate of the last solve that asked for one:
     * 0 if none was made, infinity if the estimate was not finite.
     */
    double
    condition_estimate() const
    {
      return last_condition_estimate;
    }

  protected:
    /** Set by solve() when asked to estimate. */
    double last_condition_estimate = 0.;
  };
} // namespace impm

#endif
