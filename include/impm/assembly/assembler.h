#ifndef impm_assembly_assembler_h
#define impm_assembly_assembler_h

#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <impm/core/effects.h>
#include <impm/core/parameters.h>
#include <impm/coupling/coupling.h>
#include <impm/points/material_points.h>
#include <impm/system/load_step_system.h>

#include <memory>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The assembly of one Newton iterate: the stress update of every
   * point, the external force of the scene's force effects, and the
   * internal force and the stiffness matrix of the chosen statement of
   * equilibrium.
   *
   * The statement (the per-point integrands of
   * mechanics/equilibrium_forms.h) is chosen once, when the assembler is
   * created: each is its own implementation of the two virtual functions,
   * with no test of the formulation inside the loops. A coupling that sets
   * the points' volumes (Coupling::sets_point_volumes(), F-bar) takes over
   * the stress update and changes each point's tangent; the other
   * couplings add their own terms beside the points' (LoadStepProblem).
   * As PointGradients it gives the couplings the gradients it assembles
   * with.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class Assembler : public PointGradients<dim>
  {
  public:
    /**
     * @brief Create the assembler of a statement of equilibrium.
     * @param formulation Previously converged or updated Lagrangian.
     * @param material_points The points.
     * @param system The load step's system (its point steps are updated).
     * @param force_effects The scene's loads.
     * @param volume_coupling The coupling that sets the points' volumes
     *   (Couplings::volume_coupling()), or nullptr (none).
     * @param communicator The processes of the run.
     */
    static std::unique_ptr<Assembler<dim>>
    create(const Parameters::Formulation formulation,
           const MaterialPoints<dim>    &material_points,
           LoadStepSystem<dim>          &system,
           const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects,
           Coupling<dim> *volume_coupling,
           const MPI_Comm communicator);

    /** @brief Destructor. */
    virtual ~Assembler() override = default;

    /**
     * @brief The stress update: each point's deformation gradient increment
     * from @p increment and its material's return map (with a coupling that
     * sets the points' volumes, through it). Returns false on
     * every process if any point's increment is inverted or not finite.
     * Collective.
     */
    bool
    update_stresses(const NodalVector &increment);

    /**
     * @brief The stresses of the zero increment without a return map: each
     * point's step holds its start-of-step Kirchhoff stress and b^e, with
     * the unit deformation increment (what update_stresses() of a zero
     * increment gives, at a fraction of its cost: the residual of a step's
     * start). The tangent of this state is not set.
     */
    void
    set_start_stresses();

    /**
     * @brief The external force of the force effects at @p load_factor,
     * spread to the nodes with the points' weights (compressed).
     * Collective.
     */
    void
    assemble_external_force(const double load_factor,
                            NodalVector &external_force) const;

    /**
     * @brief Whether the external force changes with the load factor (some
     * force effect's ForceEffect::scales_with_load_factor()); if not, one
     * assembly serves a step's start and its end.
     */
    bool
    external_force_scales_with_load_factor() const
    {
      for (const auto &effect : force_effects)
        if (effect->scales_with_load_factor())
          return true;
      return false;
    }

    /**
     * @brief Add the points' internal force of the last stress update to
     * @p internal_force (not compressed).
     */
    virtual void
    add_internal_force(NodalVector &internal_force) = 0;

    /**
     * @brief Add the points' consistent tangent of the last stress update
     * to @p matrix (not compressed), one dense block per assembly group.
     */
    virtual void
    add_stiffness(TrilinosWrappers::SparseMatrix &matrix) const = 0;

  protected:
    /** @brief Constructor (see create()). */
    Assembler(
      const MaterialPoints<dim>                            &material_points,
      LoadStepSystem<dim>                                  &system,
      const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects,
      Coupling<dim>                                        *volume_coupling,
      const MPI_Comm                                        communicator);

    /** The points. */
    const MaterialPoints<dim> &material_points;
    /** The system of the load step. */
    LoadStepSystem<dim> &system;
    /** The loads. */
    const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects;
    /** The coupling that sets the points' volumes, or nullptr. */
    Coupling<dim> *volume_coupling;
    /** The processes. */
    const MPI_Comm communicator;
  };
} // namespace impm

#endif
