#ifndef impm_coupling_mass_ghost_penalty_h
#define impm_coupling_mass_ghost_penalty_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <impm/core/body.h>
#include <impm/coupling/time_integrator.h>
#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/system/face_jump_penalty.h>
#include <impm/system/load_step_system.h>

#include <memory>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The ghost penalty of the mass (Inertia's 'Mass ghost penalty'):
   * the face penalty @f$G = \gamma_m \rho h^3 \sum_F \int_F [\![\partial_n
   * N_I]\!] [\![\partial_n N_J]\!]\, dA@f$ (FaceJumpPenalty over the faces
   * of barely filled cells; rho the largest density of the bodies), with
   * the factor the mass has in the implicit integrators' matrix, @f$k_m
   * c_1 = k_m / (\beta \Delta t^2)@f$: the matrix gains @f$k_m c_1 G@f$
   * and the internal force @f$k_m c_1 G \Delta u@f$.
   *
   * Why: a node that only the edge of a point's support reaches has a
   * tiny mass, and with a small time step the matrix is dominated by
   * @f$k_m c_1 M@f$, against which the stiffness's ghost penalty (gamma E
   * h) becomes negligible: the vibrating bar's worst condition estimate
   * grows from 2.5e3 at 100 steps a period to 1.4e5 at 1000. A node of a
   * full cell has a mass of order @f$\rho h^d@f$; the penalty gives the
   * nodes of a stabilised face a term of order @f$\gamma_m \rho h^d@f$ on
   * the kink of their motion.
   *
   * Like the stiffness's penalty it acts on the step's displacement
   * increment, so it keeps no memory: a linear field of increment (a
   * rigid motion, a uniform strain) is not penalised, a converged step is
   * in equilibrium with it, and it can only take energy out (the kink of
   * the increment at a stabilised face), never put it in. Applied to the
   * end-of-step acceleration instead (@f$G a^{n+1}@f$, with the nodes'
   * start velocity mapped from the points) it put energy in: the kink of
   * each step's mapped velocity carried a "ghost" kinetic energy, @f$v^T G
   * v / 2@f$, that the step turned into real motion (the bar gained 31 %
   * of its energy in a period at gamma_m = 0.1 and 1000 steps; with the
   * increment it loses 1e-5).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class MassGhostPenalty
  {
  public:
    /** @brief Declare 'Mass ghost penalty' and 'Mass ghost fill
     *  threshold' in the current subsection (Inertia). */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief Read the entries of the current subsection; active when the
     * penalty is above 0, which the explicit integrators refuse (their
     * lumped mass has no matrix to stabilise).
     * @param prm The Inertia subsection.
     * @param integrator The scene's time integrator.
     * @param grid The background grid.
     * @param bodies The bodies: the largest density scales the penalty.
     */
    MassGhostPenalty(const ParameterHandler       &prm,
                     const TimeIntegrator         &integrator,
                     const BackgroundGrid<dim>    &grid,
                     const std::vector<Body<dim>> &bodies);

    /** @brief Whether the scene asks for the penalty. */
    bool
    active() const
    {
      return static_cast<bool>(penalty);
    }

    /** @brief The step's faces (FaceJumpPenalty::choose_faces()).
     *  Collective. */
    void
    choose_faces(const MaterialPoints<dim> &material_points,
                 const std::vector<bool>   &touched);

    /** @brief The faces' DoFs as dense blocks of the sparsity pattern. */
    void
    add_blocks(const LoadStepSystem<dim>                         &system,
               std::vector<std::vector<types::global_dof_index>> &blocks) const;

    /**
     * @brief Add @f$k_m c_1 G \Delta u@f$ to @p force.
     * @param increment The displacement increment (ghosted).
     * @param time_step The step's time step.
     * @param force The internal force (before its compress()).
     */
    void
    add_forces(const NodalVector &increment,
               const double       time_step,
               NodalVector       &force) const;

    /**
     * @brief Half its force times the increment @p increment at this
     * process's owned DoFs: the energy it takes out of a step (it grows
     * from zero with the step's increment). Collective.
     */
    double
    dissipation(const NodalVector &increment, const double time_step) const;

    /** @brief Add @f$k_m c_1 G@f$ to @p matrix (before its compress()). */
    void
    add_matrix(const LoadStepSystem<dim>      &system,
               const double                    time_step,
               TrilinosWrappers::SparseMatrix &matrix) const;

    /** @brief The factor of the mass in the matrix, @f$k_m c_1 = k_m /
     *  (\beta \Delta t^2)@f$. */
    double
    factor(const double time_step) const;

    /** @brief "mass ghost penalty ..." for the start-up report. */
    std::string
    description() const;

  private:
    const TimeIntegrator &integrator;
    const double          penalty_scale;
    const double          fill_threshold;
    /** The faces (none unless active()). */
    std::unique_ptr<FaceJumpPenalty<dim>> penalty;
  };
} // namespace impm

#endif
