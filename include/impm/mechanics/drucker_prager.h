#ifndef impm_mechanics_drucker_prager_h
#define impm_mechanics_drucker_prager_h

#include <impm/mechanics/frictional_plasticity.h>

#include <array>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Drucker-Prager plasticity, @f$\Phi = \sqrt{J_2(\tau)} + \eta\,p
   * - \xi\,c(\bar\varepsilon^p)@f$ with the flow potential @f$\sqrt{J_2} +
   * \bar\eta\,p@f$ (p the mean stress, tension positive), and the returns
   * to the cone and to its apex (de Souza Neto et al. 2008, box 8.9).
   *
   * The constants come from the friction angle @f$\phi@f$, the dilation
   * angle @f$\psi@f$ and a match to Mohr-Coulomb:
   * - outer cone (compressive meridians): @f$\eta = 6\sin\phi/(\sqrt3
   *   (3 - \sin\phi))@f$, @f$\xi = 6\cos\phi/(\sqrt3(3 - \sin\phi))@f$;
   * - inner cone (tensile meridians): the same with @f$3 + \sin\phi@f$;
   * - plane strain: the plane-strain collapse load of Mohr-Coulomb with the
   *   same angles, @f$\bar\eta = \sqrt3\sin\psi/\sqrt{3 + \sin^2\psi}@f$,
   *   @f$\eta = \sin\phi/d@f$, @f$\xi = \cos\phi/d@f$ with @f$d =
   *   \sqrt{1 - \bar\eta^2/3} + \bar\eta\sin\phi/3@f$ (from zero plastic
   *   strain out of the plane; associated flow gives de Souza Neto's
   *   @f$\eta = 3\tan\phi/\sqrt{9 + 12\tan^2\phi}@f$, zero dilation
   *   @f$\eta = \sin\phi@f$, @f$\xi = \cos\phi@f$).
   *   For @f$\bar\eta@f$ the cones use their formula with @f$\psi@f$.
   * The equivalent plastic strain is @f$\xi\,\kappa@f$.
   */
  class DruckerPrager : public PrincipalStressPlasticity
  {
  public:
    /** How the cone is fitted to the Mohr-Coulomb surface. */
    enum class Match
    {
      /** Plane-strain collapse loads of Mohr-Coulomb. */
      plane_strain,
      /** Through the compressive meridians (outer cone). */
      outer_cone,
      /** Through the tensile meridians (inner cone). */
      inner_cone
    };

    /**
     * @brief Constructor.
     * @param parameters Elastic constants, cohesion, angles.
     * @param match The fit of the cone to Mohr-Coulomb.
     */
    DruckerPrager(const FrictionalParameters &parameters, const Match match);

    std::string
    description() const override;

    /** @brief FrictionalParameters::reduced(), fitted as before. */
    std::unique_ptr<Material>
    with_reduced_strength(const double factor) const override;

    /** @brief The constants @f$\{\eta, \xi, \bar\eta\}@f$ of a match. */
    static std::array<double, 3>
    cone_constants(const double friction_angle,
                   const double dilation_angle,
                   const Match  match);

  protected:
    void
    principal_return(const std::array<double, 3> &trial_strain,
                     const double                 cohesion,
                     const double                 hardening_slope,
                     PrincipalReturn             &result) const override;

  private:
    /** The fit. */
    const Match match;
    /** @f$\eta@f$, @f$\xi@f$ and @f$\bar\eta@f$. */
    const std::array<double, 3> constants;
  };
} // namespace impm

#endif
