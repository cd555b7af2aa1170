#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <impm/solver/linear_solver.h>

#include <cmath>
#include <limits>

namespace impm
{
  namespace
  {
    /**
     * @brief A sparse direct solver of Trilinos Amesos (KLU, a serial
     * factorisation, or MUMPS, a distributed one), with an optional
     * condition estimate from the factorisation it has made.
     */
    class DirectSolver : public LinearSolver
    {
    public:
      /** @brief The Amesos solver @p amesos_name ("Amesos_Klu", ...). */
      explicit DirectSolver(const std::string &amesos_name)
        : amesos_name(amesos_name)
      {}

      void
      solve(const TrilinosWrappers::SparseMatrix &matrix,
            TrilinosWrappers::MPI::Vector        &solution,
            const TrilinosWrappers::MPI::Vector  &rhs,
            const bool                            estimate_condition) override
      {
        SolverControl                                  control(1, 0);
        TrilinosWrappers::SolverDirect::AdditionalData data(false, amesos_name);
        TrilinosWrappers::SolverDirect                 solver(control, data);
        solver.initialize(matrix);
        solution = 0.;
        solver.solve(solution, rhs);
        if (!estimate_condition)
          return;
        // |A|_F times a lower bound of |A^-1|_2 from three steps of inverse
        // iteration with the factorisation already made.
        TrilinosWrappers::MPI::Vector x(rhs.locally_owned_elements(),
                                        rhs.get_mpi_communicator()),
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
        const double condition  = matrix.frobenius_norm() * inverse_norm;
        last_condition_estimate = std::isfinite(condition) ?
                                    condition :
                                    std::numeric_limits<double>::infinity();
      }

    private:
      const std::string amesos_name;
    };



    /**
     * @brief GMRES preconditioned by Trilinos ML's algebraic multigrid, to
     * 'Solver/Linear tolerance' relative to the right-hand side.
     */
    class GmresAmgSolver : public LinearSolver
    {
    public:
      /** @brief A Krylov solver to the relative @p tolerance. */
      explicit GmresAmgSolver(const double tolerance)
        : tolerance(tolerance)
      {}

      void
      solve(const TrilinosWrappers::SparseMatrix &matrix,
            TrilinosWrappers::MPI::Vector        &solution,
            const TrilinosWrappers::MPI::Vector  &rhs,
            const bool /*estimate_condition*/) override
      {
        TrilinosWrappers::PreconditionAMG                 amg;
        TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
        amg_data.elliptic              = true;
        amg_data.higher_order_elements = false;
        amg_data.smoother_sweeps       = 2;
        amg.initialize(matrix, amg_data);
        SolverControl                 control(1000, tolerance * rhs.l2_norm());
        TrilinosWrappers::SolverGMRES solver(control);
        solution = 0.;
        solver.solve(matrix, solution, rhs, amg);
      }

    private:
      const double tolerance;
    };
  } // namespace



  std::unique_ptr<LinearSolver>
  LinearSolver::create(const Parameters::Solver &parameters)
  {
    switch (parameters.linear_solver)
      {
        case Parameters::LinearSolverType::direct:
          return std::make_unique<DirectSolver>("Amesos_Klu");
        case Parameters::LinearSolverType::mumps:
          return std::make_unique<DirectSolver>("Amesos_Mumps");
        case Parameters::LinearSolverType::gmres_amg:
          return std::make_unique<GmresAmgSolver>(parameters.linear_tolerance);
      }
    throw std::logic_error("Unknown linear solver type.");
  }
} // namespace impm
