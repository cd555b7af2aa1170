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
   */
  class MohrCoulomb : public PrincipalStressPlasticity
  {
  public:
    /** @brief Constructor. */
    explicit MohrCoulomb(const FrictionalParameters &parameters);

    std::string
    description() const override;

  protected:
    void
    principal_return(const std::array<double, 3> &trial_strain,
                     const double                 cohesion,
                     const double                 hardening_slope,
                     PrincipalReturn             &result) const override;

  private:
    /**
     * @brief The return to the planes @p planes at once (one or two), each
     * given by its larger and smaller principal index; false if a
     * multiplier came out negative.
     */
    bool
    return_to_planes(const std::array<double, 3>                &trial_stress,
                     const std::vector<std::array<unsigned, 2>> &planes,
                     const double                                cohesion,
                     const double     hardening_slope,
                     PrincipalReturn &result) const;
  };
} // namespace impm

#endif
