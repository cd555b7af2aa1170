#ifndef impm_coupling_time_integrator_h
#define impm_coupling_time_integrator_h

#include <deal.II/base/parameter_handler.h>

#include <impm/basis/basis_functions.h>

#include <string>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The order of an explicit step's updates: none (an implicit
   * integrator), MUSL (the increment from the updated points' momentum,
   * mapped to the nodes again: Sulsky's modified update) or USL (from the
   * nodes' updated velocity).
   */
  enum class ExplicitOrder
  {
    none,
    musl,
    usl
  };

  /**
   * @brief The time integrator of Inertia, from the entries of its
   * subsection: Newmark's @f$\beta, \gamma@f$, generalised-alpha's
   * @f$\alpha_m, \alpha_f@f$ (with @f$\beta, \gamma@f$) from the spectral
   * radius at infinity @f$\rho_\infty@f$ (Chung and Hulbert 1993:
   * @f$\alpha_m = (2\rho_\infty - 1)/(\rho_\infty + 1)@f$, @f$\alpha_f =
   * \rho_\infty/(\rho_\infty + 1)@f$, @f$\gamma = 1/2 - \alpha_m +
   * \alpha_f@f$, @f$\beta = (1 - \alpha_m + \alpha_f)^2/4@f$; Newmark has
   * @f$\alpha_m = \alpha_f = 0@f$), or the explicit central difference
   * rule with its Courant number; the mass damping and the points'
   * velocity update (FLIP/PIC or APIC) of all.
   */
  struct TimeIntegrator
  {
    /** @brief Declare the integrator's entries in the current
     *  subsection. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** @brief Read and check them (one-line InputErrors). */
    explicit TimeIntegrator(const ParameterHandler &prm);

    /** @brief Whether the integrator is explicit. */
    bool
    is_explicit() const
    {
      return explicit_order != ExplicitOrder::none;
    }

    /** @brief The weight of the end-of-step inertial force in the
     *  balance divided by @f$1 - \alpha_f@f$: @f$(1 - \alpha_m)/(1 -
     *  \alpha_f)@f$. */
    double
    k_m() const
    {
      return (1. - alpha_m) / (1. - alpha_f);
    }

    /**
     * @brief Check the velocity update against the scene: APIC with an
     * explicit integrator needs GIMP (an InputError for @p basis standard
     * MPM); with an implicit one and @p rigid_bodies, it warns on standard
     * error (if @p print) unless generalised-alpha damps the contact's
     * unresolved oscillation (spectral radius at most 0.5).
     */
    void
    check_velocity_update(const BasisType basis,
                          const bool      rigid_bodies,
                          const bool      print) const;

    /** @brief One line: the integrator and its parameters. */
    std::string
    description() const;

    /** The explicit order (none: implicit). */
    ExplicitOrder explicit_order;
    /** The explicit step's fraction of the stable one. */
    double courant_number;
    /**
     * @brief The FLIP fraction of a step of length @p time_step: 'FLIP
     * fraction' phi, or with a 'FLIP reference step' T above 0,
     * phi^(time_step / T), so that the PIC share's damping per second does
     * not depend on the step.
     */
    double
    flip_fraction_of_step(const double time_step) const;

    /** The points' velocity update's FLIP fraction (1: FLIP, 0: PIC), per
     *  step or per flip_reference_step. */
    double flip_fraction;
    /** The time step flip_fraction is given for (s; 0: every step). */
    double flip_reference_step;
    /** Whether the points carry the nodes' velocity gradient and give
     *  the nodes an affine velocity field (APIC; FLIP fraction 1). */
    bool affine_transfer;
    /** Whether the implicit integrator is generalised-alpha. */
    bool generalised_alpha;
    /** Generalised-alpha's spectral radius at infinity. */
    double spectral_radius;
    /** The weight of the start of the step in the inertia (0 for
     *  Newmark). */
    double alpha_m;
    /** The weight of the start of the step in the forces (0 for
     *  Newmark). */
    double alpha_f;
    /** Newmark's beta. */
    double beta;
    /** Newmark's gamma. */
    double gamma;
    /** The mass-proportional damping coefficient (1/s). */
    double mass_damping;
    /** The stiffness-proportional damping coefficient (s;
     *  StiffnessDamping). */
    double stiffness_damping;
    /** Local non-viscous damping's fraction (explicit only). */
    double local_damping;
    /** Whether the implicit mass is the consistent matrix. */
    bool consistent_mass;
    /** The fraction of the lumped mass added to the consistent one. */
    double mass_regularisation;
  };
} // namespace impm

#endif
