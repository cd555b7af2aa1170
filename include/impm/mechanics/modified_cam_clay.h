#ifndef impm_mechanics_modified_cam_clay_h
#define impm_mechanics_modified_cam_clay_h

#include <deal.II/base/parameter_handler.h>

#include <impm/mechanics/material.h>

#include <array>
#include <string>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Modified Cam-clay at finite strain: hyperelastic,
   * pressure-dependent elasticity in the principal logarithmic elastic
   * strains, the elliptical yield surface in Kirchhoff stress with
   * associated flow, and hardening of the preconsolidation pressure with
   * the plastic volume change; the exponential-map return in principal
   * stresses with its exact tangent (after Borja and Tamagnini 1998, with
   * other unknowns).
   *
   * <b>Signs.</b> IMPM's stresses and strains are tension positive. This
   * model works in the soil-mechanics invariants, compression positive:
   * the mean effective Kirchhoff stress @f$p = -\mathrm{tr}\,\tau/3@f$, the
   * deviatoric stress @f$q = \sqrt{3/2}\,|\mathrm{dev}\,\tau|@f$, the
   * volumetric logarithmic strain @f$\varepsilon_v = -\mathrm{tr}\,
   * \varepsilon@f$ and the shear strain @f$\varepsilon_s = \sqrt{2/3}\,
   * |\mathrm{dev}\,\varepsilon|@f$, with @f$\varepsilon = \tfrac12\ln b@f$
   * (b the elastic left Cauchy-Green tensor for the elastic strain).
   *
   * <b>Elasticity</b> (conservative): the stored energy
   * @f$\psi = p_{ref}\,\kappa^*\,\exp(\varepsilon^e_v/\kappa^*) +
   * \tfrac32\,G\,(\varepsilon^e_s)^2@f$ separates into a volumetric and a
   * deviatoric part, so @f$p = p_{ref}\exp(\varepsilon^e_v/\kappa^*)@f$,
   * @f$q = 3G\varepsilon^e_s@f$, @f$\tau = \partial\psi/\partial
   * \varepsilon^e@f$, with the tangent bulk modulus @f$K = p/\kappa^*@f$
   * and a constant shear modulus G: the energy is convex for every strain,
   * so no closed elastic cycle creates or dissipates energy. A constant
   * Poisson's ratio (G proportional to K(p)) was not chosen: its
   * @f$\partial q/\partial\varepsilon^e_v \neq \partial p/\partial
   * \varepsilon^e_s@f$ for any shear, so the law has no potential and
   * closed strain cycles create energy (Zytynski et al. 1978). The elastic
   * strain is zero at @f$p = p_{ref}@f$, q = 0; @f$p > 0@f$ at every finite
   * strain, and no strain gives zero stress.
   *
   * <b>Compression indices.</b> @f$\lambda@f$ and @f$\kappa@f$ are the
   * slopes of the normal compression and swelling lines in e - ln p' at
   * the initial void ratio @f$e_0@f$; the model uses @f$\kappa^* =
   * \kappa/(1 + e_0)@f$ and @f$\lambda^* = \lambda/(1 + e_0)@f$ as the
   * slopes of ln v - ln p (v = 1 + e the specific volume, ln v - ln v_0 =
   * ln J the logarithmic volume change; Butterfield 1979). So ln v is
   * linear in ln p exactly (slope @f$-\lambda^*@f$ on the normal compression
   * line, @f$-\kappa^*@f$ on swelling), and the slope in e - ln p is
   * @f$\lambda\,v/v_0@f$: equal to @f$\lambda@f$ only at @f$v = v_0@f$. The
   * pressure of these lines is the Kirchhoff one (Cauchy times J).
   *
   * <b>Plasticity.</b> @f$f = q^2/M^2 + p\,(p - p_c)@f$, associated flow
   * @f$\Delta\varepsilon^p = \Delta\gamma\,\partial f/\partial\tau@f$ (in
   * the invariants, @f$\Delta\varepsilon^p_v = \Delta\gamma\,(2p - p_c)@f$
   * compression positive, @f$\Delta\varepsilon^p_s = \Delta\gamma\,2q/M^2@f$)
   * and @f$p_c = p_{c,n}\exp(\Delta\varepsilon^p_v/(\lambda^* -
   * \kappa^*))@f$: compaction (@f$\Delta\varepsilon^p_v > 0@f$, the wet
   * side @f$p > p_c/2@f$) hardens, dilation (the dry side) softens. The
   * exponential map makes the logarithmic strains additive, so along the
   * normal compression line @f$\ln J = -\lambda^*\ln(p/p_0)@f$ exactly.
   *
   * <b>Return.</b> The trial deviatoric direction is kept, so @f$q = q^{tr}
   * \rho@f$ with @f$\rho = 1/(1 + 6G\Delta\gamma/M^2)@f$. The unknowns are
   * @f$\varepsilon^e_v@f$ and @f$\Delta\gamma@f$: for a given
   * @f$\Delta\gamma@f$ the volumetric equation @f$\varepsilon^e_v -
   * \varepsilon^{tr}_v + \Delta\gamma\,(2p - p_c) = 0@f$ is strictly
   * increasing in @f$\varepsilon^e_v@f$ and has its root between the trial
   * value and the critical-state value (where @f$2p = p_c@f$, closed form),
   * solved by Newton's method kept in that bracket; the yield function as a
   * function of @f$\Delta\gamma@f$ is positive at zero and negative for
   * large @f$\Delta\gamma@f$, solved by Newton's method with bisection
   * once bracketed. The exact tangent @f$D_{ab} = \partial\tau_a/
   * \partial\varepsilon^{tr}_b@f$ follows by differentiating the two
   * equations at the solution; the off-diagonal coefficient is
   * @f$2G\rho@f$. The tangent is not symmetric (the hardening variable
   * follows the plastic volume change, not @f$-\Delta\gamma\,\partial f/
   * \partial p_c@f$), as tests/cam_clay_tangent.cc measures.
   *
   * <b>Low mean stress.</b> The trial pressure is positive at any finite
   * strain, so there is no tension and no cut-off: a state expanded far
   * beyond @f$p_{ref}@f$ has a small p and a small bulk modulus, and a
   * shear returns it to the dry side of the ellipse. An exponential that
   * overflows or underflows (an iterate far from the solution) throws, which
   * fails the Newton iteration.
   *
   * The state is the preconsolidation pressure @f$p_c@f$ (the tip of the
   * ellipse), `preconsolidation_pressure`.
   */
  class ModifiedCamClay : public Material
  {
  public:
    /** The model's parameters, in the subsection "Modified Cam-clay". */
    struct Parameters
    {
      /** M, the critical-state stress ratio q/p. */
      double critical_state_ratio = 1.;
      /** @f$\lambda@f$, slope of the normal compression line in e-ln p'. */
      double lambda = 0.2;
      /** @f$\kappa@f$, slope of the swelling line in e-ln p'. */
      double kappa = 0.04;
      /** The initial void ratio @f$e_0@f$. */
      double initial_void_ratio = 1.;
      /** The shear modulus G in Pa. */
      double shear_modulus = 3e6;
      /** @f$p_{ref}@f$ in Pa: the p at zero elastic strain. */
      double reference_pressure = 1e5;
      /** The overconsolidation ratio of a new point, @f$\ge 1@f$. */
      double overconsolidation_ratio = 1.;

      /** @brief Declare the entries in the current subsection. */
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * @brief Read them, with one line naming the entry for a bad value
       * (after @p path, the subsection's path).
       */
      void
      parse_parameters(ParameterHandler &prm, const std::string &path);
    };

    /** What principal_return() gives. */
    struct PrincipalReturn
    {
      /** Principal Kirchhoff stresses, in the order of the strains. */
      std::array<double, 3> stress;
      /** Principal logarithmic elastic strains. */
      std::array<double, 3> elastic_strain;
      /** @f$D_{ab} = \partial\tau_a / \partial\varepsilon^{tr}_b@f$. */
      double tangent[3][3];
      /** The off-diagonal coefficient @f$2G\rho@f$. */
      double shear_coefficient = 0.;
      /** @f$\Delta\gamma@f$ (zero if elastic), in 1/Pa. */
      double plastic_multiplier = 0.;
      /** @f$p_c@f$ at the end of the step. */
      double preconsolidation_pressure = 0.;
      /** Whether the return was active. */
      bool plastic = false;
    };

    /** @brief Constructor, from checked parameters. */
    explicit ModifiedCamClay(const Parameters &parameters);

    using Material::update;

    /** @brief The preconsolidation pressure @f$p_c@f$ (written). */
    PointFields
    state_fields() const override;

    /**
     * @brief @f$p_c = \mathrm{OCR}\,(p + q^2/(M^2 p))@f$: OCR times the
     * tip of the ellipse through the stress (the isotropic definition of the
     * overconsolidation ratio), so OCR = 1 starts on the surface; at zero
     * stress p is @f$p_{ref}@f$, the pressure of zero elastic strain.
     */
    void
    initialize_state(const SymmetricTensor<2, 3> &kirchhoff_stress,
                     const ArrayView<double>     &state) const override;

    /** @brief The return, with @f$p_{c,n}@f$ the first entry of @p state. */
    void
    update(const Tensor<2, 3>            &deformation_increment,
           const SymmetricTensor<2, 3>   &previous_elastic_strain,
           const ArrayView<const double> &state,
           ConstitutiveUpdate            &result) const override;

    /** @brief The preconsolidation pressure at the end of the step. */
    void
    store_state(const ConstitutiveUpdate &result,
                const ArrayView<double>  &state) const override;

    /**
     * @brief The tangent from the return's exact principal tangent
     * (computed again from the trial eigenvalues and @f$p_{c,n}@f$) through
     * principal_frame_response().
     */
    void
    tangent(const ConstitutiveUpdate &result,
            const unsigned int        n_components,
            Tensor<4, 3>             &C) const override;

    /**
     * @brief The material part of the pulled-back tangent, directly (the
     * rotation of pull_back_rotation()), at the cost of tangent().
     */
    void
    pulled_back_tangent(const ConstitutiveUpdate &result,
                        const unsigned int        n_components,
                        const Tensor<2, 3>       &deformation_increment_inverse,
                        Tensor<4, 3>             &M) const override;

    /** @brief False: the plastic tangent is not symmetric (see above). */
    bool
    has_symmetric_tangent() const override
    {
      return false;
    }

    /**
     * @brief The elastic law inverted: @f$\varepsilon^e_v = \kappa^*
     * \ln(p/p_{ref})@f$, @f$\mathrm{dev}\,\varepsilon^e =
     * \mathrm{dev}\,\tau/(2G)@f$. Throws an InputError for @f$p \le 0@f$,
     * which no strain reaches.
     */
    SymmetricTensor<2, 3>
    elastic_strain_for_stress(
      const SymmetricTensor<2, 3> &kirchhoff_stress) const override;

    /** @brief "Modified Cam-clay: M = ..., lambda = ..., ..., OCR = ...". */
    std::string
    description() const override;

    /**
     * @brief M reduced through the friction angle it has in triaxial
     * compression, @f$\sin\phi = 3M/(6 + M)@f$: @f$\tan\phi_F = \tan\phi
     * / F@f$ and @f$M_F = 6 \sin\phi_F / (3 - \sin\phi_F)@f$; the
     * compression and swelling lines, the shear modulus and the
     * preconsolidation pressure unchanged.
     */
    std::unique_ptr<Material>
    with_reduced_strength(const double factor) const override;

    /**
     * @brief The initial void ratio @f$e_0@f$: the void ratio of a point
     * whose deformation gradient has determinant J is @f$(1 + e_0) J - 1@f$.
     */
    double
    initial_void_ratio() const
    {
      return parameters.initial_void_ratio;
    }

    /**
     * @brief Young's modulus at the reference pressure, @f$9KG/(3K + G)@f$
     * with @f$K = p_{ref}/\kappa^*@f$: the stiffness that scales penalties.
     */
    double
    elastic_modulus() const override;

    /** @brief @f$K + 4\mu/3@f$ at the reference pressure (the bulk
     *  modulus grows with the mean stress: an explicit step's limit takes
     *  each point's, p_wave_modulus_at()). */
    double
    p_wave_modulus() const override;

    /** @brief @f$p'/\kappa^* + 4\mu/3@f$ at the mean stress @f$p' =
     *  -\mathrm{tr}\,\tau/3@f$ of @p kirchhoff_stress (the tangent bulk
     *  modulus of @f$p' = p_{ref} \exp(\varepsilon_v^e/\kappa^*)@f$), or
     *  that of the reference pressure where @f$p'@f$ is below it. */
    double
    p_wave_modulus_at(
      const dealii::SymmetricTensor<2, 3> &kirchhoff_stress) const override;

    /** @brief The constant shear modulus. */
    double
    shear_modulus() const override
    {
      return mu;
    }

    /**
     * @brief The return map in principal stresses from the trial
     * logarithmic strains @p trial_strain and @f$p_{c,n}@f$.
     */
    PrincipalReturn
    principal_return(const std::array<double, 3> &trial_strain,
                     const double preconsolidation_pressure) const;

    /** @brief @f$\kappa^* = \kappa/(1 + e_0)@f$. */
    double
    modified_kappa() const
    {
      return kappa_star;
    }

    /** @brief @f$\lambda^* = \lambda/(1 + e_0)@f$. */
    double
    modified_lambda() const
    {
      return kappa_star + theta;
    }

    /** @brief The parameters. */
    const Parameters &
    get_parameters() const
    {
      return parameters;
    }

    /** @brief @f$p = -\mathrm{tr}\,\tau/3@f$ (compression positive). */
    static double
    mean_pressure(const SymmetricTensor<2, 3> &kirchhoff_stress);

    /** @brief @f$q = \sqrt{3/2}\,|\mathrm{dev}\,\tau|@f$. */
    static double
    deviatoric_stress(const SymmetricTensor<2, 3> &kirchhoff_stress);

  private:
    /**
     * @brief The elastic volumetric strain (compression positive) of the
     * volumetric equation at @p dgamma, in the bracket [@p low, @p high]
     * that holds the root, from @p guess.
     */
    double
    volumetric_strain_at(const double dgamma,
                         const double trial_volumetric,
                         const double preconsolidation_pressure,
                         double       low,
                         double       high,
                         const double guess) const;

    /**
     * @brief The exact principal tangent at the solution (@p volumetric,
     * @p dgamma) of the plastic return, whose end-of-step preconsolidation
     * pressure @p result holds, into @p result.tangent.
     */
    void
    plastic_tangent(const std::array<double, 3> &trial_deviator,
                    const double                 trial_q,
                    const double                 volumetric,
                    const double                 dgamma,
                    PrincipalReturn             &result) const;

    /**
     * @brief principal_frame_response() with the return's principal
     * tangent for perturbations rotated by @p R.
     */
    void
    response(const ConstitutiveUpdate &result,
             const unsigned int        n_components,
             const Tensor<2, 3>       &R,
             Tensor<4, 3>             &T) const;

    /** The parameters. */
    const Parameters parameters;
    /** @f$\kappa^*@f$. */
    const double kappa_star;
    /** @f$\lambda^* - \kappa^*@f$. */
    const double theta;
    /** G. */
    const double mu;
    /** @f$M^2@f$. */
    const double M2;
  };
} // namespace impm

#endif
