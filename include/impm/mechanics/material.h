#ifndef impm_mechanics_material_h
#define impm_mechanics_material_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <impm/base/plugin_list.h>
#include <impm/base/point_field.h>
#include <impm/mechanics/spectral_decomposition.h>

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief What a constitutive update returns: the new state and what its
   * tangent needs.
   *
   * All tensors are 3x3: in plane strain the out-of-plane stretch is one but
   * the out-of-plane stress is not zero.
   */
  struct ConstitutiveUpdate
  {
    /** Kirchhoff stress @f$\tau@f$ at the end of the step. */
    SymmetricTensor<2, 3> kirchhoff_stress;
    /** Elastic left Cauchy-Green tensor @f$b^e_{n+1}@f$. */
    SymmetricTensor<2, 3> elastic_left_cauchy_green;
    /** Plastic multiplier increment @f$\Delta\gamma@f$ (zero if elastic). */
    double plastic_multiplier = 0.;

    /** Eigenvalues of the trial @f$b^e_{tr}@f$. */
    std::array<double, 3> trial_eigenvalues;
    /** Eigenvectors of the trial @f$b^e_{tr}@f$, one per column. */
    Tensor<2, 3> trial_eigenvectors;
    /** Whether the return map was active (the step is plastic). */
    bool plastic = false;
    /** @f$\rho_y/\rho_{tr}@f$ when plastic. */
    double return_ratio = 1.;
    /** Unit deviatoric flow direction in the principal frame when plastic. */
    std::array<double, 3> flow_direction = {{0., 0., 0.}};
    /**
     * The hardening variable at the start of the step, as update() read it
     * from the point's state (the accumulated plastic multiplier); models
     * with hardening need it again in their tangent.
     */
    double hardening_variable = 0.;
    /**
     * The stored elastic energy per unit reference volume as the update
     * found it: @f$\tfrac12\,\tau : \varepsilon_e@f$ in its principal
     * frame (set_coaxial_state()), or the model's own where its elasticity
     * is not linear in the logarithmic strain (Cam-clay's potential), or
     * NaN where the update did not set it (then elastic_energy_density()
     * decomposes @f$b_e@f$).
     */
    double elastic_energy = std::numeric_limits<double>::quiet_NaN();
  };

  /**
   * @brief The elastic energy per unit reference volume of an update,
   * @f$\tfrac12\,\tau : \varepsilon_e@f$ with the elastic logarithmic
   * strain @f$\varepsilon_e = \tfrac12 \ln b_e@f$: exact for the elastic
   * laws linear in the logarithmic strain (Hencky, and the plastic models
   * built on it). The value the update stored
   * (ConstitutiveUpdate::elastic_energy: a pressure-dependent elasticity
   * stores its own potential, as Cam-clay does) if any, else from the
   * spectral decomposition of @f$b_e@f$.
   */
  double
  elastic_energy_density(const ConstitutiveUpdate &update);

  /**
   * @brief The energy per unit reference volume a plastic update's return
   * map dissipated: @f$\tau^{n+1} : (\varepsilon^{tr}_e -
   * \varepsilon^{n+1}_e)@f$ in the trial's principal frame (the
   * exponential map's return is coaxial), the backward Euler rule's
   * plastic work; zero for an elastic update.
   */
  double
  plastic_dissipation_density(const ConstitutiveUpdate &update);

  /**
   * @brief The spectral decomposition of the trial elastic left
   * Cauchy-Green tensor @f$b^e_{tr} = \Delta F\, b^e_n\, \Delta F^T@f$
   * into @p result's trial eigenvalues and eigenvectors (descending).
   * Throws if an eigenvalue is not positive and finite (an iterate far from
   * the solution), which fails the Newton iteration.
   * @return The trial logarithmic strains @f$\tfrac12 \ln \lambda_a@f$.
   */
  std::array<double, 3>
  decompose_trial_strain(const Tensor<2, 3>          &deformation_increment,
                         const SymmetricTensor<2, 3> &previous_elastic_strain,
                         ConstitutiveUpdate          &result);

  /**
   * @brief Set @p result's Kirchhoff stress and elastic left Cauchy-Green
   * tensor from principal values along its trial eigenvectors:
   * @f$\tau = \sum_a \tau_a n_a \otimes n_a@f$, @f$b^e = \sum_a
   * \exp(2 \varepsilon_a) n_a \otimes n_a@f$.
   */
  void
  set_coaxial_state(const std::array<double, 3> &principal_stress,
                    const std::array<double, 3> &principal_elastic_strain,
                    ConstitutiveUpdate          &result);

  /**
   * @brief The rotation @f$R = Q^T \Delta F^{-T}@f$ that makes
   * principal_frame_response() give the material part of the pulled-back
   * tangent: a perturbation @f$d(\Delta F) = e_k \otimes e_q@f$ is
   * @f$G = e_k \otimes@f$ (row q of @f$\Delta F^{-1}@f$), in the principal
   * frame @f$G'_{ab} = Q_{ka} R_{bq}@f$, and @f$\tau \Delta F^{-T}@f$
   * rotates back as @f$Q\, d\tau'\, R@f$.
   */
  Tensor<2, 3>
  pull_back_rotation(const Tensor<2, 3> &Q,
                     const Tensor<2, 3> &deformation_increment_inverse,
                     const unsigned int  n_components);

  /**
   * @brief Hencky elasticity inverted: the @f$b^e = \exp(2\varepsilon^e)@f$
   * with @f$\tau = \lambda\,\mathrm{tr}\,\varepsilon^e\, I + 2\mu\,
   * \varepsilon^e@f$.
   */
  SymmetricTensor<2, 3>
  hencky_elastic_strain_for_stress(
    const double                 lambda,
    const double                 mu,
    const SymmetricTensor<2, 3> &kirchhoff_stress);

  /**
   * @brief The response of an isotropic function of the trial logarithmic
   * strain, @f$\tau = \sum_a \tau_a(\varepsilon^{tr})\, n_a \otimes
   * n_a@f$, to perturbations of the deformation increment: the step from a
   * principal-space tangent to the full tangent, shared by all models.
   *
   * For the perturbation (k, l) the principal-frame gradient is
   * @f$G'_{ab} = Q_{ka} R_{bl}@f$, the change of the trial strain
   * @f$d\varepsilon'_{ab} = \tfrac12 \theta_{ab} (\lambda_b G'_{ab} +
   * \lambda_a G'_{ba})@f$ with the divided differences @f$\theta@f$ of the
   * logarithm, and the change of stress @f$d\tau'_{aa} = \sum_b D_{ab}\,
   * d\varepsilon'_{bb}@f$ on the diagonal, @f$d\tau'_{ab} = c_{ab}\,
   * d\varepsilon'_{ab}@f$ off it. The result is @f$T_{imkl} =
   * Q_{ia}\,d\tau'_{ab}\,R_{bm}@f$: with @f$R = Q^T@f$ the tangent
   * @f$\mathcal C@f$, with @f$R = Q^T \Delta F^{-T}@f$ the material part of
   * the pulled-back tangent.
   *
   * @param trial_eigenvalues Eigenvalues @f$\lambda_a@f$ of @f$b^e_{tr}@f$.
   * @param Q Its eigenvectors, one per column.
   * @param R The rotation of the perturbation (see above).
   * @param D Principal algorithmic tangent, @f$D_{ab} = \partial\tau_a /
   *   \partial \varepsilon^{tr}_b@f$.
   * @param shear Off-diagonal coefficients @f$c_{ab}@f$ (a != b; for
   *   distinct strains @f$(\tau_a - \tau_b)/(\varepsilon_a -
   *   \varepsilon_b)@f$).
   * @param n_components 2 in plane strain, 3 in 3D.
   * @param[out] T The response; entries with an index at or above
   *   @p n_components are not set.
   */
  void
  principal_frame_response(const std::array<double, 3> &trial_eigenvalues,
                           const Tensor<2, 3>          &Q,
                           const Tensor<2, 3>          &R,
                           const double                 D[3][3],
                           const double                 shear[3][3],
                           const unsigned int           n_components,
                           Tensor<4, 3>                &T);

  /**
   * @brief Interface of a constitutive model for finite strain with a
   * multiplicative split and an exponential-map return.
   *
   * A model maps the increment of deformation gradient @f$\Delta F@f$ and the
   * previous elastic left Cauchy-Green tensor to the Kirchhoff stress, and
   * provides @f$\mathcal C@f$ with @f$d\tau = \mathcal C : G@f$ for a
   * perturbation @f$d(\Delta F) = G\,\Delta F@f$.
   */
  class Material
  {
  public:
    /** Destructor. */
    virtual ~Material() = default;

    /**
     * @brief The state variables the model stores at each of its points,
     * beside the stress and the elastic strain every point has (a
     * hardening variable, a preconsolidation pressure, a back stress): the
     * points' layout, their files and the checkpoint follow from this
     * declaration. update() sees the entries in this order. The default is
     * none.
     */
    virtual PointFields
    state_fields() const
    {
      return {};
    }

    /** @brief The number of state entries, the sum over state_fields(). */
    unsigned int
    n_state_entries() const;

    /**
     * @brief The state of a new point whose Kirchhoff stress is @p
     * kirchhoff_stress (zero or geostatic) into @p state (n_state_entries()
     * entries). The default sets every entry to zero.
     */
    virtual void
    initialize_state(const SymmetricTensor<2, 3> &kirchhoff_stress,
                     const ArrayView<double>     &state) const;

    /**
     * @brief Stress update (elastic predictor, plastic corrector).
     *
     * @param deformation_increment @f$\Delta F@f$ (3x3).
     * @param previous_elastic_strain @f$b^e_n@f$.
     * @param state The point's state variables at the start of the step
     *   (state_fields(), in their order); empty if the model has none.
     * @param[out] result The new stress and what the tangent and
     *   store_state() need.
     */
    virtual void
    update(const Tensor<2, 3>            &deformation_increment,
           const SymmetricTensor<2, 3>   &previous_elastic_strain,
           const ArrayView<const double> &state,
           ConstitutiveUpdate            &result) const = 0;

    /**
     * @brief The update of a new point: the state initialize_state() gives
     * at zero stress.
     */
    void
    update(const Tensor<2, 3>          &deformation_increment,
           const SymmetricTensor<2, 3> &previous_elastic_strain,
           ConstitutiveUpdate          &result) const;

    /**
     * @brief A converged step's end: write the state variables at the end
     * of the step from the update @p result into @p state, which holds them
     * at the start. The default (a model without state) does nothing.
     */
    virtual void
    store_state(const ConstitutiveUpdate &result,
                const ArrayView<double>  &state) const;

    /**
     * @brief The tangent @f$\mathcal C_{imkl}@f$ of the last update, for
     * indices below @p n_components (2 in plane strain, 3 in 3D).
     */
    virtual void
    tangent(const ConstitutiveUpdate &result,
            const unsigned int        n_components,
            Tensor<4, 3>             &C) const = 0;

    /**
     * @brief The material part of the previously converged tangent,
     * @f$M_{ijkq} = \mathcal C_{imkl}\,\Delta F^{-1}_{ql}\,
     * \Delta F^{-1}_{jm}@f$: the change of @f$\tau\,\Delta F^{-T}@f$ per
     * unit change of @f$\Delta F_{kq}@f$ at fixed @f$\Delta F^{-T}@f$
     * (formulation note, section 3), for indices below @p n_components.
     *
     * This default pulls @f$\mathcal C@f$ of tangent() back. A model that
     * can differentiate its stress with respect to @f$\Delta F@f$ directly
     * overrides it and saves the pull-back.
     *
     * @param result The last update.
     * @param n_components 2 in plane strain, 3 in 3D.
     * @param deformation_increment_inverse @f$\Delta F^{-1}@f$ (the
     *   out-of-plane row and column are not read in plane strain).
     * @param[out] M The tangent; entries with an index at or above
     *   @p n_components are not set.
     */
    virtual void
    pulled_back_tangent(const ConstitutiveUpdate &result,
                        const unsigned int        n_components,
                        const Tensor<2, 3>       &deformation_increment_inverse,
                        Tensor<4, 3>             &M) const;

    /**
     * @brief Whether the tangent has major symmetry,
     * @f$A_{ijkq} = A_{kqij}@f$, in every state: true for a model whose
     * stress update derives from a potential (hyperelasticity, associated
     * plasticity with the exponential-map return), which lets the assembly
     * compute half of each point stiffness (PointStiffness). The default,
     * false, is always safe.
     */
    virtual bool
    has_symmetric_tangent() const
    {
      return false;
    }

    /**
     * @brief The elastic left Cauchy-Green tensor @f$b^e@f$ whose stress is
     * @p kirchhoff_stress: the elastic law inverted, to start a point from
     * a given stress (a geostatic start).
     */
    virtual SymmetricTensor<2, 3>
    elastic_strain_for_stress(
      const SymmetricTensor<2, 3> &kirchhoff_stress) const = 0;

    /**
     * @brief A one-line description of the model and its parameters.
     */
    virtual std::string
    description() const = 0;

    /**
     * @brief Young's modulus, the stiffness that scales penalties.
     */
    virtual double
    elastic_modulus() const = 0;

    /**
     * @brief The P-wave (constrained) modulus @f$\lambda + 2\mu@f$ of the
     * elastic law, for the speed of sound @f$c_p = \sqrt{(\lambda +
     * 2\mu)/\rho}@f$ that bounds an explicit time step. A
     * pressure-dependent law gives that of its reference state.
     */
    virtual double
    p_wave_modulus() const = 0;

    /**
     * @brief The elastic P-wave modulus in the state of Kirchhoff stress
     * @p kirchhoff_stress: the tangent of the Kirchhoff stress against the
     * logarithmic strain along one axis with the others held, so that the
     * speed of sound of a point is @f$\sqrt{M/\rho_0}@f$ with its
     * reference density whatever its volume change (the mass and the
     * Kirchhoff stiffness of a point both go with its initial volume). The
     * default is p_wave_modulus(), for a law whose elasticity does not
     * depend on the stress; a pressure-dependent law gives that of the
     * state, so that an explicit step follows its stiffening.
     */
    virtual double
    p_wave_modulus_at(
      const dealii::SymmetricTensor<2, 3> &kirchhoff_stress) const;

    /**
     * @brief The shear modulus @f$\mu@f$ of the elastic law (a
     * pressure-dependent law's at its reference state), for the elastic
     * stiffness of a stiffness-proportional damping (StiffnessDamping). The
     * default finds it from elastic_modulus() and p_wave_modulus(), the
     * smaller root of @f$4\mu^2 - (3M + E)\mu + EM = 0@f$ (the other root
     * is a negative Poisson's ratio); a model that knows it says it.
     */
    virtual double
    shear_modulus() const;

    /**
     * @brief The same model with its strength divided by @p factor (> 0),
     * for a strength reduction (StrengthReduction): the cohesion, the
     * tangents of the friction and dilation angles, a yield stress or a
     * critical-state ratio's friction angle, each as the model says; the
     * elastic constants and the state variables' meaning unchanged. The
     * default refuses a model that does not say (one line naming it).
     */
    virtual std::unique_ptr<Material>
    with_reduced_strength(const double factor) const;
  };

  /**
   * @brief Hencky elasticity (Kirchhoff stress linear in logarithmic elastic
   * strain) with optional von Mises perfect plasticity.
   *
   * The return map is the radial return in principal logarithmic strain
   * space; its algorithmic tangent is exact (formulation note, section 2).
   */
  class HenckyVonMises : public Material
  {
  public:
    /**
     * @brief Constructor.
     * @param youngs_modulus Young's modulus E > 0.
     * @param poissons_ratio Poisson's ratio in (-1, 0.5).
     * @param yield_stress @f$\rho_y = \sqrt{2 J_2}@f$ at yield; infinite for
     *   an elastic model.
     */
    HenckyVonMises(const double youngs_modulus,
                   const double poissons_ratio,
                   const double yield_stress);

    using Material::update;

    /**
     * @brief The accumulated plastic multiplier, if the model is plastic
     * (written, not read: the model does not harden).
     */
    PointFields
    state_fields() const override;

    /** The radial return; @p state is not read. */
    void
    update(const Tensor<2, 3>            &deformation_increment,
           const SymmetricTensor<2, 3>   &previous_elastic_strain,
           const ArrayView<const double> &state,
           ConstitutiveUpdate            &result) const override;

    /** @brief Accumulate the plastic multiplier. */
    void
    store_state(const ConstitutiveUpdate &result,
                const ArrayView<double>  &state) const override;

    void
    tangent(const ConstitutiveUpdate &result,
            const unsigned int        n_components,
            Tensor<4, 3>             &C) const override;

    /**
     * @brief The pulled-back tangent without a pull-back: the principal-frame
     * response is evaluated for perturbations of @f$\Delta F@f$ itself,
     * @f$d(\Delta F) = e_k \otimes e_q@f$, and rotated back with
     * @f$\Delta F^{-T}@f$ folded in, at the cost of tangent().
     */
    void
    pulled_back_tangent(const ConstitutiveUpdate &result,
                        const unsigned int        n_components,
                        const Tensor<2, 3>       &deformation_increment_inverse,
                        Tensor<4, 3>             &M) const override;

    /** @brief Whether the yield stress is finite. */
    bool
    is_plastic() const;

    /**
     * @brief True: Hencky elasticity derives from a stored energy and the
     * radial return of von Mises plasticity is a closest-point projection
     * in the energy norm, so the algorithmic tangent is symmetric (Simo
     * 1992; checked by tests/point_stiffness.cc).
     */
    bool
    has_symmetric_tangent() const override
    {
      return true;
    }

    SymmetricTensor<2, 3>
    elastic_strain_for_stress(
      const SymmetricTensor<2, 3> &kirchhoff_stress) const override
    {
      return hencky_elastic_strain_for_stress(lambda, mu, kirchhoff_stress);
    }

    std::string
    description() const override;

    double
    elastic_modulus() const override;

    double
    p_wave_modulus() const override
    {
      return lambda + 2. * mu;
    }

    /**
     * @brief The yield stress divided by @p factor (the undrained strength
     * of a total-stress analysis); an elastic model unchanged.
     */
    std::unique_ptr<Material>
    with_reduced_strength(const double factor) const override;

  private:
    /**
     * @brief principal_frame_response() with this model's principal
     * tangent: tangent() uses @f$R = Q^T@f$, pulled_back_tangent()
     * @f$R = Q^T \Delta F^{-T}@f$.
     */
    void
    principal_response(const ConstitutiveUpdate &result,
                       const unsigned int        n_components,
                       const Tensor<2, 3>       &R,
                       Tensor<4, 3>             &T) const;

  public:
    /** @brief Lame's first parameter lambda. */
    double
    lame_first_parameter() const
    {
      return lambda;
    }

    /** @brief The shear modulus mu. */
    double
    shear_modulus() const override
    {
      return mu;
    }

  private:
    /** Lame's first parameter. */
    double lambda;
    /** Shear modulus. */
    double mu;
    /** Yield strength @f$\rho_y@f$. */
    double yield_stress;
    /** Young's modulus (for the description). */
    double youngs_modulus;
    /** Poisson's ratio (for the description). */
    double poissons_ratio;
  };

  /**
   * @brief The material models, registered by name.
   *
   * Each model registers a name, a function that declares its parameters in
   * the subsection of that name and a function that creates it from them
   * (given also that subsection's path, "Body 1/Material/von Mises/", for
   * its messages).
   * The names form the `Patterns::Selection` of the scene's `Model` entry,
   * so a misspelt name is an error that lists the known ones.
   */
  using MaterialList =
    PluginList<Material, ParameterHandler &, const std::string &>;

  /**
   * @brief The elastic constants every model declares: `Young's modulus`
   * and `Poisson's ratio`.
   */
  namespace ElasticConstants
  {
    /** @brief Declare both entries in the current subsection. */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief Read and check them: {E, nu}, with one line naming the entry
     * (after @p path, the subsection's path) when E is not positive.
     */
    std::pair<double, double>
    parse_parameters(ParameterHandler &prm, const std::string &path);
  } // namespace ElasticConstants

  /**
   * @brief The `Model` entry of a body's "Material" subsection.
   */
  namespace MaterialRegistry
  {
    /**
     * @brief Declare, in the current subsection, the `Model` entry and one
     * subsection per registered model.
     */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * @brief Create the model named by `Model` in the current subsection,
     * whose path (for messages) is @p path ("Body 1/Material").
     */
    std::unique_ptr<Material>
    create(ParameterHandler &prm, const std::string &path);
  } // namespace MaterialRegistry
} // namespace impm

#endif
