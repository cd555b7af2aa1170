#ifndef impm_mechanics_frictional_plasticity_h
#define impm_mechanics_frictional_plasticity_h

#include <deal.II/base/parameter_handler.h>

#include <impm/mechanics/material.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The cohesion of a frictional material as a function of the
   * equivalent plastic strain @f$\bar\varepsilon^p@f$: linear hardening
   * (H > 0) or softening (H < 0) from the initial value, never below the
   * residual value.
   */
  struct CohesionLaw
  {
    /** Initial cohesion @f$c_0 \ge 0@f$ in Pa. */
    double initial = 0.;
    /** Hardening modulus @f$H = dc/d\bar\varepsilon^p@f$ in Pa. */
    double hardening_modulus = 0.;
    /** Residual cohesion in Pa, the floor of a softening cohesion. */
    double residual = 0.;

    /**
     * @brief The branch of the law at @p equivalent_plastic_strain: the
     * cohesion there and the slope that holds beyond it (zero on the floor).
     */
    std::pair<double, double>
    branch(const double equivalent_plastic_strain) const;
  };

  /**
   * @brief The parameters the frictional models share: elastic constants,
   * cohesion law, friction and dilation angles.
   */
  struct FrictionalParameters
  {
    /** Young's modulus E. */
    double youngs_modulus = 1e6;
    /** Poisson's ratio. */
    double poissons_ratio = 0.;
    /** The cohesion and its hardening. */
    CohesionLaw cohesion;
    /** Friction angle in radians, in [0, pi/2). */
    double friction_angle = 0.;
    /** Dilation angle in radians, in [0, friction angle]. */
    double dilation_angle = 0.;

    /**
     * @brief Declare Young's modulus, Poisson's ratio, Cohesion, Friction
     * angle, Dilation angle, Hardening modulus and Residual cohesion in the
     * current subsection.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief Read them, with one line naming the entry for a value out of
     * range (a dilation angle above the friction angle, a residual cohesion
     * above the cohesion, a material with neither cohesion nor friction)
     * after @p path, the subsection's path.
     */
    void
    parse_parameters(ParameterHandler &prm, const std::string &path);

    /** @brief "E = ..., nu = ..., c = ..., phi = ..., psi = ..." (and H). */
    std::string
    description() const;

    /**
     * @brief The parameters of a strength reduction by @p factor: the
     * cohesion law (initial, residual, hardening modulus) divided by it,
     * @f$\tan\phi_F = \tan\phi / F@f$ and @f$\tan\psi_F = \tan\psi /
     * F@f$ (so that the dilation angle stays below the friction angle), the
     * elastic constants unchanged.
     */
    FrictionalParameters
    reduced(const double factor) const;
  };

  /**
   * @brief Where a return map ended: used by the tests and by the
   * description of a point's state.
   */
  enum class ReturnRegion
  {
    /** Inside the yield surface. */
    elastic,
    /** On a smooth part of the surface (DP cone, one MC plane). */
    smooth,
    /** On an edge of two Mohr-Coulomb planes. */
    edge,
    /** At the apex. */
    apex,
    /** On a tension cut-off plane (alone or with others). */
    tension_cut_off
  };

  /** @brief The name of a region ("smooth surface", "edge", ...). */
  std::string
  return_region_name(const ReturnRegion region);

  /**
   * @brief Hencky elasticity with a plastic return map in principal
   * Kirchhoff stresses: the base of the frictional models.
   *
   * The trial elastic strain @f$\varepsilon^{tr} = \tfrac12 \ln
   * b^e_{tr}@f$ and the stress share principal directions; the exponential
   * map makes the finite-strain return the small-strain return of a model
   * in principal stresses (de Souza Neto, Peric and Owen 2008, ch. 14), so
   * a model only gives principal_return(): the returned principal stresses
   * and their exact derivative @f$D_{ab} = \partial\tau_a / \partial
   * \varepsilon^{tr}_b@f$. The full tangent follows from
   * principal_frame_response(). The tangent does not store that
   * derivative per point: it calls the return again from the trial
   * eigenvalues, which costs a few dozen operations.
   *
   * The model's one state variable is the point's accumulated plastic
   * multiplier @f$\kappa@f$ (`plastic_multiplier`); the equivalent plastic
   * strain that drives the cohesion is @f$\bar\varepsilon^p = h\,\kappa@f$
   * with the model's factor h.
   */
  class PrincipalStressPlasticity : public Material
  {
  public:
    /**
     * @brief Constructor.
     * @param parameters Elastic constants, cohesion, angles.
     * @param hardening_factor h in @f$\bar\varepsilon^p = h\,\kappa@f$.
     */
    PrincipalStressPlasticity(const FrictionalParameters &parameters,
                              const double                hardening_factor);

    using Material::update;

    /** @brief The accumulated plastic multiplier @f$\kappa@f$. */
    PointFields
    state_fields() const override;

    /** @brief The return, with @f$\kappa@f$ the first entry of @p state. */
    void
    update(const Tensor<2, 3>            &deformation_increment,
           const SymmetricTensor<2, 3>   &previous_elastic_strain,
           const ArrayView<const double> &state,
           ConstitutiveUpdate            &result) const override;

    /** @brief Accumulate @f$\kappa@f$. */
    void
    store_state(const ConstitutiveUpdate &result,
                const ArrayView<double>  &state) const override;

    void
    tangent(const ConstitutiveUpdate &result,
            const unsigned int        n_components,
            Tensor<4, 3>             &C) const override;

    void
    pulled_back_tangent(const ConstitutiveUpdate &result,
                        const unsigned int        n_components,
                        const Tensor<2, 3>       &deformation_increment_inverse,
                        Tensor<4, 3>             &M) const override;

    /**
     * @brief True for associated flow (dilation angle equal to the friction
     * angle): the return is then a closest-point projection in the energy
     * norm and the tangent symmetric.
     */
    bool
    has_symmetric_tangent() const override
    {
      return parameters.dilation_angle == parameters.friction_angle;
    }

    double
    elastic_modulus() const override
    {
      return parameters.youngs_modulus;
    }

    double
    p_wave_modulus() const override
    {
      const double nu = parameters.poissons_ratio;
      return parameters.youngs_modulus * (1. - nu) /
             ((1. + nu) * (1. - 2. * nu));
    }

    double
    shear_modulus() const override
    {
      return mu;
    }

    SymmetricTensor<2, 3>
    elastic_strain_for_stress(
      const SymmetricTensor<2, 3> &kirchhoff_stress) const override
    {
      return hencky_elastic_strain_for_stress(lambda, mu, kirchhoff_stress);
    }

    /**
     * @brief The region of the yield surface the last update returned to.
     */
    ReturnRegion
    return_region(const ConstitutiveUpdate &result) const;

  protected:
    /** What principal_return() gives. */
    struct PrincipalReturn
    {
      /** Principal Kirchhoff stresses, in the order of the strains. */
      std::array<double, 3> stress;
      /** @f$D_{ab} = \partial\tau_a / \partial\varepsilon^{tr}_b@f$. */
      double tangent[3][3];
      /** Increment of the equivalent plastic strain. */
      double equivalent_plastic_strain = 0.;
      /** The region of the surface. */
      ReturnRegion region = ReturnRegion::elastic;
    };

    /**
     * @brief The return map in principal stresses.
     * @param trial_strain Principal trial logarithmic strains, in
     *   descending order (so are the trial stresses).
     * @param cohesion The cohesion at the start of the step.
     * @param hardening_slope @f$dc/d\bar\varepsilon^p@f$ on this branch of
     *   the cohesion law.
     * @param[out] result Stresses, tangent, plastic strain, region.
     */
    virtual void
    principal_return(const std::array<double, 3> &trial_strain,
                     const double                 cohesion,
                     const double                 hardening_slope,
                     PrincipalReturn             &result) const = 0;

    /**
     * Relative margin of the yield checks: a point returned in the step
     * before sits on the surface up to round-off, and the choice of branch
     * must not depend on it (nor on the number of processes).
     */
    static constexpr double yield_margin = 1e-10;

    /**
     * @brief The return to the apex of a cone, shared by the models: the
     * mean stress @f$p = p_{tr} - K\,\Delta\varepsilon^p_v@f$ reaches
     * @f$k\,c(\bar\varepsilon^p)@f$ with @f$\bar\varepsilon^p =
     * \alpha\,\Delta\varepsilon^p_v@f$ (linear, so one division), and
     * @f$D = K(1 - K/(K + k \alpha H))\, 1 \otimes 1@f$.
     * @param trial_pressure @f$p_{tr}@f$.
     * @param apex_ratio k, the apex pressure per unit cohesion.
     * @param alpha @f$\alpha@f$.
     * @param cohesion, hardening_slope As for principal_return().
     * @param[out] result Stresses, tangent, plastic strain, region.
     */
    void
    apex_return(const double     trial_pressure,
                const double     apex_ratio,
                const double     alpha,
                const double     cohesion,
                const double     hardening_slope,
                PrincipalReturn &result) const;

    /** @brief The elastic principal stresses of the strains @p strain. */
    std::array<double, 3>
    elastic_stress(const std::array<double, 3> &strain) const;

    /** @brief The elastic principal tangent, @f$\lambda\, 1 \otimes 1 + 2
     * \mu I@f$. */
    void
    elastic_tangent(double D[3][3]) const;

    /** The parameters. */
    const FrictionalParameters parameters;
    /** Lame's first parameter. */
    const double lambda;
    /** Shear modulus. */
    const double mu;
    /** Bulk modulus. */
    const double bulk;

  private:
    /**
     * @brief principal_return() on the branch of the cohesion law that the
     * result lies on, from the trial eigenvalues and the hardening variable
     * of @p result.
     */
    void
    return_on_branch(const std::array<double, 3> &trial_eigenvalues,
                     const double                 hardening_variable,
                     PrincipalReturn             &principal) const;

    /**
     * @brief The response to perturbations rotated by @p R (see
     * principal_frame_response()).
     */
    void
    response(const ConstitutiveUpdate &result,
             const unsigned int        n_components,
             const Tensor<2, 3>       &R,
             Tensor<4, 3>             &T) const;

    /** h in @f$\bar\varepsilon^p = h\,\kappa@f$. */
    const double hardening_factor;
  };
} // namespace impm

#endif
