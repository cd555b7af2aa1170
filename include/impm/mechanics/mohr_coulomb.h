#ifndef impm_mechanics_mohr_coulomb_h
#define impm_mechanics_mohr_coulomb_h

#include <impm/mechanics/frictional_plasticity.h>

#include <array>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Mohr-Coulomb plasticity, @f$\Phi = \tau_1 - \tau_3 + (\tau_1 +
   * \tau_3)\sin\phi - 2c\cos\phi@f$ with the principal stresses @f$\tau_1
   * \ge \tau_2 \ge \tau_3@f$ (tension positive) and the flow potential with
   * @f$\psi@f$ in place of @f$\phi@f$: the returns to a plane, to the edges
   * @f$\tau_1 = \tau_2@f$ and @f$\tau_2 = \tau_3@f$ and to the apex
   * (de Souza Neto et al. 2008, boxes 8.4 and 8.5), each with its exact
   * tangent. With linear hardening every return is a linear solve.
   * The equivalent plastic strain is @f$2\cos\phi\,\kappa@f$.
   *
   * An optional tension cut-off (Rankine, associated flow) bounds every
   * principal stress by the tensile strength @f$T@f$ (where T is below the
   * apex pressure @f$c\cot\phi@f$; at or above it, it cuts nothing and
   * the returns are those above): the return then looks for the set of active
   * surfaces among the three Mohr-Coulomb planes and the three tension
   * planes whose multipliers are non-negative and whose stresses violate no
   * surface and keep their order. Plastic flow on a tension plane does not
   * change the cohesion.
   */
  class MohrCoulomb : public PrincipalStressPlasticity
  {
  public:
    /**
     * @brief Constructor.
     * @param parameters Elastic constants, cohesion, angles.
     * @param tensile_strength The tension cut-off T in Pa, or a negative
     *   number for none.
     */
    explicit MohrCoulomb(const FrictionalParameters &parameters,
                         const double                tensile_strength = -1.);

    /**
     * @brief Declare the entries of the Mohr-Coulomb subsection: those of
     * FrictionalParameters and the tension cut-off.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    std::string
    description() const override;

    /**
     * @brief FrictionalParameters::reduced(), and the tensile strength
     * divided by @p factor.
     */
    std::unique_ptr<Material>
    with_reduced_strength(const double factor) const override;

  protected:
    void
    principal_return(const std::array<double, 3> &trial_strain,
                     const double                 cohesion,
                     const double                 hardening_slope,
                     PrincipalReturn             &result) const override;

  private:
    /**
     * @brief A linear yield surface in principal stresses, @f$N \cdot
     * \tau \le r@f$, with flow direction M.
     */
    struct Surface
    {
      /** The normal N and the flow direction M. */
      std::array<double, 3> normal, flow;
      /** The level r at the start of the return. */
      double level;
      /** Whether its level is @f$2c\cos\phi@f$ (it hardens with the
       *  cohesion and its multiplier is plastic strain). */
      bool cohesive;
    };

    /**
     * @brief The Mohr-Coulomb plane of the principal indices @p larger and
     * @p smaller at cohesion @p c.
     */
    Surface
    plane(const unsigned int larger,
          const unsigned int smaller,
          const double       c) const;

    /**
     * @brief The return to @p surfaces at once (one to three): all active,
     * their multipliers from one linear solve; false if a multiplier came
     * out negative.
     */
    bool
    return_to_surfaces(const std::array<double, 3> &trial_stress,
                       const std::vector<Surface>  &surfaces,
                       const double                 hardening_slope,
                       PrincipalReturn             &result) const;

    /**
     * @brief With the tension cut-off: the first set of active surfaces
     * (fewest first) whose return is admissible.
     */
    void
    return_with_cut_off(const std::array<double, 3> &trial_stress,
                        const double                 cohesion,
                        const double                 hardening_slope,
                        PrincipalReturn             &result) const;

    /** The tension cut-off T (negative: none). */
    double tensile_strength;
  };
} // namespace impm

#endif
