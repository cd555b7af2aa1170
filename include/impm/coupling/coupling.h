#ifndef impm_coupling_coupling_h
#define impm_coupling_coupling_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <impm/base/errors.h>
#include <impm/base/plugin_list.h>
#include <impm/core/load_path.h>
#include <impm/core/parameters.h>
#include <impm/coupling/coupling_inputs.h>
#include <impm/coupling/point_gradients.h>
#include <impm/coupling/step_energy.h>
#include <impm/coupling/step_measure.h>
#include <impm/coupling/step_refusal.h>
#include <impm/grid/background_grid.h>
#include <impm/io/run_state.h>
#include <impm/mechanics/pulled_back_stress.h>
#include <impm/points/material_points.h>
#include <impm/points/point_step.h>
#include <impm/system/load_step_system.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Where a coupling's rows of unknowns go in the load step's linear
   * system: after this process's nodal rows, coupling after coupling.
   */
  struct CouplingRows
  {
    /** The first of the rows this coupling owns on this process. */
    types::global_dof_index first;
    /** The rows this process owns in the system (all couplings'). */
    const IndexSet &owned;
  };

  /**
   * @brief Everything that adds to a load step's equilibrium beside the
   * points' stresses and the loads: a stabilisation, a kinematic treatment,
   * a contact, springs, and whatever comes next (inertia, pore water).
   * ASPECT's assembler manager and Lethe's physics assemblers are the
   * pattern: the load-step code (LoadStepSystem, LoadStepProblem, the
   * Assembler, MPMSolver) loops over the scene's couplings (Couplings) and
   * names none of them.
   *
   * A coupling may
   * - add rows of unknowns of its own to the sparse system (prepare(),
   *   setup(), add_row_residuals(), add_solution()), with dense blocks in
   *   the sparsity pattern,
   * - add a few unknowns shared by all processes (n_global_unknowns()),
   *   which LoadStepProblem eliminates together, all couplings' in one
   *   bordered block,
   * - add forces and their derivative (add_forces(), add_matrix(), and the
   *   part of the matrix that is fixed over a load step,
   *   add_constant_matrix()),
   * - set the points' volume change (sets_point_volumes(): F-bar), and
   *   with it change each point's tangent,
   * - keep state that changes when a step is accepted (accept()), is saved
   *   in a checkpoint (save(), load()) and written (step_measures()),
   * - describe itself in a line (descriptions()).
   *
   * Every function has a default that does nothing, so that a coupling
   * implements only what it adds. Functions marked collective are called
   * on every process of every coupling.
   *
   * A new coupling is a class derived from this one and a registration
   * line (IMPM_REGISTER_COUPLING); doc/architecture.md follows a load step
   * through these functions.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class Coupling
  {
  public:
    /** @brief Destructor. */
    virtual ~Coupling() = default;

    /** @name The run */
    /** @{ */

    /** @brief Lines for the run's list of effects. */
    virtual std::vector<std::string>
    descriptions() const = 0;

    /** @brief Notes for the start-up report on the scene's linear solver
     *  @p linear_solver (none by default). */
    virtual std::vector<std::string>
    notes(const Parameters::LinearSolverType linear_solver) const;

    /** @brief Whether the linear systems need a direct solver (what
     *  'automatic' then chooses). */
    virtual bool
    needs_direct_solver() const;

    /**
     * @brief The fields this coupling stores at every material point (a
     * history it needs from step to step); none by default. The points lay
     * them out, write those marked written and keep them in checkpoints; the
     * coupling finds its field's first entry in a point's properties with
     * PointLayout::coupling_field(name) and stores new values with
     * MaterialPoints::set_coupling_field().
     */
    virtual PointFields
    point_fields() const;

    /** @brief Whether it may hold the material in displacement component
     *  @p component, so that no face condition needs to (a floor, springs):
     *  SceneChecks::check_supports(). False by default. */
    virtual bool
    holds_material(const unsigned int component) const;

    /** @brief Check the scene once its points exist, in a run that does
     *  not resume. Collective. */
    virtual void
    check_start(const MaterialPoints<dim> &material_points) const;

    /** @brief Give the points the initial values of its point_fields() (a
     *  run that does not resume; after check_start(); zero by default). */
    virtual void
    initialize_points(MaterialPoints<dim> &material_points);

    /** @brief Save what a resumed run needs into @p state. */
    virtual void
    save(RunState &state) const;

    /** @brief Read what save() stored. */
    virtual void
    load(const RunState &state);
    /** @} */

    /** @name The load step's system */
    /** @{ */

    /**
     * @brief Before the system is numbered: see the step's points and which
     * local DoFs they touch (@p touched), and return the number of rows of
     * unknowns of its own this process adds (0 by default). Collective.
     */
    virtual unsigned int
    prepare(const MaterialPoints<dim> &material_points,
            const LoadStepSystem<dim> &system,
            const std::vector<bool>   &touched);

    /**
     * @brief Once the system is numbered: number its own rows from @p
     * rows.first, and append to @p blocks the system indices (ascending) of
     * every dense block it adds to the matrix, for the sparsity pattern.
     * Collective.
     */
    virtual void
    setup(const MaterialPoints<dim>                         &material_points,
          const LoadStepSystem<dim>                         &system,
          const CouplingRows                                &rows,
          std::vector<std::vector<types::global_dof_index>> &blocks);
    /** @} */

    /** @name One attempt at a load step */
    /** @{ */

    /**
     * @brief Start an attempt at the step @p span (its load factors and
     * times), before the first residual. Collective.
     */
    virtual void
    begin_attempt(const MaterialPoints<dim> &material_points,
                  const LoadStepSystem<dim> &system,
                  const StepSpan            &span);

    /**
     * @brief Whether this attempt needs the residual of the step's start
     * (set_start_residual()): an integrator in time that weighs the
     * forces of the start and of the end of a step, or the first step's
     * acceleration. False by default: none is computed.
     */
    virtual bool
    needs_start_residual() const;

    /**
     * @brief The residual of the step's start, after begin_attempt(): the
     * material's internal force of the start-of-step stresses on this
     * step's grid, with the forces of the couplings that do not ask for it
     * at the zero increment (contact, springs, a base's shaking), minus
     * the external force at the step's start load factor, on every DoF
     * (owned, with the ghosts updated).
     */
    virtual void
    set_start_residual(const NodalVector &internal_minus_external);

    /** @brief Whether this coupling finds each step's increment itself
     *  (explicit time integration): the system then has no matrix and a
     *  step no Newton iteration; step_increment() gives the increment after
     *  set_start_residual(). At most one coupling may. False by default. */
    virtual bool
    solves_step() const;

    /**
     * @brief The step's increment at the DoFs of the system, owned and
     * ghost (the others keep theirs: zero, or a prescribed face's), when
     * solves_step(); @p largest_time_step is set to the time step the
     * coupling allows from this step's start (explicit: the Courant number
     * times the stable step), or left as it is.
     * @return The empty string, or why the step must be cut (a time step
     *   above the stable one). Collective.
     */
    virtual std::string
    step_increment(const LoadStepSystem<dim> &system,
                   NodalVector               &increment,
                   double                    &largest_time_step);

    /** @brief Why this coupling cannot be part of a scene whose steps are
     *  explicit (Couplings::step_solver()), in one line; empty (the
     *  default) if it can. Asked once, when the couplings are made. */
    virtual std::string
    explicit_step_conflict() const;

    /** @brief The largest stiffness per area (Pa/m) this coupling's springs
     *  add at the material's surface (Winkler springs; 0 by default), which
     *  the stable explicit step counts (explicit_modulus()). */
    virtual double
    surface_stiffness() const;

    /**
     * @brief Told once, when the couplings are made, that the scene's steps
     * are explicit (Couplings::step_solver()), with the largest
     * surface_stiffness() of the scene's couplings: a coupling whose forces
     * must allow for an explicit step's dynamics adjusts (RigidContact: an
     * impact presses faces deeper than the penalty's equilibrium; Inertia:
     * the stable step counts the springs). The default does nothing.
     */
    virtual void
    use_explicit_steps(const double surface_stiffness);

    /**
     * @brief Whether this coupling sets the points' volume change: then the
     * Assembler hands it every point's stress update
     * (update_stresses()), and changes each point's tangent through
     * point_tangent(). At most one coupling of a scene may.
     */
    virtual bool
    sets_point_volumes() const;

    /**
     * @brief The stress update of every point, when sets_point_volumes().
     * @param point_steps The points, with their true deformation gradient
     *   increments (all with positive determinant).
     * @param update_point Runs point q's return map on its
     *   PointStep::deformation_increment; false if the model threw.
     * @return False if the update failed (an inadmissible iterate).
     * Collective.
     */
    virtual bool
    update_stresses(PointSteps<dim>                         &point_steps,
                    const std::function<bool(unsigned int)> &update_point);

    /**
     * @brief The tangent of point @p p with this coupling's part, when
     * sets_point_volumes() (the point's group is then assembled without
     * major symmetry).
     * @param p The point's index in the point steps.
     * @param tangent The statement's tangent (times volume).
     * @param force_stress The statement's force stress (times volume).
     * @param gradient_map As PointGradients::gradient_map().
     * @param hoop Axisymmetry: the point's hoop entries of the tangent
     *   (times volume), which it may change too; nullptr otherwise.
     * @param hoop_force_stress Axisymmetry: the hoop force's factor on the
     *   statement's hoop weights (@f$\tau_{\theta\theta} V^0 /
     *   \Delta F_{\theta\theta}@f$ on the start-of-step grid,
     *   @f$\tau_{\theta\theta} V^0@f$ in the current configuration).
     * @param hoop_map As PointGradients::hoop_map().
     */
    virtual Tensor<4, dim>
    point_tangent(const unsigned int    p,
                  const Tensor<4, dim> &tangent,
                  const Tensor<2, dim> &force_stress,
                  const Tensor<2, dim> &gradient_map,
                  HoopTangent<dim>     *hoop,
                  const double          hoop_force_stress,
                  const double          hoop_map);

    /**
     * @brief Add this coupling's force on the material, with the sign of an
     * internal force, at the displacement increment @p increment to @p
     * internal_force (before its compress()).
     */
    virtual void
    add_forces(const LoadStepSystem<dim> &system,
               const NodalVector         &increment,
               NodalVector               &internal_force);

    /**
     * @brief As add_forces(), for the residual of the step's start
     * (set_start_residual()): the force at the step's start time, where it
     * depends on time (a base's shaking). By default add_forces().
     */
    virtual void
    add_start_forces(const LoadStepSystem<dim> &system,
                     const NodalVector         &increment,
                     NodalVector               &internal_force);

    /**
     * @brief Append the residuals of its own rows that this process owns,
     * as (system index, residual), the residual with the sign of an
     * internal force. Collective.
     */
    virtual void
    add_row_residuals(
      std::vector<std::pair<types::global_dof_index, double>> &residuals);

    /**
     * @brief The size of the forces its rows and global unknowns are
     * measured against (applied forces), added to the residual's reference
     * (0 by default).
     */
    virtual double
    reference_force() const;

    /**
     * @brief Whether its state changed (into or out of a contact) at the
     * last add_forces() against the one before in the same attempt: a full
     * linear solve follows, and a tangent check leaves the column out.
     * Collective.
     */
    virtual bool
    state_changed() const;

    /**
     * @brief The size (N) of the round-off in the forces of its last
     * add_forces(), independent of the iterate: a residual below it is as
     * converged as the arithmetic allows (0 by default). A penalty contact's
     * forces are a stiffness of E/h times a gap found by subtracting
     * coordinates of the order of the grid's size: the residual of a block
     * resting on a rigid floor under a small load increment stalls there,
     * above 'Solver/Tolerance' times its load (RigidContact). Collective.
     */
    virtual double
    round_off_force() const;

    /**
     * @brief Add the part of the matrix that does not change within a load
     * step (after setup(), to a zeroed matrix); returns whether it added
     * anything. The system keeps it for the step's later assemblies.
     */
    virtual bool
    add_constant_matrix(const LoadStepSystem<dim>      &system,
                        TrilinosWrappers::SparseMatrix &matrix);

    /**
     * @brief Add the derivative of its forces and rows at the last residual
     * to @p matrix (after the points' blocks, before the compress()).
     * Returns whether an entry went through the matrix's add() (then the
     * matrix is compressed).
     */
    virtual bool
    add_matrix(const PointGradients<dim>      &gradients,
               const LoadStepSystem<dim>      &system,
               TrilinosWrappers::SparseMatrix &matrix);

    /**
     * @brief Add the Newton correction @p solution (the system's
     * numbering) to its own rows' unknowns.
     */
    virtual void
    add_solution(const TrilinosWrappers::MPI::Vector &solution);

    /**
     * @brief The tangent check: perturb its own row @p row by @p amount
     * over the cell size if this process owns it; returns the factor the
     * perturbation was scaled by, or 0 (not its row, or not this
     * process's).
     */
    virtual double
    perturb_row(const types::global_dof_index row, const double amount);

    /**
     * @brief The largest change of its unknowns over the attempt, in cells
     * (0 by default). Collective.
     */
    virtual double
    max_unknown_increment() const;
    /** @} */

    /** @name Unknowns shared by all processes */
    /** @{ */

    /** @brief Their number (0 by default). */
    virtual unsigned int
    n_global_unknowns() const;

    /** @brief Their residuals at the last add_forces() (with the sign of
     *  f_ext - f_int), the same on every process. Collective. */
    virtual Vector<double>
    global_residuals() const;

    /**
     * @brief The blocks of the matrix that couple its global unknowns with
     * the DoFs, at the last add_forces(): per unknown j the column @p
     * columns[j] and the row @p rows[j] (full numbering, compressed), and
     * the derivative of their forces with respect to each other, @p
     * corner. Collective.
     */
    virtual void
    global_coupling(const LoadStepSystem<dim> &system,
                    std::vector<NodalVector>  &columns,
                    std::vector<NodalVector>  &rows,
                    FullMatrix<double>        &corner) const;

    /** @brief Add @p correction (one per global unknown, the same on every
     *  process) to them. */
    virtual void
    add_to_global_unknowns(const Vector<double> &correction);

    /** @brief Why global unknown @p j with no stiffness of its own cannot
     *  be solved for (a line for the failed solve). */
    virtual std::string
    unbalanced_unknown(const unsigned int j) const;
    /** @} */

    /** @name A converged step */
    /** @{ */

    /** @brief Take the converged step, whose displacement increment is
     *  @p increment (ghosted): store what it keeps (in the points too: its
     *  point_fields(), by the points' steps in @p system). Collective. */
    virtual void
    accept(MaterialPoints<dim>       &material_points,
           const LoadStepSystem<dim> &system,
           const NodalVector         &increment);

    /** @brief Whether the converged step with displacement increment @p
     *  increment (ghosted) must be refused (none by default): checked
     *  before accept(), on every process. Collective. */
    virtual StepRefusal
    refuse_step(const MaterialPoints<dim> &material_points,
                const LoadStepSystem<dim> &system,
                const NodalVector         &increment) const;

    /** @brief Add this process's share of the energy its forces moved over
     *  the converged step with displacement increment @p increment
     *  (ghosted; the increments of the points in @p system), by the rule in
     *  time those forces follow: their work on the material
     *  (StepEnergy::external_work: springs, dashpots, contacts, a shaken
     *  base) or what a numerical term took out (StepEnergy::dissipated).
     *  Called before accept() and only in a scene that keeps an energy
     *  balance. Nothing by default, right only for a coupling with no
     *  forces of its own: one that adds forces must say what they do. */
    virtual void
    add_step_energy(const LoadStepSystem<dim> &system,
                    const NodalVector         &increment,
                    StepEnergy                &energy);

    /** @brief Whether it keeps the scene's energy balance (inertia; none
     *  by default): then take_step_energy() tells it what the others
     *  moved in each converged step. */
    virtual bool
    keeps_energy_balance() const;

    /** @brief The converged step's energy from the loads, the faces and
     *  the other couplings, summed over the processes, before accept()
     *  (a keeper of the energy balance only). */
    virtual void
    take_step_energy(const StepEnergy &energy);

    /** @brief Why the run cannot go on after the accepted step although
     *  it converged (empty if it can): a check of the solution itself, as
     *  the energy balance of an integration gone unstable. After the
     *  step's output; the same on every process. */
    virtual std::string
    run_failure() const;

    /** @brief The force of the material on what this coupling stands for
     *  (bodies, springs) at the last accepted step, which carries part of
     *  the load (zero by default). */
    virtual Tensor<1, dim>
    force_from_material() const;

    /** @brief The columns of its step_measures(), for steps.csv. */
    virtual std::vector<std::string>
    step_measure_columns() const;

    /** @brief Its values after the last accepted step (at load factor @p
     *  load_factor). */
    virtual void
    step_measures(const double              load_factor,
                  std::vector<StepMeasure> &measures) const;
    /** @} */
  };

  /**
   * @brief The couplings, registered by name: an entry's create() returns
   * nullptr when the scene does not ask for it (which then costs nothing);
   * its declare_parameters() declares its subsection's entries (entered by
   * Couplings::declare_parameters(); empty for couplings whose parameters
   * live elsewhere).
   */
  template <int dim>
  using CouplingList = PluginList<Coupling<dim>, const CouplingInputs<dim> &>;

} // namespace impm

/**
 * Register coupling CLASS (a class template over dim, constructed from
 * CouplingInputs) under NAME, created when @p WANTED (an expression of
 * `inputs`, a CouplingInputs<dim>) holds; @p DECLARE declares its
 * parameters (a lambda in parentheses taking a ParameterHandler, or
 * nullptr). The one line a coupling needs besides its class.
 */
#define IMPM_REGISTER_COUPLING(CLASS, NAME, WANTED, DECLARE) \
  IMPM_REGISTER_PLUGIN_IN_BOTH_DIMENSIONS(                   \
    impm::CouplingList,                                      \
    CLASS,                                                   \
    NAME,                                                    \
    DECLARE,                                                 \
    ([](const impm::CouplingInputs<dim> &inputs)             \
       -> std::unique_ptr<impm::Coupling<dim>> {             \
      if (!(WANTED))                                         \
        return nullptr;                                      \
      return std::make_unique<CLASS<dim>>(inputs);           \
    }))

#endif
