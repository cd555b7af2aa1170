#ifndef impm_contact_rigid_contact_h
#define impm_contact_rigid_contact_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <impm/core/rigid_body.h>
#include <impm/coupling/coupling.h>
#include <impm/grid/background_grid.h>
#include <impm/io/run_state.h>
#include <impm/points/material_points.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Contact between the material points and the scene's rigid
   * bodies: a penalty on the overlap of the points' GIMP domains with the
   * bodies, and Coulomb friction with a stick/slip return, inside the full
   * Newton solve with the consistent tangent of both.
   *
   * Each face of a point's domain that lies near a rigid body at the start
   * of an attempt becomes a contact probe: its centre moves with the
   * face's mean displacement (the face weights of BasisEvaluator), and
   * where it is inside the body and faces it (its outward normal against
   * the body's normal n), it carries a uniform pressure p = -k g (g the
   * signed distance, k = alpha E / h per area) over its area projected on
   * the body's surface, A c with c = -n_f . n. The friction traction is a
   * return of the trial traction t^n + k_t (relative slip in the step),
   * projected on the tangent plane, to |t| <= mu p. The contact force acts
   * on the material as a load that depends on the displacement: it is
   * added to the internal force with the opposite sign, and its derivative
   * to the matrix, so Testing/Check tangent checks both.
   *
   * A body pushed by a force (RigidBody::force_components) has its
   * displacement in those components as unknowns of the Newton solve
   * (unknowns()): their equation is the balance of the applied force with
   * the material's contact force on the body, and since every probe's
   * force depends on the face's position minus the body's displacement,
   * the derivatives with respect to the body follow from those with
   * respect to the face (add_coupling()): they are the coupling's global
   * unknowns, which LoadStepProblem eliminates with the other couplings'.
   *
   * A converged step stores each face's friction traction in the point
   * (the point field `contact_friction_traction`, only in scenes with
   * friction) and sums
   * the force on each body. A scene without rigid bodies creates none of
   * this.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class RigidContact : public Coupling<dim>
  {
  public:
    /** @brief The coupling of a scene with rigid bodies. */
    explicit RigidContact(const CouplingInputs<dim> &inputs);

    /**
     * @brief With friction, the field `contact_friction_traction`: the
     * friction traction of each probe of each face of the point's domain
     * (traction_entries() entries, not written).
     */
    PointFields
    point_fields() const override;

    /** @brief begin(). */
    void
    begin_attempt(const MaterialPoints<dim> &material_points,
                  const LoadStepSystem<dim> &system,
                  const StepSpan            &span) override;

    /** @brief add_contact_matrix(); through the matrix's add(). */
    bool
    add_matrix(const PointGradients<dim>      &gradients,
               const LoadStepSystem<dim>      &system,
               TrilinosWrappers::SparseMatrix &matrix) override;

    /** @brief applied_force_norm() with unknowns, else 0. */
    double
    reference_force() const override;

    /** @brief The size of unknowns(). */
    unsigned int
    n_global_unknowns() const override;

    /** @brief unknown_residuals(). */
    Vector<double>
    global_residuals() const override;

    /** @brief add_coupling(). */
    void
    global_coupling(const LoadStepSystem<dim> &system,
                    std::vector<NodalVector>  &columns,
                    std::vector<NodalVector>  &rows,
                    FullMatrix<double>        &corner) const override;

    /** @brief add_to_unknowns(). */
    void
    add_to_global_unknowns(const Vector<double> &correction) override;

    /**
     * @brief Refuse a converged step in which a body left the grid (the
     * run stops), was displaced by more than 'Rigid contact/Maximum motion
     * per step' cell sizes in one direction (its rotation is not limited), or
     * after which a material point lies inside a body deeper than the contact
     * lets a face in (tunnelling); the step control cuts the last two.
     * Collective.
     */
    StepRefusal
    refuse_step(const MaterialPoints<dim> &material_points,
                const LoadStepSystem<dim> &system,
                const NodalVector         &increment) const override;

    /** @brief Declare the entries of subsection 'Rigid contact'. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** @brief The body that no material holds in a force-driven
     *  component. */
    std::string
    unbalanced_unknown(const unsigned int j) const override;

    /** @brief True: rigid bodies may hold the material (a floor, a
     *  plate); whether they do is known only once they touch it. */
    bool
    holds_material(const unsigned int component) const override;

    /** @brief The sum of body_forces(). */
    Tensor<1, dim>
    force_from_material() const override;

    /**
     * @brief The entries of the friction tractions per point: dim per
     * probe of each face for each body with friction (0 without
     * friction).
     */
    static unsigned int
    traction_entries(const std::vector<RigidBody<dim>> &rigid_bodies);

    /**
     * @brief The largest number of probes on a face of a point's domain
     * over @p rigid_bodies (RigidBody::face_points() per direction).
     */
    static unsigned int
    max_face_points(const std::vector<RigidBody<dim>> &rigid_bodies);

    /**
     * @brief Constructor.
     * @param rigid_bodies The scene's rigid bodies (at least one).
     * @param grid The background grid.
     */
    RigidContact(const std::vector<RigidBody<dim>> &rigid_bodies,
                 const BackgroundGrid<dim>         &grid);

    /**
     * @brief Whether any of @p rigid_bodies has friction, so that the
     * points store their faces' friction tractions.
     */
    static bool
    has_friction(const std::vector<RigidBody<dim>> &rigid_bodies);

    /**
     * @brief Refuse a scene whose material points start inside a rigid
     * body: one line naming the rigid body and a point. Collective.
     */
    void
    check_start(const MaterialPoints<dim> &material_points) const override;

    /**
     * @brief Move the bodies to their displacement and rotation at load
     * factor @p start and @p target (the attempt's start and end) and
     * return the region each may touch in the attempt: its boxes at both,
     * grown by @p largest_cell (two for a body pushed by a force, which may
     * move about a cell more within the attempt).
     */
    std::vector<std::pair<Point<dim>, Point<dim>>>
    move_bodies(const double start,
                const double target,
                const double largest_cell);

    /**
     * @brief Start an attempt from load factor @p start to @p target: the
     * bodies move to their displacement at @p target, and the faces of
     * the points near them (within a cell of the bodies' boxes at @p start
     * and @p target) become this attempt's probes.
     * @param material_points The points at the start of the step.
     * @param system The step's system (its point steps and face weights).
     * @param start, target The load factors at the step's start and target.
     */
    void
    begin(const MaterialPoints<dim> &material_points,
          const LoadStepSystem<dim> &system,
          const double               start,
          const double               target);

    /**
     * @brief Evaluate the contact at the displacement increment @p
     * increment and subtract its force on the material from @p
     * internal_force (before its compress()).
     */
    void
    add_forces(const LoadStepSystem<dim> &system,
               const NodalVector         &increment,
               NodalVector               &internal_force) override;

    /**
     * @brief The contact of the step's start, for the residual of the
     * start (generalised-alpha weighs it): each face where the step starts
     * (the points unmoved) against each body where the step starts (its
     * start displacement and rotation, the friction's traction of the step
     * before); @p increment is not read. The probes' states are left as
     * they are.
     */
    void
    add_start_forces(const LoadStepSystem<dim> &system,
                     const NodalVector         &increment,
                     NodalVector               &internal_force) override;

    /**
     * @brief The contact's work on the material over the converged step
     * with increment @p increment: at each face, the mean of its force at
     * the step's start (as add_start_forces() finds it) and at its end,
     * times the face's displacement (the trapezoidal rule: exact for the
     * penalty's linear spring, an estimate for the friction's slip).
     */
    void
    add_step_energy(const LoadStepSystem<dim> &system,
                    const NodalVector         &increment,
                    StepEnergy                &energy) override;

    /** @brief An unknown of the bodies: a force-driven component. */
    struct Unknown
    {
      /** Index of the rigid body. */
      unsigned int body;
      /** The component of its displacement. */
      unsigned int component;
    };

    /** @brief The unknowns of the bodies (empty: every body's motion is
     *  prescribed), body by body. */
    const std::vector<Unknown> &
    unknowns() const
    {
      return body_unknowns;
    }

    /**
     * @brief The residual of each unknown at the last add_forces(): the
     * applied force at the attempt's target minus the force of the
     * contact on the material, summed over the body (N). Collective.
     */
    Vector<double>
    unknown_residuals() const;

    /**
     * @brief The norm of the applied forces on the unknowns at the
     * attempt's target (N).
     */
    double
    applied_force_norm() const;

    /**
     * @brief The blocks of the system matrix that couple the unknowns
     * with the displacement DoFs, at the last add_forces(): per unknown
     * j, the column @p columns[j] (the derivative of the internal force
     * with respect to it) and the row @p rows[j] (the derivative of its
     * residual's force with respect to the DoFs), in full numbering, and
     * @p corner, the derivative of the unknowns' forces with respect to
     * the unknowns. The vectors are compressed; @p corner is summed over
     * the processes. Collective.
     */
    void
    add_coupling(const LoadStepSystem<dim> &system,
                 std::vector<NodalVector>  &columns,
                 std::vector<NodalVector>  &rows,
                 FullMatrix<double>        &corner) const;

    /**
     * @brief Add @p correction (one entry per unknown, the same on every
     * process) to the bodies' displacements.
     */
    void
    add_to_unknowns(const Vector<double> &correction);

    /**
     * @brief The largest change of an unknown over the attempt, in cells
     * of its direction (0 without unknowns).
     */
    double
    max_unknown_increment() const override;

    /**
     * @brief The displacement of body @p k at load factor @p load_factor
     * when that was the last accepted step's (for output): the prescribed
     * part and, on the force-driven components, the accepted unknowns.
     */
    Tensor<1, dim>
    displacement_of(const unsigned int k, const double load_factor) const;

    /** @brief The displacement of body @p k on its force-driven
     *  components at the last accepted step (zero on the others). */
    const Tensor<1, dim> &
    pushed_displacement(const unsigned int k) const
    {
      return accepted_unknowns[k];
    }

    /** @brief Store the accepted unknowns in @p state (scenes with
     *  unknowns). */
    void
    save(RunState &state) const override;

    /** @brief Read the accepted unknowns from @p state (scenes with
     *  unknowns). */
    void
    load(const RunState &state) override;

    /**
     * @brief Whether, on any process, a probe changed its state (into or
     * out of contact, stick or slip) in the last add_forces() against the
     * one before in the same attempt. Collective.
     */
    bool
    state_changed() const override;

    /**
     * @brief With explicit steps a side keeps pushing a face that started
     * the step over it up to half its domain's half-length behind it (not
     * only h / alpha): an impact at a few m/s presses faces several times
     * deeper than the penalty's equilibrium within a step, and the body
     * passed through the side it struck.
     */
    void
    use_explicit_steps(const double surface_stiffness) override;

    /** @brief A body with force-driven components: its displacement there
     *  is an unknown of the load step's system, which an explicit step
     *  does not solve (the body would stand still). */
    std::string
    explicit_step_conflict() const override;

    /**
     * @brief The round-off of the last add_forces(): over the probes in
     * contact, the root of the sum of the squares of @f$\epsilon (k + k_t)
     * A |x|_\infty@f$, the stiffnesses per area times the probe's area
     * times the round-off of a gap found from coordinates of size
     * @f$|x|_\infty@f$ (the probe's position and the body's
     * displacement). Collective.
     */
    double
    round_off_force() const override;

    /**
     * @brief Add the derivative of the forces of the last add_forces() to
     * the system matrix (before its compress()).
     */
    void
    add_contact_matrix(const LoadStepSystem<dim>      &system,
                       TrilinosWrappers::SparseMatrix &matrix) const;

    /**
     * @brief After a converged step: store each face's friction traction
     * in the points (scenes with friction) and sum the force on each body.
     * Collective.
     */
    void
    accept(MaterialPoints<dim>       &material_points,
           const LoadStepSystem<dim> &system,
           const NodalVector         &increment) override;

    /** @brief The force of the material on a body, in parts. */
    struct BodyForce
    {
      /** The total force. */
      Tensor<1, dim> total;
      /** Its part normal to the body's surface (the pressures). */
      Tensor<1, dim> normal;
      /** Its part along the surface (friction). */
      Tensor<1, dim> tangential;
      /** Number of probes (faces or Gauss points on them) in contact. */
      unsigned int n_contacts = 0;
      /** Number of them that slip (Coulomb friction at its limit). */
      unsigned int n_slipping = 0;
    };

    /** @brief The force on each body at the last accepted step. */
    const std::vector<BodyForce> &
    body_forces() const
    {
      return forces_on_bodies;
    }

    /** @brief The rigid bodies. */
    const std::vector<RigidBody<dim>> &
    bodies() const
    {
      return rigid_bodies;
    }

    /** @brief One line per rigid body for the start-up report. */
    std::vector<std::string>
    descriptions() const override;

  private:
    /**
     * @brief A face whose normal makes a cosine with the body's normal no
     * larger than this is taken as at right angles to the surface (no
     * share of it, not in contact): round-off of a turned body's frame.
     */
    static constexpr double perpendicular_cosine = 1e-12;

    /** @brief A face of a point's domain near a rigid body, in one
     *  attempt. */
    struct Probe
    {
      /** Index of the point (solver order). */
      unsigned int point;
      /** Index of the rigid body. */
      unsigned int body;
      /** For a body with friction, which of the point's probes: the
       *  body's first slot (friction_slot_base), plus the face (2 axis + 1
       *  if on the + side) times max_face_points(), plus the Gauss point on
       *  the face: its friction traction's place in the point's
       *  properties. numbers::invalid_unsigned_int for a frictionless
       *  body (nothing stored). */
      unsigned int slot;
      /** The face's centre at the start of the step. */
      Point<dim> start_position;
      /** The face as the body's proximity() needs it: its outward normal,
       *  start and half-lengths, in the body's frame. */
      typename RigidBody<dim>::Facing facing;
      /** The face's outward normal (an axis). */
      Tensor<1, dim> face_normal;
      /** The face's area (length in 2D) times the Gauss point's
       *  weight. */
      double area;
      /** Normal and tangential penalty stiffness per area. */
      double stiffness, tangential_stiffness;
      /** The friction traction at the start of the step. */
      Tensor<1, dim> previous_traction;
      /** The face weights over the point's support (they sum to one). */
      std::array<double, PointSupport<dim>::max_nodes> weights;

      /** Of the last evaluation: whether in contact and slipping, the
       *  force on the
       *  material (normal and friction parts), the friction traction
       *  and the derivative of the force with respect to the face's
       *  position. */
      bool active = false, slipping = false;
      /** Of the last evaluation: the piece of the body's contact
       *  (RigidBody::Proximity::piece). */
      unsigned int piece = 0;
      /** Whether the last evaluation changed active, slipping or the
       *  piece. */
      bool           changed = false;
      Tensor<1, dim> normal_force, friction_force, traction;
      Tensor<2, dim> force_derivative;
    };

    /** @brief Call @p visit(index, probe) with a copy of each probe
     *  evaluated where the step starts (the bodies at their start pose, the
     *  faces unmoved); the probes and the poses are left as they are. */
    void
    visit_start_probes(
      const std::function<void(unsigned int, const Probe &)> &visit);

    /** @brief Evaluate @p probe at the face centre @p position. */
    void
    evaluate(Probe &probe, const Point<dim> &position) const;

    /** @brief Subtract @p probe's force on the material (normal and
     *  friction) from @p internal_force at its point's nodes. */
    void
    subtract_probe_force(const Probe               &probe,
                         const LoadStepSystem<dim> &system,
                         NodalVector               &internal_force) const;

    /** @brief The corners of body @p b's own box displaced by @p
     *  displacement and turned by @p rotation. */
    std::vector<Point<dim>>
    moved_corners(const unsigned int    b,
                  const Tensor<1, dim> &displacement,
                  const Tensor<2, dim> &rotation) const;

    /** @brief The tunnelling check of refuse_step(): the material point
     *  deepest inside a body at the end of the step. Collective. */
    StepRefusal
    points_inside(const MaterialPoints<dim> &material_points,
                  const LoadStepSystem<dim> &system,
                  const NodalVector         &increment) const;

    /** 'Rigid contact/Maximum motion per step', in cell sizes (0: no
     *  limit). */
    double maximum_motion = 1.;

    const std::vector<RigidBody<dim>> &rigid_bodies;
    const BackgroundGrid<dim>         &grid;
    /** The name of the points' friction tractions (point_fields()). */
    static constexpr const char *traction_field = "contact_friction_traction";
    /** Whether the points store friction tractions. */
    const bool friction;
    /** max_face_points() and traction_entries() of the bodies. */
    const unsigned int probes_per_face, n_traction_entries;
    /** Each body's first friction slot in a point (its friction tractions
     *  are its own, also where another body touches the same face);
     *  numbers::invalid_unsigned_int for a frictionless body. */
    std::vector<unsigned int> friction_slot_base;
    /** The bodies' force-driven components (body by body). */
    const std::vector<Unknown> body_unknowns;
    /** The bodies' displacement at the attempt's target (on the
     *  force-driven components: the current iterate), at its start, and
     *  the change over the attempt. */
    std::vector<Tensor<1, dim>> displacement, start_displacement,
      displacement_increment;
    /** The bodies' rotation at the attempt's target and at its start,
     *  and the rotation over the attempt (target times start's
     *  transpose). */
    std::vector<Tensor<2, dim>> rotation, start_rotation, rotation_increment;
    /** The bodies' displacement at the last accepted step on the
     *  force-driven components (zero on the others). */
    std::vector<Tensor<1, dim>> accepted_unknowns;
    /** The applied force on each body at the attempt's target. */
    std::vector<Tensor<1, dim>> applied_force;
    /** This process's part of the contact's force on the material, per
     *  body, at the last add_forces(). */
    std::vector<Tensor<1, dim>> force_on_material;
    /** This process's sum of the squares of the probes' force round-off
     *  at the last add_forces(). */
    double round_off_squared = 0.;
    /** Whether the scene's steps are explicit (use_explicit_steps()). */
    bool                   explicit_steps = false;
    std::vector<Probe>     probes;
    std::vector<BodyForce> forces_on_bodies;
  };
} // namespace impm

#endif
