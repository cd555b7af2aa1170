// The release of the initial stress with the load factor: a scene that
// starts from a stress its loads do not balance (a geostatic stress beside
// a free face) begins in equilibrium and reaches its true one at the full
// load, as an excavation is modelled in stages.
#include <impm/base/errors.h>
#include <impm/coupling/coupling.h>
#include <impm/coupling/fixed_nodal_load.h>
#include <impm/mechanics/equilibrium_forms.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * @brief The initial stress released with the load factor.
     *
     * Each point keeps its initial Kirchhoff stress @f$\tau_p^0@f$ (the
     * point field `initial_stress`). At load factor @f$\lambda@f$ the
     * material is loaded, beside the scene's loads, by
     * @f$(1-\lambda)\, r^0@f$ with the imbalance of the start
     * @f$r^0_v = \sum_p \tau^0_p V^0_p \nabla N_{vp} - \sum_p m_p
     * N_{vp}\, a^0@f$: the internal force of the initial stresses
     * (in axisymmetry with the hoop part @f$\tau^0_{p,\theta\theta} V^0_p
     * \bar N_{\theta,vp}@f$ on the radial component) less the load at
     * load factor 0 (@f$a^0@f$: an unramped gravity), on the step's grid
     * where the points are. At @f$\lambda = 0@f$ the points' stresses are
     * their initial ones and the scene is in equilibrium, whatever its
     * loads leave unbalanced; at @f$\lambda = 1@f$ the release is gone.
     * Inside a geostatic field under gravity applied at once the
     * imbalance is only the discretisation's; what is released is the
     * traction of the initial stress on a free face (a cut, a K0 stress
     * beside a slope).
     *
     * The force is that of the points' initial stresses, unrotated, where
     * the points are; it does not depend on the step's increment (no
     * matrix). It acts on the DoFs of the system, so the reactions of the
     * held faces are those of the points' stresses: at load factor 0 the
     * supports carry the initial stress (a K0 thrust on a symmetry line),
     * at 1 what the true equilibrium asks of them.
     *
     * @tparam dim Space dimension.
     */
    template <int dim>
    class InitialStressRelease : public Coupling<dim>
    {
    public:
      /** @brief The subsection's entries. */
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Enabled",
          "false",
          Patterns::Bool(),
          "Whether the part of the initial stress (Body N/Initial stress) "
          "that the scene's loads do not balance is released with the load "
          "factor: the material is also loaded by (1 - load factor) times "
          "the internal force of the points' initial stresses, so that the "
          "first step starts in equilibrium and the imbalance (a free face "
          "cut into a geostatic stress field, a K0 stress beside a slope) "
          "grows with the load; the held faces' reactions go from the "
          "initial stress's to the final ones. Not in scenes with time (a "
          "dynamic scene starts from the imbalance). Off: not created, "
          "costs nothing.");
      }

      /** @brief The release of a scene (from its subsection). */
      explicit InitialStressRelease(const CouplingInputs<dim> &inputs)
        : grid(inputs.grid)
        , acceleration(inputs.acceleration_from_the_start)
      {
        bool any_initial_stress = false;
        for (const auto &body : inputs.parameters.bodies)
          any_initial_stress =
            any_initial_stress || body.initial_stress.geostatic;
        if (!any_initial_stress)
          throw InputError("'Initial stress release/Enabled' = true, but no "
                           "body starts from a stress: set 'Body N/Initial "
                           "stress = geostatic' (or disable the release).");
        if (inputs.time.in_time())
          throw InputError(
            "'Initial stress release/Enabled' = true in a scene with time: "
            "the release follows the load factor of quasi-static steps.");
      }

      std::vector<std::string>
      descriptions() const override
      {
        return {"initial stress released with the load factor"};
      }

      PointFields
      point_fields() const override
      {
        return {{"initial_stress", 6, false}};
      }

      /** @brief Each point's initial stress, from its stress at the start. */
      void
      initialize_points(MaterialPoints<dim> &material_points) override
      {
        material_points.initialize_coupling_field(
          "initial_stress",
          [](const PointState<dim> &state, const ArrayView<double> &stress) {
            const SymmetricTensor<2, 3> tau = state.kirchhoff_stress();
            for (unsigned int k = 0; k < 6; ++k)
              stress[k] = tau.access_raw_entry(k);
          });
      }

      /** @brief The force of the initial stresses on this step's grid,
       *  times (1 - the step's target load factor). */
      void
      begin_attempt(const MaterialPoints<dim> &material_points,
                    const LoadStepSystem<dim> &system,
                    const StepSpan            &span) override
      {
        const double       remaining    = 1. - span.target;
        const bool         axisymmetric = system.axisymmetric();
        const unsigned int first =
          material_points.layout().coupling_field("initial_stress");
        NodalVector &release = released.reset(grid);
        std::array<double, PointSupport<dim>::max_nodes * dim> forces;
        for (const auto &point : material_points.particles())
          {
            const PointStep<dim> &step = system.point_steps.of(point);
            const double         *tau0 = point.get_properties().data() + first;
            SymmetricTensor<2, 3> initial;
            for (unsigned int k = 0; k < 6; ++k)
              initial.access_raw_entry(k) = tau0[k];
            const double   scale = remaining * step.initial_volume;
            Tensor<2, dim> stress;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                stress[i][j] = scale * initial[i][j];
            const Tensor<1, dim> weight =
              remaining * PointState<dim>(point.get_properties()).mass() *
              acceleration;
            const unsigned int n = step.support.n_nodes * dim;
            std::fill(forces.begin(), forces.begin() + n, 0.);
            add_point_forces(stress,
                             step.support.gradients.data(),
                             step.support.n_nodes,
                             forces.data());
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              {
                if (axisymmetric)
                  forces[v * dim] +=
                    scale * initial[2][2] * step.support.hoop_weights[v];
                for (unsigned int i = 0; i < dim; ++i)
                  forces[v * dim + i] -= step.support.weights[v] * weight[i];
              }
            for (unsigned int k = 0; k < n; ++k)
              release.local_element(step.dofs[k]) += forces[k];
          }
        released.finish(system, grid);
      }

      /** @brief Minus the released force at the owned DoFs of the system
       *  (not at the held ones, whose reactions stay those of the points'
       *  stresses and the scene's loads: at load factor 0 the supports
       *  carry the initial stress). */
      void
      add_forces(const LoadStepSystem<dim> &,
                 const NodalVector &,
                 NodalVector &internal_force) override
      {
        released.subtract_from(internal_force);
      }

      /** @brief The released force's work on the material: the step's
       *  end force times the increment (first order in the step: the force
       *  falls from the start's to the end's within it). */
      void
      add_step_energy(const LoadStepSystem<dim> &,
                      const NodalVector &increment,
                      StepEnergy        &energy) override
      {
        energy.external_work += released.work(increment);
      }

      /** @brief The size of the released force still applied. */
      double
      reference_force() const override
      {
        return released.norm();
      }

      /** @brief Minus the released force's sum over the system's DoFs (it
       *  enters the balance through the internal force). */
      Tensor<1, dim>
      force_from_material() const override
      {
        return -released.sum();
      }

    private:
      const BackgroundGrid<dim> &grid;
      /** The acceleration of the load at load factor 0. */
      const Tensor<1, dim> acceleration;
      /** The step's released force, (1 - lambda) r0. */
      FixedNodalLoad<dim> released;
    };
  } // namespace

  IMPM_REGISTER_COUPLING(InitialStressRelease,
                         "Initial stress release",
                         inputs.prm.get_bool("Enabled"),
                         ([](ParameterHandler &prm) {
                           InitialStressRelease<dim>::declare_parameters(prm);
                         }))
} // namespace impm
