#ifndef impm_coupling_stiffness_damping_h
#define impm_coupling_stiffness_damping_h

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <impm/coupling/nodal_momentum.h>
#include <impm/coupling/time_integrator.h>
#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/points/point_step.h>
#include <impm/system/dense_block_adder.h>
#include <impm/system/load_step_system.h>

#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The stiffness-proportional part of Rayleigh damping, @f$C =
   * \beta_R K_e@f$, for Inertia: a viscous (Kelvin-Voigt) Cauchy stress
   * @f$\sigma_d = \beta_R\, \mathbb D^e : \dot\varepsilon@f$ at every point,
   * with the point's isotropic elastic moduli @f$\lambda, \mu@f$
   * (Material::p_wave_modulus(), Material::shear_modulus(): a
   * pressure-dependent law's reference ones) and the rate of strain of the
   * nodal velocity on the step's start-of-step grid, @f$\dot\varepsilon =
   * \mathrm{sym} \sum_I v_I \otimes \nabla N_I@f$ (with the hoop rate
   * @f$\sum_I \bar N_{\theta,I} v_{I,r}@f$ in axisymmetry). Its nodal force
   * is @f$\sum_p V_p^n \sigma_d \nabla N_{Ip}@f$ with the points' volume at
   * the step's start: @f$\beta_R K_e v@f$, where @f$K_e@f$ is the small-strain
   * elastic stiffness of the start-of-step grid. A mode of angular
   * frequency @f$\omega@f$ of an elastic body is damped at the ratio
   * @f$\zeta = \beta_R \omega / 2@f$: the highest frequencies most, which is
   * what the damping is for. The stress is not stored and not part of the
   * points' stress; the damping's work is dissipated.
   *
   * The implicit integrators take it at the balance's time like the mass
   * damping: @f$\beta_R K_e (v^{n+1} + k_r v^n)@f$, with generalised-alpha's
   * @f$k_r = \alpha_f/(1-\alpha_f)@f$ (0 for Newmark) and the nodal
   * velocity of the Newmark relations, @f$v^{n+1} = v^n + \Delta t((1 -
   * \gamma) a^n + \gamma a^{n+1})@f$, from the lumped nodal momentum of the
   * step's start (@f$v^n = p_I / M_I@f$, also with the consistent mass); its
   * derivative @f$\beta_R \gamma/(\beta\Delta t)\,K_e@f$ goes into the
   * matrix. Nodes whose motion is prescribed (outside the system) move at
   * @f$\Delta u / \Delta t@f$. The explicit integrators add
   * @f$\beta_R K_e v^n@f$ to the residual of the step's start, and their
   * stable step falls to @f$\Delta t_c (\sqrt{1 + \zeta_{max}^2} -
   * \zeta_{max})@f$, @f$\zeta_{max} = \beta_R/\Delta t_c@f$ the ratio at the
   * grid's highest frequency @f$2/\Delta t_c@f$ (critical_time_step()).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class StiffnessDamping
  {
  public:
    /** @brief The damping of @p integrator (its 'Stiffness damping'
     *  coefficient). */
    explicit StiffnessDamping(const TimeIntegrator &integrator);

    /** @brief Whether the scene asks for it (a coefficient above 0). */
    bool
    active() const
    {
      return coefficient > 0.;
    }

    /** @brief Keep each point's elastic moduli times @f$\beta_R V^n@f$
     *  for the step (nothing when inactive). */
    void
    begin_step(const MaterialPoints<dim> &material_points,
               const PointSteps<dim>     &steps);

    /**
     * @brief The stable explicit time step with the damping, from the
     * undamped one @p undamped_step at Courant number 1, @f$\Delta t_c
     * (\sqrt{1 + \zeta^2} - \zeta)@f$ with @f$\zeta = \beta_R / \Delta
     * t_c@f$ (the undamped step when inactive).
     */
    double
    critical_time_step(const double undamped_step) const;

    /**
     * @brief Implicit integrators: add the damping force at the displacement
     * increment @p increment (ghosted) to @p internal_force (local DoFs,
     * before its compress()), from the start's nodal momentum @p nodes.
     * @return The size of the force for the residual's reference: the sum
     *   of the squares of the points' nodal forces on this process.
     */
    double
    add_implicit_forces(const NodalMomentum<dim>  &nodes,
                        const LoadStepSystem<dim> &system,
                        const NodalVector         &increment,
                        const double               time_step,
                        NodalVector               &internal_force);

    /** @brief Implicit integrators: add the force's derivative,
     *  @f$\beta_R \gamma/(\beta\Delta t)\, K_e@f$, to @p matrix. */
    void
    add_implicit_matrix(const LoadStepSystem<dim>      &system,
                        const double                    time_step,
                        TrilinosWrappers::SparseMatrix &matrix);

    /**
     * @brief Explicit integrators: the residual of the step's start @p
     * residual (ghosted) plus the damping force of the start's nodal
     * velocity @f$p_I / M_I@f$ (zero outside the system), ghosted.
     * Collective.
     */
    const NodalVector &
    damped_residual(const NodalMomentum<dim>  &nodes,
                    const LoadStepSystem<dim> &system,
                    const NodalVector         &residual);

    /**
     * @brief Implicit integrators: the energy the damping force at the
     * converged increment @p increment takes out (that force times the
     * increment at this process's owned DoFs; 0 when inactive), once a
     * step. Collective.
     */
    double
    implicit_dissipation(const NodalMomentum<dim>  &nodes,
                         const LoadStepSystem<dim> &system,
                         const NodalVector         &increment,
                         const double               time_step);

    /**
     * @brief The energy the last damped_residual()'s damping force takes
     * out over the explicit increment @p increment (by local DoF): that
     * force times the increment at the first @p n_owned (this process's)
     * DoFs.
     */
    double
    explicit_dissipation(const std::vector<double> &increment,
                         const unsigned int         n_owned) const;

  private:
    /** @brief Add @f$\beta_R K_e v@f$ of the nodal velocity @p velocity
     *  (local DoFs) to @p force (local DoFs, before a compress()); returns
     *  the sum of the squares of the points' nodal forces on this
     *  process. */
    double
    add_force(const LoadStepSystem<dim> &system,
              const std::vector<double> &velocity,
              NodalVector               &force) const;

    /** The coefficient @f$\beta_R@f$ (s). */
    const double coefficient;
    /** Newmark's @f$\gamma/\beta@f$ and generalised-alpha's @f$k_r@f$. */
    const double gamma_over_beta, k_r;
    /** Scratch: the nodal velocity of a force. */
    std::vector<double> velocity;
    /** The explicit integrators' damped residual and its damping
     *  force. */
    NodalVector residual_with_damping, damping_force;
    /** Per point (by step index): @f$\beta_R V^n (\lambda, \mu)@f$ of
     *  the step (begin_step()). */
    std::vector<std::pair<double, double>> scaled_moduli;
    /** An assembly group's dense block and where its rows and columns are
     *  in it: scratch of the matrix. */
    std::vector<double>       block;
    std::vector<unsigned int> row_offsets, column_offsets;
    /** Adds the groups' blocks. */
    DenseBlockAdder block_adder;
  };
} // namespace impm

#endif
