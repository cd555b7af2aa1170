// Inertia as a coupling: implicit Newmark time stepping in the previously
// converged form, with the lumped mass of the start-of-step grid.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

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
     * solved in time (subsection `Time`), each step a time step on the
     * grid of the step's start (the previously converged statement of
     * equilibrium with the inertial force added to the internal force).
     *
     * At the start of a step the points' mass, momentum and mass times
     * acceleration are mapped to the nodes with the step's weights
     * @f$N_{Ip}@f$ (a lumped mass: @f$M_I = \sum_p N_{Ip} m_p@f$,
     * @f$p_I = M_I v_I = \sum_p N_{Ip} m_p v_p@f$, @f$q_I = M_I a_I =
     * \sum_p N_{Ip} m_p a_p@f$), zero on the DoFs outside the system
     * (constrained). The Newmark relations with @f$\beta, \gamma@f$ give
     * the nodal acceleration and velocity at the step's end from the
     * displacement increment @f$\Delta u@f$: @f$a^{n+1} = c_1 \Delta u -
     * c_2 v^n - c_3 a^n@f$ with @f$c_1 = 1/(\beta\Delta t^2)@f$, @f$c_2 =
     * 1/(\beta\Delta t)@f$, @f$c_3 = 1/(2\beta) - 1@f$, and @f$v^{n+1} =
     * v^n + \Delta t\,((1 - \gamma)\, a^n + \gamma\, a^{n+1})@f$.
     *
     * Generalised-alpha (Chung and Hulbert 1993) holds the balance at
     * @f$t_{n+1-\alpha_f}@f$ with the inertia at @f$n+1-\alpha_m@f$:
     * @f$(1-\alpha_m) M a^{n+1} + \alpha_m M a^n + (1-\alpha_f)\, r(\Delta
     * u) + \alpha_f\, r^n = 0@f$, where @f$r = f_{int} - f_{ext}@f$ and
     * @f$r^n@f$ is the residual of the step's start on this step's grid
     * (Coupling::set_start_residual()). Divided by @f$1-\alpha_f@f$, the
     * coupling adds @f$k_m M a^{n+1} + k_a q + k_r r^n@f$ to the internal
     * force, @f$k_m = (1-\alpha_m)/(1-\alpha_f)@f$, @f$k_a =
     * \alpha_m/(1-\alpha_f)@f$, @f$k_r = \alpha_f/(1-\alpha_f)@f$. From the
     * spectral radius at infinite frequency @f$\rho_\infty@f$:
     * @f$\alpha_m = (2\rho_\infty - 1)/(\rho_\infty + 1)@f$, @f$\alpha_f =
     * \rho_\infty/(\rho_\infty + 1)@f$, @f$\gamma = 1/2 - \alpha_m +
     * \alpha_f@f$, @f$\beta = (1 - \alpha_m + \alpha_f)^2/4@f$. Newmark is
     * the case @f$\alpha_m = \alpha_f = 0@f$. The other couplings' forces
     * (contact, springs) are taken at the step's end, not weighed.
     *
     * Mass-proportional (Rayleigh) damping @f$C = \alpha_R M@f$ adds
     * @f$\alpha_R (M v^{n+1} + k_r p)@f$, weighed like the internal force.
     * The matrix gains @f$(k_m c_1 + \alpha_R\gamma\Delta t\, c_1) M@f$ on
     * its diagonal, constant over the step.
     *
     * The first step's nodal acceleration is that of the balance at the
     * start, @f$M a^0 = f_{ext}(0) - f_{int}(0)@f$ (a body under gravity
     * applied at once starts falling at g), not the points' zero.
     *
     * A converged step updates each point (FLIP): @f$v_p \mathrel{+}=
     * \sum_I N_{Ip} (v_I^{n+1} - v_I^n)@f$, @f$a_p = \sum_I N_{Ip}
     * a_I^{n+1}@f$. The trapezoidal rule (@f$\beta = 1/4, \gamma =
     * 1/2@f$, the default) conserves the energy of the nodal system; the
     * mapping between points and nodes at each step's start loses the part
     * of the points' kinetic energy the nodes cannot represent.
     *
     * The points' `velocity` and `acceleration` are declared point fields
     * (written, kept in checkpoints); the kinetic, elastic (strain) and
     * total energy are step measures. A scene that does not name inertia
     * creates none of this.
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
                          "solved in time (it needs 'Time/End time'). Off: "
                          "the quasi-static statement, with no mass matrix "
                          "and no velocities stored.");
        prm.declare_entry("Integrator",
                          "Newmark",
                          Patterns::Selection("Newmark|generalised-alpha"),
                          "The time integrator: 'Newmark' (with 'Newmark "
                          "beta' and 'Newmark gamma'; the trapezoidal rule "
                          "by default) or 'generalised-alpha' (Chung and "
                          "Hulbert, with 'Spectral radius'), both implicit "
                          "in full Newton.");
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
        prm.declare_entry("Spectral radius",
                          "0.8",
                          Patterns::Double(0., 1.),
                          "generalised-alpha's spectral radius at infinite "
                          "frequency, from 0 (the most damping of the "
                          "highest frequencies) to 1 (none: the "
                          "trapezoidal rule's energy conservation).");
        prm.declare_entry("Mass damping",
                          "0",
                          Patterns::Double(0.),
                          "The mass-proportional Rayleigh damping "
                          "coefficient alpha in 1/s (damping force alpha M "
                          "v; a mode of angular frequency omega is damped "
                          "at the ratio alpha / (2 omega)). 0: none.");
        prm.declare_entry("Initial velocity",
                          "0",
                          Patterns::Anything(),
                          "The points' velocity at the start, in m/s: 0, or "
                          "one expression per axis separated by ';' in the "
                          "initial position x, y (and z) and the constant "
                          "pi (deal.II's FunctionParser, muparser syntax), "
                          "e.g. '0.1*sin(pi*x/50); 0'.");
      }

      /** @brief The inertia of a scene (from its subsection; it needs the
       *  scene's time). */
      explicit Inertia(const CouplingInputs<dim> &inputs)
        : generalised_alpha(inputs.prm.get("Integrator") == "generalised-alpha")
        , spectral_radius(inputs.prm.get_double("Spectral radius"))
        , alpha_m(generalised_alpha ?
                    (2. * spectral_radius - 1.) / (spectral_radius + 1.) :
                    0.)
        , alpha_f(generalised_alpha ? spectral_radius / (spectral_radius + 1.) :
                                      0.)
        , beta(generalised_alpha ?
                 0.25 * (1. - alpha_m + alpha_f) * (1. - alpha_m + alpha_f) :
                 inputs.prm.get_double("Newmark beta"))
        , gamma(generalised_alpha ? 0.5 - alpha_m + alpha_f :
                                    inputs.prm.get_double("Newmark gamma"))
        , mass_damping(inputs.prm.get_double("Mass damping"))
        , initial_velocity_expression(inputs.prm.get("Initial velocity"))
        , grid(inputs.grid)
      {
        if (!inputs.time.in_time())
          throw InputError("Inertia needs time: set 'Time/End time' above 0 "
                           "(the load steps are then time steps).");
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

      /** @brief True: the mass matrix holds the material in every
       *  direction (a body in free flight is a regular problem). */
      bool
      holds_material(const unsigned int) const override
      {
        return true;
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
        if (generalised_alpha)
          out << "inertia: generalised-alpha (spectral radius "
              << spectral_radius << ": alpha_m " << alpha_m << ", alpha_f "
              << alpha_f << ")";
        else
          out << "inertia: Newmark (beta " << beta << ", gamma " << gamma
              << (beta == 0.25 && gamma == 0.5 ? ", the trapezoidal rule" : "")
              << ")";
        out << ", lumped mass";
        if (mass_damping > 0.)
          out << ", mass damping " << mass_damping << " 1/s";
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

      /** @brief A resumed run's points carry their accelerations. */
      void
      load(const RunState &) override
      {
        started = true;
      }

      /** @brief The nodal mass, momentum and mass times acceleration of
       *  the step's start. */
      void
      begin_attempt(const MaterialPoints<dim> &material_points,
                    const LoadStepSystem<dim> &system,
                    const StepSpan            &span) override
      {
        time_step = span.time_step();
        grid.reinit_vector(mass);
        grid.reinit_vector(momentum);
        grid.reinit_vector(mass_acceleration);
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
        in_system.assign(n_local(), false);
        for (unsigned int i = 0; i < n_local(); ++i)
          {
            in_system[i] = system.system_index(i) != numbers::invalid_dof_index;
            if (!in_system[i])
              {
                momentum.local_element(i)          = 0.;
                mass_acceleration.local_element(i) = 0.;
              }
          }
        start_residual.clear();
      }

      /** @brief Generalised-alpha weighs the start's residual; the first
       *  step takes its acceleration from it. */
      bool
      needs_start_residual() const override
      {
        return alpha_f > 0. || !started;
      }

      /** @brief Keep the start's residual (generalised-alpha), and on the
       *  first step set the nodes' mass times acceleration to the start's
       *  balance, @f$M a^0 = -r^0@f$. */
      void
      set_start_residual(const NodalVector &internal_minus_external) override
      {
        if (alpha_f > 0.)
          {
            start_residual.resize(n_local());
            for (unsigned int i = 0; i < n_local(); ++i)
              start_residual[i] =
                in_system[i] ? internal_minus_external.local_element(i) : 0.;
          }
        if (!started)
          for (unsigned int i = 0; i < n_local(); ++i)
            if (in_system[i] && mass.local_element(i) > 0.)
              mass_acceleration.local_element(i) =
                -internal_minus_external.local_element(i);
      }

      /** @brief The mass term of the matrix on the diagonal of the owned
       *  rows (added with every matrix: the constant part of the matrix is
       *  kept over the attempts of a step, whose time steps differ). */
      bool
      add_matrix(const PointGradients<dim> &,
                 const LoadStepSystem<dim>      &system,
                 TrilinosWrappers::SparseMatrix &matrix) override
      {
        const double c1 = 1. / (beta * time_step * time_step);
        const double c  = (k_m() + mass_damping * gamma * time_step) * c1;
        for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
          {
            const auto row = system.system_index(i);
            if (row != numbers::invalid_dof_index && mass.local_element(i) > 0.)
              matrix.add(row, row, c * mass.local_element(i));
          }
        return true;
      }

      /** @brief The inertial (and damping) force at the owned DoFs of the
       *  system. Collective (its size). */
      void
      add_forces(const LoadStepSystem<dim> &,
                 const NodalVector &increment,
                 NodalVector       &internal_force) override
      {
        const double c1           = 1. / (beta * time_step * time_step);
        const double c2           = 1. / (beta * time_step);
        const double c3           = 1. / (2. * beta) - 1.;
        const double k_a          = alpha_m / (1. - alpha_f);
        const double k_r          = alpha_f / (1. - alpha_f);
        double       norm_squared = 0.;
        force_on_material         = Tensor<1, dim>();
        for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
          if (in_system[i])
            {
              const double p = momentum.local_element(i);
              const double q = mass_acceleration.local_element(i);
              // M a^{n+1}
              const double mass_times_acceleration =
                c1 * mass.local_element(i) * increment.local_element(i) -
                c2 * p - c3 * q;
              double force = k_m() * mass_times_acceleration + k_a * q;
              if (!start_residual.empty())
                force += k_r * start_residual[i];
              if (mass_damping > 0.)
                force += mass_damping *
                         (p +
                          time_step * ((1. - gamma) * q +
                                       gamma * mass_times_acceleration) +
                          k_r * p);
              internal_force.local_element(i) += force;
              norm_squared += force * force;
              force_on_material[grid.component(i)] += force;
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
        std::vector<double> new_acceleration(n_local()),
          velocity_change(n_local());
        for (unsigned int i = 0; i < n_local(); ++i)
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
        double energy = 0., elastic_energy = 0.;
        for (const auto &point : material_points.particles())
          {
            const auto            properties = point.get_properties();
            const unsigned int    p          = steps.index_of(point);
            const PointStep<dim> &step       = steps[p];
            elastic_energy += stored_energy(step);
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
        strain_energy  = Utilities::MPI::sum(elastic_energy, communicator);
        for (unsigned int d = 0; d < dim; ++d)
          accepted_force[d] =
            Utilities::MPI::sum(force_on_material[d], communicator);
        started = true;
      }

      std::vector<std::string>
      step_measure_columns() const override
      {
        return {"kinetic_energy", "strain_energy", "total_energy"};
      }

      void
      step_measures(const double,
                    std::vector<StepMeasure> &measures) const override
      {
        measures.push_back(
          {"kinetic_energy", "Ek", kinetic_energy, MeasureKind::energy});
        measures.push_back(
          {"strain_energy", "Es", strain_energy, MeasureKind::energy});
        measures.push_back({"total_energy",
                            "E",
                            kinetic_energy + strain_energy,
                            MeasureKind::energy});
      }

    private:
      /** A point's elastic energy at the step's end (its converged
       *  update), @f$V_0\,\tfrac12\,\tau : \varepsilon_e@f$
       *  with the elastic logarithmic strain @f$\varepsilon_e = \tfrac12
       *  \ln b_e@f$: exact for the elastic laws linear in the logarithmic
       *  strain (Hencky, and the plastic models built on it), an estimate
       *  for pressure-dependent elasticity (Cam-clay). */
      static double
      stored_energy(const PointStep<dim> &step)
      {
        const auto eigen =
          spectral_decomposition(step.update.elastic_left_cauchy_green);
        SymmetricTensor<2, 3> log_strain;
        for (unsigned int k = 0; k < 3; ++k)
          log_strain +=
            0.5 * std::log(eigen[k].first) *
            symmetrize(outer_product(eigen[k].second, eigen[k].second));
        return step.initial_volume * 0.5 *
               (step.update.kirchhoff_stress * log_strain);
      }

      /** The weight of the end-of-step inertial force, (1 - alpha_m) / (1 -
       *  alpha_f). */
      double
      k_m() const
      {
        return (1. - alpha_m) / (1. - alpha_f);
      }

      /** The number of local DoFs (owned and ghosts). */
      unsigned int
      n_local() const
      {
        return mass.locally_owned_size() +
               mass.get_partitioner()->n_ghost_indices();
      }

      const bool                           generalised_alpha;
      const double                         spectral_radius;
      const double                         alpha_m;
      const double                         alpha_f;
      const double                         beta;
      const double                         gamma;
      const double                         mass_damping;
      const std::string                    initial_velocity_expression;
      std::unique_ptr<FunctionParser<dim>> initial_velocity;
      const BackgroundGrid<dim>           &grid;
      /** Whether a step was accepted (or the run resumed): the points
       *  carry accelerations. */
      bool        started   = false;
      double      time_step = 0.;
      NodalVector mass, momentum, mass_acceleration;
      /** Whether each local DoF is in the system (not constrained). */
      std::vector<bool> in_system;
      /** The residual of the step's start on the local DoFs (empty
       *  unless generalised-alpha). */
      std::vector<double> start_residual;
      double              inertial_force_norm = 0.;
      double              kinetic_energy      = 0.;
      double              strain_energy       = 0.;
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
