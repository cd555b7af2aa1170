#include <impm/base/names.h>
#include <impm/contact/rigid_contact.h>
#include <impm/postprocess/postprocessor.h>

namespace impm
{
  namespace
  {
    /**
     * @brief The force of the material on each rigid body after every
     * converged step, as step measures (so in `steps.csv`, `summary.json`
     * and the progress log): per body k the total force's components
     * `rigid_k_force_x`, ..., the sizes of its normal part (the pressures)
     * `rigid_k_normal_force` and of its tangential part (friction)
     * `rigid_k_friction_force`, the number of probes in contact (domain
     * faces, or Gauss points on them: RigidBody::face_points())
     * `rigid_k_contacts` and of those that slip `rigid_k_slipping`. Forces in N
     * (per m of thickness in 2D). Created only in scenes with rigid bodies.
     */
    template <int dim>
    class RigidBodyForces : public Postprocessor<dim>
    {
    public:
      /** @brief Constructor. */
      explicit RigidBodyForces(const RunContext<dim> &context)
        : bodies(context.couplings.template find<RigidContact<dim>>()->bodies())
        , n_bodies(bodies.size())
      {}

      std::vector<std::string>
      step_measure_columns() const override
      {
        std::vector<std::string> columns;
        for (unsigned int k = 1; k <= n_bodies; ++k)
          {
            const std::string prefix = "rigid_" + std::to_string(k) + '_';
            for (unsigned int d = 0; d < dim; ++d)
              columns.push_back(prefix + "force_" + Names::axis(d));
            columns.push_back(prefix + "normal_force");
            columns.push_back(prefix + "friction_force");
            columns.push_back(prefix + "contacts");
            columns.push_back(prefix + "slipping");
            for (const unsigned int d : bodies[k - 1].force_components)
              columns.push_back(prefix + "displacement_" + Names::axis(d));
          }
        return columns;
      }

      void
      measure_step(const RunContext<dim> &context, StepRecord &record) override
      {
        const auto &forces =
          context.couplings.template find<RigidContact<dim>>()->body_forces();
        for (unsigned int k = 0; k < n_bodies; ++k)
          {
            const std::string prefix = "rigid_" + std::to_string(k + 1) + '_';
            const std::string label  = "R" + std::to_string(k + 1);
            for (unsigned int d = 0; d < dim; ++d)
              record.measures.push_back({prefix + "force_" + Names::axis(d),
                                         label + Names::axis(d),
                                         forces[k].total[d],
                                         MeasureKind::force});
            record.measures.push_back({prefix + "normal_force",
                                       label + "n",
                                       forces[k].normal.norm(),
                                       MeasureKind::force});
            record.measures.push_back({prefix + "friction_force",
                                       label + "t",
                                       forces[k].tangential.norm(),
                                       MeasureKind::force});
            record.measures.push_back(
              {prefix + "contacts",
               label + "c",
               static_cast<double>(forces[k].n_contacts),
               MeasureKind::count});
            record.measures.push_back(
              {prefix + "slipping",
               label + "s",
               static_cast<double>(forces[k].n_slipping),
               MeasureKind::count});
            const Tensor<1, dim> displacement =
              context.couplings.template find<RigidContact<dim>>()
                ->displacement_of(k, record.target);
            for (const unsigned int d : bodies[k].force_components)
              record.measures.push_back(
                {prefix + "displacement_" + Names::axis(d),
                 label + "u" + Names::axis(d),
                 displacement[d],
                 MeasureKind::length});
          }
      }

    private:
      const std::vector<RigidBody<dim>> &bodies;
      const unsigned int                 n_bodies;
    };
  } // namespace

  IMPM_REGISTER_POSTPROCESSOR(
    RigidBodyForces,
    "rigid body forces",
    context.couplings.template find<RigidContact<dim>>() != nullptr)
} // namespace impm
