#ifndef impm_coupling_step_energy_h
#define impm_coupling_step_energy_h

namespace impm
{
  /**
   * @brief The energy one converged step moved into or out of the material,
   * as the loads, the faces and the couplings account it (J; per m of
   * thickness in plane strain). A scene that keeps an energy balance
   * (inertia, Coupling::keeps_energy_balance()) sums it over the run; the
   * kinetic and elastic energy and the points' stress work are the
   * keeper's own.
   */
  struct StepEnergy
  {
    /** The work done on the material from outside it: the loads, the moving
     *  faces' reactions, springs and dashpots, contacts, a shaken base. */
    double external_work = 0.;
    /** The energy a numerical term took out of the material (a ghost
     *  penalty), which no physical agent stores. */
    double dissipated = 0.;
  };

  /**
   * @brief The nodes' kinetic energy at a step's start and end, @f$\tfrac12
   * \sum_I M_I |v_I|^2@f$ with the lumped mass, on this process's owned
   * DoFs: against the points' (StepEnergy's keeper) it measures what the
   * transfer between points and nodes takes out or adds.
   */
  struct NodalKineticEnergy
  {
    /** From the start's velocity the points' momentum gives. */
    double start = 0.;
    /** From the nodes' new velocity. */
    double end = 0.;
  };
} // namespace impm

#endif
