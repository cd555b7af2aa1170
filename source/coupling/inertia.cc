// Inertia as a coupling: implicit Newmark time stepping in the previously
// converged form, with the lumped or consistent mass of the start-of-step
// grid.
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <impm/base/errors.h>
#include <impm/base/names.h>
#include <impm/coupling/central_difference.h>
#include <impm/coupling/coupling.h>
#include <impm/coupling/energy_balance.h>
#include <impm/coupling/initial_velocity.h>
#include <impm/coupling/mass_ghost_penalty.h>
#include <impm/coupling/newmark_update.h>
#include <impm/coupling/nodal_momentum.h>
#include <impm/coupling/stiffness_damping.h>
#include <impm/coupling/time_integrator.h>

#include <algorithm>
#include <cmath>
#include <limits>
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
     * the case @f$\alpha_m = \alpha_f = 0@f$. r^n holds the couplings'
     * start forces (Coupling::add_start_forces(): springs, a base's shaking).
     *
     * Mass-proportional (Rayleigh) damping @f$C = \alpha_R M@f$ adds
     * @f$\alpha_R (M v^{n+1} + k_r p)@f$, weighed like the internal force.
     * The matrix gains @f$(k_m c_1 + \alpha_R\gamma\Delta t\, c_1) M@f$ on
     * its diagonal, constant over the step. The stiffness-proportional
     * part, @f$\beta_R K_e@f$, is a viscous stress at the points
     * (StiffnessDamping), weighed alike.
     *
     * The first step's nodal acceleration is that of the balance at the
     * start, @f$M a^0 = f_{ext}(0) - f_{int}(0)@f$ less the damping of the
     * initial velocity (a body under gravity at once falls at g).
     *
     * The explicit integrators (`explicit MUSL`, `explicit USL`) are the
     * central difference rule with the lumped mass
     * (central_difference_step()): no matrix and no Newton iteration
     * (Coupling::solves_step()), the increment through the same stress
     * update as an implicit step. The step is stable below @f$\Delta t_c
     * = C\, h_{min} / c_p@f$ (Courant number C, smallest cell, largest
     * speed of sound @f$\sqrt{M/\rho_0}@f$ of the points), checked when
     * the scene is made and every step from each point's stress
     * (stable_time_step()): a step above it is cut.
     *
     * A converged step updates each point (FLIP): @f$v_p \mathrel{+}=
     * \sum_I N_{Ip} (v_I^{n+1} - v_I^n)@f$, @f$a_p = \sum_I N_{Ip}
     * a_I^{n+1}@f$ (a held or prescribed node: no change of velocity, its
     * face's mean velocity, no acceleration). The trapezoidal rule
     * (@f$\beta = 1/4, \gamma = 1/2@f$, the default) conserves the energy
     * of the nodal system; the transfer between points and nodes does not
     * (EnergyBalance measures it). A FLIP
     * fraction @f$\phi < 1@f$ blends in PIC: @f$v_p = \phi\,(v_p +
     * \sum_I N_{Ip}\Delta v_I) + (1 - \phi) \sum_I N_{Ip} v_I^{n+1}@f$,
     * which damps the points' velocity noise. APIC (`Velocity update`)
     * takes the nodes' new velocity and its gradient to the points and an
     * affine field back to the nodes (NodalMomentum): a rigid rotation
     * stays rigid.
     *
     * The points' `velocity` and `acceleration` are declared point fields
     * (written, kept in checkpoints); the energy balance (EnergyBalance)
     * gives the step measures. A scene that does not name inertia
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
        TimeIntegrator::declare_parameters(prm);
        EnergyBalance<dim>::declare_parameters(prm);
        MassGhostPenalty<dim>::declare_parameters(prm);
        InitialVelocity<dim>::declare_parameters(prm);
      }

      /** @brief The inertia of a scene (from its subsection; it needs the
       *  scene's time). */
      explicit Inertia(const CouplingInputs<dim> &inputs)
        : integrator(inputs.prm)
        , initial_velocity(inputs.prm)
        , grid(inputs.grid)
        , nodes(inputs.grid, integrator.affine_transfer)
        , stiffness_damping(integrator)
        , contact_penalty(
            contact_penalty_factor(inputs.parameters.rigid_bodies))
        , mass_ghost(inputs.prm,
                     integrator,
                     inputs.grid,
                     inputs.parameters.bodies)
        , inputs(inputs)
        , energy_balance(inputs.prm,
                         grid.get_triangulation().get_communicator(),
                         integrator.is_explicit())
      {
        if (!inputs.time.in_time())
          throw InputError("Inertia needs time: set 'Time/End time' above 0 "
                           "(the load steps are then time steps).");
        integrator.check_velocity_update(
          inputs.parameters.material_points.basis,
          !inputs.parameters.rigid_bodies.empty(),
          Utilities::MPI::this_mpi_process(
            grid.get_triangulation().get_communicator()) == 0);
      }

      /** @brief Refuse a time step above the stable explicit step, with
       *  the couplings' springs (once all couplings are made). */
      void
      use_explicit_steps(const double surface_stiffness) override
      {
        springs_stiffness = surface_stiffness;
        if (integrator.is_explicit())
          check_explicit_time_step(inputs,
                                   integrator,
                                   stiffness_damping,
                                   surface_stiffness);
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
        PointFields fields{{"velocity", dim, true},
                           {"acceleration", dim, true}};
        if (integrator.affine_transfer)
          fields.push_back({"velocity_gradient", dim * dim, true});
        return fields;
      }

      std::vector<std::string>
      descriptions() const override
      {
        std::ostringstream out;
        out << "inertia: " << integrator.description();
        if (initial_velocity.active())
          out << ", " << initial_velocity.description();
        if (mass_ghost.active())
          out << ", " << mass_ghost.description();
        return {out.str()};
      }

      void
      initialize_points(MaterialPoints<dim> &material_points) override
      {
        initial_velocity.initialize(material_points,
                                    integrator.affine_transfer);
      }

      void
      save(RunState &state) const override
      {
        energy_balance.save(state);
      }

      /** @brief A resumed run: its points carry their accelerations. */
      void
      load(const RunState &state) override
      {
        energy_balance.load(state);
        started = true;
      }

      /** @brief True: a scene with inertia keeps an energy balance. */
      bool
      keeps_energy_balance() const override
      {
        return true;
      }
      void
      take_step_energy(const StepEnergy &energy) override
      {
        energy_balance.take(energy);
      }
      /** @brief Energy made from nothing (EnergyBalance::unstable_growth()). */
      std::string
      run_failure() const override
      {
        return energy_balance.unstable_growth();
      }

      /** @brief The mass ghost penalty's faces of the step. */
      unsigned int
      prepare(const MaterialPoints<dim> &material_points,
              const LoadStepSystem<dim> &,
              const std::vector<bool> &touched) override
      {
        mass_ghost.choose_faces(material_points, touched);
        return 0;
      }

      /** @brief The mass ghost penalty's blocks. */
      void
      setup(const MaterialPoints<dim> &,
            const LoadStepSystem<dim> &system,
            const CouplingRows &,
            std::vector<std::vector<types::global_dof_index>> &blocks) override
      {
        mass_ghost.add_blocks(system, blocks);
      }

      /** @brief The nodal mass, momentum and mass times acceleration of
       *  the step's start. */
      void
      begin_attempt(const MaterialPoints<dim> &material_points,
                    const LoadStepSystem<dim> &system,
                    const StepSpan            &span) override
      {
        time_step = span.time_step();
        end_time  = span.end_time;
        held_increment =
          integrator.is_explicit() && grid.moves_faces() ?
            grid.local_prescribed_increment(span.target - span.start) :
            std::vector<double>();
        if (!started)
          energy_balance.start(material_points, system.point_steps);
        nodes.map_points(material_points, system);
        stiffness_damping.begin_step(material_points, system.point_steps);
        start_residual.clear();
        current_points = &material_points;
        current_system = &system;
        const MPI_Comm communicator =
          grid.get_triangulation().get_communicator();
        if (integrator.is_explicit())
          stable_step_size =
            integrator.courant_number * stiffness_damping.critical_time_step(
                                          stable_time_step(material_points,
                                                           system.point_steps,
                                                           grid.cartesian(),
                                                           1.,
                                                           contact_penalty,
                                                           springs_stiffness,
                                                           communicator));
        else
          // The momentum part of the inertial force, M v / (beta dt), whose
          // size floors the residual's reference.
          momentum_force =
            nodes.momentum_norm() / (integrator.beta * time_step);
      }

      /** @brief Generalised-alpha weighs the start's residual; the first
       *  step takes its acceleration from it. */
      bool
      needs_start_residual() const override
      {
        // A moving face's force at the start enters the energy balance.
        return integrator.alpha_f > 0. || !started ||
               integrator.is_explicit() || grid.moves_faces();
      }

      /** @brief True with an explicit integrator. */
      bool
      solves_step() const override
      {
        return integrator.is_explicit();
      }

      /** @brief The explicit step's increment (set_start_residual()
       *  found it), or why the step is cut: its time step above the
       *  stable one at Courant number 1; the largest time step the
       *  Courant number allows from this start. */
      std::string
      step_increment(const LoadStepSystem<dim> &system,
                     NodalVector               &increment,
                     double                    &largest_time_step) override
      {
        largest_time_step = stable_step_size;
        const std::string refusal =
          explicit_step_refusal(time_step,
                                stable_step_size / integrator.courant_number,
                                grid.cartesian());
        if (!refusal.empty())
          return refusal;
        for (unsigned int i = 0; i < nodes.n_local(); ++i)
          if (system.system_index(i) != numbers::invalid_dof_index)
            increment.local_element(i) = explicit_increment[i];
        return "";
      }

      /** @brief Keep the start's residual (generalised-alpha), and on the
       *  first step set the nodes' mass times acceleration to the start's
       *  balance with the damping (set_start_acceleration()). */
      void
      set_start_residual(const NodalVector &internal_minus_external) override
      {
        if (integrator.is_explicit())
          {
            const NodalVector &residual =
              stiffness_damping.active() ?
                stiffness_damping.damped_residual(nodes,
                                                  *current_system,
                                                  internal_minus_external) :
                internal_minus_external;
            const unsigned int n_owned = grid.n_locally_owned_dofs();
            damping_dissipation =
              central_difference_step(nodes,
                                      residual,
                                      time_step,
                                      integrator,
                                      *current_points,
                                      current_system->point_steps,
                                      explicit_increment,
                                      point_velocities,
                                      point_accelerations,
                                      point_velocity_gradients,
                                      n_owned,
                                      held_increment,
                                      !started,
                                      nodal_kinetic);
            if (stiffness_damping.active())
              damping_dissipation +=
                stiffness_damping.explicit_dissipation(explicit_increment,
                                                       n_owned);
            return;
          }
        if (integrator.alpha_f > 0.)
          {
            start_residual.resize(nodes.n_local());
            for (unsigned int i = 0; i < nodes.n_local(); ++i)
              start_residual[i] = nodes.in_system(i) ?
                                    internal_minus_external.local_element(i) :
                                    0.;
          }
        if (!started)
          set_start_acceleration(nodes,
                                 integrator,
                                 stiffness_damping,
                                 *current_system,
                                 internal_minus_external);
      }

      /** @brief The mass term of the matrix on the diagonal of the owned
       *  rows (added with every matrix: the constant part of the matrix is
       *  kept over the attempts of a step, whose time steps differ). */
      bool
      add_matrix(const PointGradients<dim> &,
                 const LoadStepSystem<dim>      &system,
                 TrilinosWrappers::SparseMatrix &matrix) override
      {
        if (integrator.is_explicit())
          return false;
        const double c1 = 1. / (integrator.beta * time_step * time_step);
        const double c  = (integrator.k_m() + integrator.mass_damping *
                                               integrator.gamma * time_step) *
                         c1;
        const double diagonal =
          integrator.consistent_mass ? integrator.mass_regularisation : 1.;
        if (integrator.consistent_mass)
          nodes.add_consistent_mass(c, *current_points, system, matrix);
        for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
          {
            const auto row = system.system_index(i);
            if (row != numbers::invalid_dof_index && nodes.mass(i) > 0. &&
                diagonal > 0.)
              matrix.add(row, row, diagonal * c * nodes.mass(i));
          }
        if (stiffness_damping.active())
          stiffness_damping.add_implicit_matrix(system, time_step, matrix);
        mass_ghost.add_matrix(system, time_step, matrix);
        return true;
      }

      /** @brief The inertial (and damping) force at the owned DoFs of the
       *  system. Collective (its size). */
      void
      add_forces(const LoadStepSystem<dim> &,
                 const NodalVector &increment,
                 NodalVector       &internal_force) override
      {
        if (integrator.is_explicit())
          return;
        // M du: lumped, or the consistent matrix's (through the points).
        const NewmarkForceSums sums = add_newmark_forces(
          nodes,
          integrator,
          time_step,
          increment,
          integrator.consistent_mass ?
            nodes.consistent_mass_times(*current_points,
                                        current_system->point_steps,
                                        increment) :
            std::vector<double>(),
          start_residual,
          grid,
          internal_force);
        double norm_squared = sums.norm_squared;
        force_on_material   = sums.force;
        damping_dissipation = sums.damping_dissipation;
        mass_ghost.add_forces(increment, time_step, internal_force);
        // The viscous stress: internal, not in force_on_material.
        if (stiffness_damping.active())
          norm_squared += stiffness_damping.add_implicit_forces(
            nodes, *current_system, increment, time_step, internal_force);
        // The reference: the inertial force, floored by a millionth of its
        // momentum part M v / (beta dt) (a body moving freely has an
        // inertial force of round-off size, relative to which it stalls).
        inertial_force_norm =
          std::hypot(std::sqrt(Utilities::MPI::sum(
                       norm_squared,
                       grid.get_triangulation().get_communicator())),
                     1e-6 * momentum_force);
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

      /** @brief The points' new velocity and acceleration (and with APIC
       *  velocity gradient) and the energy balance. */
      void
      accept(MaterialPoints<dim>       &material_points,
             const LoadStepSystem<dim> &system,
             const NodalVector         &increment) override
      {
        const auto &steps = system.point_steps;
        if (!integrator.is_explicit())
          {
            nodal_kinetic = newmark_point_update(nodes,
                                                 increment,
                                                 time_step,
                                                 integrator,
                                                 material_points,
                                                 steps,
                                                 point_velocities,
                                                 point_accelerations,
                                                 point_velocity_gradients,
                                                 grid.n_locally_owned_dofs());
            // The mass ghost penalty's and the viscous stress's energy, once
            // a step (add_forces() kept the mass damping's).
            damping_dissipation +=
              mass_ghost.dissipation(increment, time_step) +
              stiffness_damping.implicit_dissipation(nodes,
                                                     system,
                                                     increment,
                                                     time_step);
          }
        energy_balance.accept(material_points,
                              steps,
                              point_velocities,
                              damping_dissipation,
                              nodal_kinetic,
                              end_time - time_step,
                              end_time);
        material_points.set_coupling_field("velocity", steps, point_velocities);
        material_points.set_coupling_field("acceleration",
                                           steps,
                                           point_accelerations);
        if (integrator.affine_transfer)
          material_points.set_coupling_field("velocity_gradient",
                                             steps,
                                             point_velocity_gradients);
        for (unsigned int d = 0; d < dim; ++d)
          accepted_force[d] =
            Utilities::MPI::sum(force_on_material[d],
                                grid.get_triangulation().get_communicator());
        started = true;
      }

      std::vector<std::string>
      step_measure_columns() const override
      {
        return EnergyBalance<dim>::columns();
      }

      void
      step_measures(const double,
                    std::vector<StepMeasure> &measures) const override
      {
        energy_balance.add_measures(measures);
      }

    private:
      /** The time integrator; the points' velocity at the start. */
      const TimeIntegrator       integrator;
      const InitialVelocity<dim> initial_velocity;
      const BackgroundGrid<dim> &grid;
      /** Whether the points carry accelerations (a step accepted). */
      bool   started   = false;
      double time_step = 0.;
      /** The stable explicit time step of the step's start. */
      double stable_step_size = std::numeric_limits<double>::max();
      /** The step's points and system (set in begin_attempt()). */
      const MaterialPoints<dim> *current_points = nullptr;
      const LoadStepSystem<dim> *current_system = nullptr;
      /** The explicit step's increment on the local DoFs; that of the
       *  DoFs a face moves (empty where none moves). */
      std::vector<double> explicit_increment, held_increment;
      /** The points' new velocities, accelerations, APIC gradients. */
      std::vector<double> point_velocities, point_accelerations,
        point_velocity_gradients;
      /** The nodes' mass and momentum of the step's start. */
      NodalMomentum<dim> nodes;
      /** The stiffness-proportional damping (inactive at 0). */
      StiffnessDamping<dim> stiffness_damping;
      /** The rigid bodies' contact stiffness as a factor of the material's
       *  Young's modulus (contact_penalty_factor()), 0 without them. */
      const double contact_penalty;
      /** The mass's ghost penalty (inactive at 0). */
      MassGhostPenalty<dim> mass_ghost;
      /** The largest stiffness per area of the scene's springs on faces
       *  (Coupling::surface_stiffness()), told by use_explicit_steps(). */
      double springs_stiffness = 0.;
      /** The scene, for the explicit start check (its references outlive
       *  the couplings). */
      const CouplingInputs<dim> inputs;
      /** The residual of the step's start on the local DoFs. */
      std::vector<double> start_residual;
      double              inertial_force_norm = 0.;
      /** The size of the step's momentum part of the inertial force,
       *  @f$|M v^n| / (\beta \Delta t)@f$ (implicit integrators). */
      double             momentum_force = 0.;
      EnergyBalance<dim> energy_balance;
      /** The end time of the step's attempt; the energy the damping and
       *  the mass's ghost penalty took out at this process's owned DoFs in
       *  the accepted step; the nodes' kinetic energy at its start and end
       *  there. */
      double             end_time = 0., damping_dissipation = 0.;
      NodalKineticEnergy nodal_kinetic;
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
