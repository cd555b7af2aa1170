#ifndef impm_core_scene_checks_h
#define impm_core_scene_checks_h

#include <deal.II/base/mpi.h>

#include <impm/core/load_path.h>
#include <impm/core/parameters.h>

#include <functional>

namespace impm
{
  /**
   * @brief The checks of a scene that no single entry can make, done when
   * the scene has been read and before anything is built. Each failure is
   * an InputError naming the entries involved.
   *
   * Checked here: every body lies inside the grid and has a density above
   * 0; every rigid body moved by a prescribed displacement reaches the grid
   * at its start or its end; no grid node is both held at 0 and moved by
   * the face conditions of two adjacent faces; every region of a face
   * condition holds a node of its face; every displacement component is
   * held by some face condition near the material or a coupling (else the
   * system is singular: check_supports(), once the couplings exist); the memory
   * the scene needs fits in the memory of the machines the run has. Checked
   * where the information is: overlapping bodies and bodies without points when
   * the points are seeded (MaterialPoints), polygons when they are read (Body),
   * loads off the material when the effects start (ForceEffect::initialize).
   */
  namespace SceneChecks
  {
    /**
     * @brief Run the checks on @p parameters (collectively on the
     * processes of @p communicator, which share the memory check).
     */
    template <int dim>
    void
    check(const Parameters::All<dim> &parameters, const MPI_Comm communicator);

    /**
     * @brief Check that every displacement component is held: by a face
     * condition near the material, or by what @p held_elsewhere says holds
     * it (the scene's couplings: Coupling::holds_material()).
     */
    template <int dim>
    void
    check_supports(const Parameters::All<dim>              &parameters,
                   const std::function<bool(unsigned int)> &held_elsewhere);

    /**
     * @brief Refuse a load factor of @p time that is not 0 at t = 0 when
     * the scene prescribes a face's displacement or a rigid body's motion:
     * those start from the scene's initial state and follow the factor's
     * change, so its value at t = 0 would be lost without a word.
     */
    template <int dim>
    void
    check_motion_start(const Parameters::All<dim> &parameters,
                       const Parameters::Time     &time);

  } // namespace SceneChecks
} // namespace impm

#endif
