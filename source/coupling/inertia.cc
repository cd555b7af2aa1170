// Inertia as a coupling: implicit Newmark time stepping in the previously
// converged form, with the lumped mass of the start-of-step grid.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/coupling/coupling.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * @brief The inertia of the material points: a scene that names it is
     * solved in time, each load step a time step of the Newmark family on
     * the grid of the step's start (the previously converged statement of
     * equilibrium with the inertial force @f$M a^{n+1}@f$ added to the
     * internal force).
     *
     * The load factor is the time over `End time`: the loads, prescribed
     * displacements and rigid-body motions ramp with it as in a
     * quasi-static scene (gravity not ramped acts at once), the step
     * control's cuts and growth are cuts and growth of the time step, and
     * a step of load increment @f$\Delta\lambda@f$ lasts @f$\Delta t =
     * \Delta\lambda\,T@f$.
     *
     * At the start of a step the points' mass, momentum and mass times
     * acceleration are mapped to the nodes with the step's weights
     * @f$N_{Ip}@f$ (a lumped mass: @f$M_I = \sum_p N_{Ip} m_p@f$,
     * @f$M_I v_I = \sum_p N_{Ip} m_p v_p@f$, @f$M_I a_I = \sum_p N_{Ip}
     * m_p a_p@f$), zero on the DoFs outside the system (constrained). The
     * Newmark relations with parameters @f$\beta, \gamma@f$ give the
     * nodal acceleration and velocity at the step's end from the
     * displacement increment @f$\Delta u@f$:
     * @f$a^{n+1} = (\Delta u - \Delta t\, v^n)/(\beta \Delta t^2) -
     * (1/(2\beta) - 1)\, a^n@f$, @f$v^{n+1} = v^n + \Delta t\,((1 -
     * \gamma)\, a^n + \gamma\, a^{n+1})@f$, so the inertial force adds
     * @f$M/(\beta\Delta t^2)@f$ to the matrix's diagonal, constant over the
     * step. A converged step updates each point (FLIP): @f$v_p \mathrel{+}=
     * \sum_I N_{Ip} (v_I^{n+1} - v_I^n)@f$, @f$a_p = \sum_I N_{Ip}
     * a_I^{n+1}@f$. The trapezoidal rule (@f$\beta = 1/4, \gamma =
     * 1/2@f$, the default) conserves the energy of the nodal system; the
     * mapping between points and nodes at each step's start loses the part
     * of the points' kinetic energy the nodes cannot represent.
     *
     * The points' `velocity` and `acceleration` are declared point fields
     * (written, kept in checkpoints); the kinetic energy and the time are
     * step measures. A scene that does not name inertia creates none of
     * this.
     *
     * @tparam dim Space dimension.
     */
    template <int dim>
    class Inertia : public Coupling<dim>
    {
    public:
      /** @brief The subsection's entries. */
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Enabled",
                          "false",
                          Patterns::Bool(),
                          "Whether the points have inertia: the scene is "
                          "solved in time (see 'End time'). Off: the "
                          "quasi-static statement, with no mass matrix and "
                          "no velocities stored.");
        prm.declare_entry("End time",
                          "1",
                          Patterns::Double(0.),
                          "The time at full load, in s (> 0): the load "
                          "factor is the time over it, so a load step of "
                          "Solver/Load steps lasts End time / Load steps.");
        prm.declare_entry("Newmark beta",
                          "0.25",
                          Patterns::Double(0., 0.5),
                          "beta of the Newmark rule (0.25 with gamma = 0.5: "
                          "the trapezoidal rule, unconditionally stable and "
                          "without numerical damping); from above 0 to "
                          "0.5.");
        prm.declare_entry("Newmark gamma",
                          "0.5",
                          Patterns::Double(0., 1.),
                          "gamma of the Newmark rule (0.5: no numerical "
                          "damping; above 0.5 damps); from 0.5 to 1, and "
                          "at most 4 beta for unconditional stability.");
        prm.declare_entry("Initial velocity",
                          "0",
                          Patterns::Anything(),
                          "The points' velocity at the start, in m/s: 0, or "
                          "one expression per axis separated by ';' in the "
                          "initial position x, y (and z) and the constant "
                          "pi (deal.II's FunctionParser, muparser syntax), "
                          "e.g. '0.1*sin(pi*x/50); 0'.");
      }

      /** @brief The inertia of a scene (from its subsection). */
      explicit Inertia(const CouplingInputs<dim> &inputs)
        : end_time(inputs.prm.get_double("End time"))
        , beta(inputs.prm.get_double("Newmark beta"))
        , gamma(inputs.prm.get_double("Newmark gamma"))
        , initial_velocity_expression(inputs.prm.get("Initial velocity"))
        , grid(inputs.grid)
      {
        if (!(end_time > 0.))
          throw InputError("Parameter 'Inertia/End time' = '" +
                           inputs.prm.get("End time") +
                           "' is not allowed: it must be > 0.");
        if (!(beta > 0.))
          throw InputError("Parameter 'Inertia/Newmark beta' = '" +
                           inputs.prm.get("Newmark beta") +
                           "' is not allowed: it must be > 0 (an implicit "
                           "rule).");
        if (gamma < 0.5 || 4. * beta < gamma)
          throw InputError(
            "Inertia: Newmark gamma = " + inputs.prm.get("Newmark gamma") +
            " with beta = " + inputs.prm.get("Newmark beta") +
            " is not unconditionally stable: it needs 0.5 <= gamma <= 4 "
            "beta.");
        if (initial_velocity_expression != "0")
          {
            initial_velocity = std::make_unique<FunctionParser<dim>>(dim);
            try
              {
                initial_velocity->initialize(dim == 2 ? "x,y" : "x,y,z",
                                             initial_velocity_expression,
                                             {{"pi", numbers::PI}});
              }
            catch (const ExceptionBase &)
              {
                throw InputError("Parameter 'Inertia/Initial velocity' = '" +
                                 initial_velocity_expression +
                                 "' is not allowed: it must "
                                 "be 0 or " +
                                 std::to_string(dim) + " expressions in " +
                                 (dim == 2 ? "x, y" : "x, y, z") +
                                 " separated by ';'.");
              }
          }
      }

      PointFields
      point_fields() const override
      {
        return {{"velocity", dim, true}, {"acceleration", dim, true}};
      }

      std::vector<std::string>
      descriptions() const override
      {
        std::ostringstream out;
        out << "inertia: Newmark (beta " << beta << ", gamma " << gamma
            << (beta == 0.25 && gamma == 0.5 ? ", the trapezoidal rule" : "")
            << "), lumped mass, end time " << end_time << " s";
        if (initial_velocity)
          out << ", initial velocity " << initial_velocity_expression;
        return {out.str()};
      }

      void
      initialize_points(MaterialPoints<dim> &material_points) override
      {
        if (!initial_velocity)
          return;
        material_points.initialize_coupling_field(
          "velocity",
          [this](const PointState<dim> &state, const ArrayView<double> &v) {
            for (unsigned int d = 0; d < dim; ++d)
              v[d] = initial_velocity->value(state.initial_position(), d);
          });
      }

      /** @brief The nodal mass, momentum and mass times acceleration of
       *  the step's start. */
      void
      begin_attempt(const MaterialPoints<dim> &material_points,
                    const LoadStepSystem<dim> &system,
                    const double               start,
                    const double               target) override
      {
        time_step        = (target - start) * end_time;
        end_of_step_time = target * end_time;
        grid.reinit_vector(mass);
        grid.reinit_vector(momentum);
        grid.reinit_vector(mass_acceleration);
        component_of.assign(mass.locally_owned_size() +
                              mass.get_partitioner()->n_ghost_indices(),
                            0);
        const auto        &layout         = material_points.layout();
        const unsigned int velocity_first = layout.coupling_field("velocity");
        const unsigned int acceleration_first =
          layout.coupling_field("acceleration");
        for (const auto &point : material_points.particles())
          {
            const auto            properties = point.get_properties();
            const PointStep<dim> &step       = system.point_steps.of(point);
            const double          m = PointState<dim>(properties).mass();
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                {
                  const unsigned int dof    = step.dofs[v * dim + i];
                  const double       weight = step.support.weights[v] * m;
                  component_of[dof]         = i;
                  mass.local_element(dof) += weight;
                  momentum.local_element(dof) +=
                    weight * properties[velocity_first + i];
                  mass_acceleration.local_element(dof) +=
                    weight * properties[acceleration_first + i];
                }
          }
        for (NodalVector *vector : {&mass, &momentum, &mass_acceleration})
          {
            vector->compress(VectorOperation::add);
            vector->update_ghost_values();
          }
        // The constrained DoFs do not move with the material: no velocity
        // or acceleration there (their motion is prescribed).
        for (unsigned int i = 0;
             i < mass.locally_owned_size() +
                   mass.get_partitioner()->n_ghost_indices();
             ++i)
          if (system.system_index(i) == numbers::invalid_dof_index)
            {
              momentum.local_element(i)          = 0.;
              mass_acceleration.local_element(i) = 0.;
            }
      }

      /** @brief The mass term of the matrix, @f$M/(\beta\Delta t^2)@f$ on
       *  the diagonal of the owned rows (added with every matrix: the
       *  constant part of the matrix is kept over the attempts of a step,
       *  whose time steps differ). */
      bool
      add_matrix(const PointGradients<dim> &,
                 const LoadStepSystem<dim>      &system,
                 TrilinosWrappers::SparseMatrix &matrix) override
      {
        const double c = 1. / (beta * time_step * time_step);
        for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
          {
            const auto row = system.system_index(i);
            if (row != numbers::invalid_dof_index && mass.local_element(i) > 0.)
              matrix.add(row, row, c * mass.local_element(i));
          }
        return true;
      }

      /** @brief The inertial force @f$M a^{n+1}(\Delta u)@f$ at the owned
       *  DoFs of the system. Collective (its size). */
      void
      add_forces(const LoadStepSystem<dim> &system,
                 const NodalVector         &increment,
                 NodalVector               &internal_force) override
      {
        const double c1           = 1. / (beta * time_step * time_step);
        const double c2           = 1. / (beta * time_step);
        const double c3           = 1. / (2. * beta) - 1.;
        double       norm_squared = 0.;
        force_on_material         = Tensor<1, dim>();
        for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
          if (system.system_index(i) != numbers::invalid_dof_index)
            {
              const double force =
                c1 * mass.local_element(i) * increment.local_element(i) -
                c2 * momentum.local_element(i) -
                c3 * mass_acceleration.local_element(i);
              internal_force.local_element(i) += force;
              norm_squared += force * force;
              force_on_material[component_of[i]] += force;
            }
        inertial_force_norm = std::sqrt(
          Utilities::MPI::sum(norm_squared,
                              grid.get_triangulation().get_communicator()));
      }

      double
      reference_force() const override
      {
        return inertial_force_norm;
      }

      /** @brief The inertial force of the converged step (the load that
       *  goes into accelerating the material, in the reactions'
       *  balance). */
      Tensor<1, dim>
      force_from_material() const override
      {
        return accepted_force;
      }

      /** @brief The points' new velocity and acceleration (FLIP) and the
       *  kinetic energy. */
      void
      accept(MaterialPoints<dim>       &material_points,
             const LoadStepSystem<dim> &system,
             const NodalVector         &increment) override
      {
        const double c3 = 1. / (2. * beta) - 1.;
        // The nodes' new acceleration and change of velocity (owned and
        // ghost DoFs: the points read both).
        const unsigned int n_local =
          mass.locally_owned_size() + mass.get_partitioner()->n_ghost_indices();
        std::vector<double> new_acceleration(n_local), velocity_change(n_local);
        for (unsigned int i = 0; i < n_local; ++i)
          {
            const double m = mass.local_element(i);
            const double v = m > 0. ? momentum.local_element(i) / m : 0.;
            const double a =
              m > 0. ? mass_acceleration.local_element(i) / m : 0.;
            new_acceleration[i] = (increment.local_element(i) - time_step * v) /
                                    (beta * time_step * time_step) -
                                  c3 * a;
            velocity_change[i] =
              time_step * ((1. - gamma) * a + gamma * new_acceleration[i]);
          }
        const auto         &layout         = material_points.layout();
        const unsigned int  velocity_first = layout.coupling_field("velocity");
        const auto         &steps          = system.point_steps;
        std::vector<double> velocities(steps.size() * dim),
          accelerations(steps.size() * dim);
        double energy = 0.;
        for (const auto &point : material_points.particles())
          {
            const auto            properties = point.get_properties();
            const unsigned int    p          = steps.index_of(point);
            const PointStep<dim> &step       = steps[p];
            for (unsigned int i = 0; i < dim; ++i)
              {
                double dv = 0., a = 0.;
                for (unsigned int v = 0; v < step.support.n_nodes; ++v)
                  {
                    const unsigned int dof = step.dofs[v * dim + i];
                    dv += step.support.weights[v] * velocity_change[dof];
                    a += step.support.weights[v] * new_acceleration[dof];
                  }
                velocities[p * dim + i] = properties[velocity_first + i] + dv;
                accelerations[p * dim + i] = a;
                energy += 0.5 * PointState<dim>(properties).mass() *
                          velocities[p * dim + i] * velocities[p * dim + i];
              }
          }
        material_points.set_coupling_field("velocity", steps, velocities);
        material_points.set_coupling_field("acceleration",
                                           steps,
                                           accelerations);
        const MPI_Comm communicator =
          grid.get_triangulation().get_communicator();
        kinetic_energy = Utilities::MPI::sum(energy, communicator);
        for (unsigned int d = 0; d < dim; ++d)
          accepted_force[d] =
            Utilities::MPI::sum(force_on_material[d], communicator);
      }

      std::vector<std::string>
      step_measure_columns() const override
      {
        return {"time", "kinetic_energy"};
      }

      void
      step_measures(const double,
                    std::vector<StepMeasure> &measures) const override
      {
        measures.push_back(
          {"time", "t", end_of_step_time, MeasureKind::number});
        measures.push_back(
          {"kinetic_energy", "Ek", kinetic_energy, MeasureKind::energy});
      }

    private:
      const double                         end_time;
      const double                         beta;
      const double                         gamma;
      const std::string                    initial_velocity_expression;
      std::unique_ptr<FunctionParser<dim>> initial_velocity;
      const BackgroundGrid<dim>           &grid;
      double                               time_step        = 0.;
      double                               end_of_step_time = 0.;
      NodalVector                          mass, momentum, mass_acceleration;
      double                               inertial_force_norm = 0.;
      double                               kinetic_energy      = 0.;
      /** Each local DoF's component (from the points' supports). */
      std::vector<unsigned char> component_of;
      /** The inertial force of the last add_forces() (this process's
       *  owned DoFs) and of the accepted step (all). */
      Tensor<1, dim> force_on_material, accepted_force;
    };
  } // namespace

  IMPM_REGISTER_COUPLING(Inertia,
                         "Inertia",
                         inputs.prm.get_bool("Enabled"),
                         ([](ParameterHandler &prm) {
                           Inertia<dim>::declare_parameters(prm);
                         }))
} // namespace impm
