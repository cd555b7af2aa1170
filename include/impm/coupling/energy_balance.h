#ifndef impm_coupling_energy_balance_h
#define impm_coupling_energy_balance_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <impm/coupling/step_energy.h>
#include <impm/coupling/step_measure.h>
#include <impm/io/run_state.h>
#include <impm/points/material_points.h>
#include <impm/points/point_step.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The energy balance of a scene with inertia, kept over the run
   * and checked after every converged step.
   *
   * From the points: the kinetic energy @f$E_k = \sum_p \tfrac12 m_p
   * |v_p|^2@f$, the elastic (strain) energy @f$E_s = \sum_p V_p^0
   * \psi_p@f$ (elastic_energy_density()) and the energy their return
   * maps dissipate, @f$\sum_p V_p^0\, \tau^{n+1} : (\varepsilon^{tr}_e
   * - \varepsilon^{n+1}_e)@f$ (plastic_dissipation_density(): the
   * backward Euler rule's plastic work, zero in an elastic step). The
   * dissipated energy @f$D@f$ is that plus what the damping and the
   * numerical penalties took out. The transfer between points and nodes
   * takes kinetic energy out on its own, @f$T@f$ (transfer_loss): the
   * nodes' kinetic energy at a step's start (lumped or consistent mass)
   * against the points' before it, and at its end against the points'
   * after it. The work from outside @f$W@f$ is that of the loads and the
   * moving faces (LoadStepProblem::work_of_loads_and_faces()) and of the
   * couplings' forces (Coupling::add_step_energy(): springs and dashpots,
   * contacts, a shaken base).
   *
   * The balance @f$E_k + E_s + D + T = E_k^0 + E_s^0 + W@f$ holds for
   * the continuum (T = 0). What the discretisation adds to it is its
   * error: the nodes' stress work against the stored energy's change (the
   * step's size against the strain's curvature: an impact's large
   * increments), the start's acceleration mapped from the points with a
   * lumped mass (not the start's forces on the new grid), the central
   * difference rule's half-step offset, an energy an effect does not
   * account. It is written relative to the run's largest energy so far
   * (the largest of @f$E_k, E_s, |W|, |D|, |T|@f$ and the initial
   * energy) and reported in one line when it exceeds the tolerance the
   * scene names, then again each time it has doubled. The elastic energy
   * is each material's stored energy (elastic_energy_density(); at the
   * start, that of the material's update without motion), Cam-clay's its
   * potential. Energy made from nothing stops the run
   * (unstable_growth()).
   *
   * In explicit steps (staggered) the points' velocities are those of the
   * half steps (the central difference rule's), a half step off the
   * strain energy and the work, which belong to the whole steps: under a
   * constant force the kinetic energy after the n-th step is only
   * (n + 1/2)^2 / (n + 1)^2 of the work. There the balance is checked at
   * each step's start @f$t_n@f$ instead, when the step is accepted: with
   * the kinetic energy of the mean of the points' velocities before and
   * after the step (@f$v^{n-1/2}@f$ and @f$v^{n+1/2}@f$, the rule's
   * velocity at @f$t_n@f$) and the strain energy, work, dissipation and
   * transfer up to @f$t_n@f$ (exact under a constant force; zero at the
   * run's start).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class EnergyBalance
  {
  public:
    /** @brief The entry of the Inertia subsection it reads. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** @brief The balance of a scene (from the Inertia subsection); with
     *  @p staggered (explicit steps) it is checked at each step's start
     *  (see the class's description). */
    EnergyBalance(const ParameterHandler &prm,
                  const MPI_Comm          communicator,
                  const bool              staggered);

    /**
     * @brief The energy at the run's start, from the points' velocity and
     * stress, once (the first attempt of a run that is not resumed).
     * Collective.
     */
    void
    start(const MaterialPoints<dim> &material_points,
          const PointSteps<dim>     &steps);

    /** @brief The step's energy from the loads, the faces and the other
     *  couplings (summed over the processes). */
    void
    take(const StepEnergy &energy);

    /**
     * @brief The converged step: the points' kinetic and elastic energy
     * and stress work from their new velocities @p velocities (by step
     * index, dim per point) and the updates in @p steps (the points still
     * hold the start's stress), with @p local_damping_dissipation, this
     * process's energy the damping took out in the step, and @p
     * local_nodal_kinetic, this process's nodes' kinetic energy at the
     * step's start and end (their difference from the points' is the
     * transfer's share). Reports an error
     * above the tolerance (on standard error, from the first process),
     * naming the time it belongs to (@p start_time, the step's start, in
     * a staggered balance; @p end_time, the step's end, otherwise).
     * Collective.
     */
    void
    accept(const MaterialPoints<dim> &material_points,
           const PointSteps<dim>     &steps,
           const std::vector<double> &velocities,
           const double               local_damping_dissipation,
           const NodalKineticEnergy  &local_nodal_kinetic,
           const double               start_time,
           const double               end_time);

    /** @brief Its columns in steps.csv: the kinetic, elastic and total
     *  energy, the work from outside, the dissipated energy, the relative
     *  error. */
    static std::vector<std::string>
    columns();

    /** @brief Its step measures after the last accepted step. */
    void
    add_measures(std::vector<StepMeasure> &measures) const;

    /** @brief Save its sums into @p state. */
    void
    save(RunState &state) const;

    /** @brief Read what save() stored. */
    void
    load(const RunState &state);

    /** @brief The balance's error relative to the run's largest energy. */
    double
    relative_error() const;

    /**
     * @brief Why the run cannot go on (empty if it can): after the last
     * accepted step the points hold more energy (kinetic, elastic and
     * dissipated; not the transfer's, which is the nodes') than was put in
     * (the initial energy plus the work from outside) by more than 'Energy
     * growth limit' times the most energy put in so far, and by more at
     * each of the last three steps (a start whose work lags its motion
     * falls back, an instability keeps growing). A stable
     * integration only loses energy to its numerical dissipation and the
     * transfer; energy made from nothing is an integration gone unstable,
     * and its answer is wrong. The same on every process.
     */
    std::string
    unstable_growth() const;

  private:
    /** @brief Kinetic energy @p kinetic_energy plus the elastic energy,
     *  the dissipated energy and the transfer's share now, against the
     *  initial energy plus the work. */
    double
    balance_error(const double kinetic_energy) const;

    const double tolerance;
    /** 'Energy growth limit' (0: never stop). */
    const double   growth_limit;
    const MPI_Comm communicator;
    /** Whether the initial energy is known (start() or load()). */
    bool started = false;
    /** The kinetic and elastic energy at the run's start. */
    double initial_kinetic = 0., initial_elastic = 0.;
    /** After the last accepted step. */
    double kinetic = 0., elastic = 0.;
    /** Sums over the run: the points' plastic dissipation, the energy
     *  damping and numerical terms took out, the work from outside. */
    double plastic_dissipation = 0., other_dissipation = 0., external_work = 0.;
    /** The sum over the run of the kinetic energy the transfer between
     *  points and nodes took out: at each step's start, the points' minus
     *  the nodes' (the mapping of the momentum, a projection, only loses),
     *  and at its end the nodes' minus the points' (a FLIP update gains
     *  less than the nodes where the change of velocity varies between
     *  them; a PIC share loses the points' own velocity). */
    double transfer_loss = 0.;
    /** The energy from outside of the step being accepted. */
    StepEnergy step_energy;
    /** The largest energy of the run so far (the error's reference). */
    double largest_energy = 0.;
    /** The relative error last reported (0: none yet). */
    double reported_error = 0.;
    /** The largest energy put in so far: the initial energy plus the work
     *  from outside, at its largest (unstable_growth()'s reference). */
    double largest_input = 0.;
    /** The points' energy above what was put in, in J, at the last
     *  accepted step (at its start when staggered), and its time. */
    double error_energy = 0., error_time = 0.;
    /** error_energy over largest_input at the last accepted step, and at
     *  the two before it (not kept in checkpoints: a resumed run judges
     *  from its third step). */
    double                growth = std::numeric_limits<double>::infinity();
    std::array<double, 2> growth_before{
      {std::numeric_limits<double>::infinity(),
       std::numeric_limits<double>::infinity()}};
    /** Whether the balance is checked at each step's start (explicit). */
    const bool staggered;
    /** Staggered: the relative error at the last accepted step's start. */
    double start_error = 0.;
    /** Staggered: whether the points' velocities are those of a half step
     *  (after the run's first step, or resumed). */
    bool half_step_velocities = false;
  };
} // namespace impm

#endif
