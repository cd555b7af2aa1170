#ifndef impm_assembly_ghost_stabilisation_h
#define impm_assembly_ghost_stabilisation_h

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <impm/core/parameters.h>
#include <impm/coupling/coupling.h>
#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/system/face_jump_penalty.h>

#include <string>
#include <vector>

namespace impm
{
  namespace Parameters
  {
    /**
     * @brief Ghost stabilisation: a penalty on the jump of the normal
     * gradient of the displacement increment across the faces of cells that
     * material barely fills (Burman's ghost penalty, as used for implicit MPM
     * by Coombs).
     */
    struct Stabilisation
    {
      /** Whether the penalty is applied. */
      bool enabled;
      /** Dimensionless penalty scale gamma (penalty = gamma E h). */
      double penalty_scale;
      /** Cells filled to less than this volume fraction are stabilised. */
      double fill_threshold;

      /** @brief Declare the entries in the current subsection ("Ghost
       *  stabilisation", entered by Couplings::declare_parameters()). */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them from the current subsection. */
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters

  using namespace dealii;

  /**
   * @brief Ghost stabilisation: a penalty on the jump of the normal
   * gradient of the displacement increment across the interior faces of
   * cells that material barely fills (Burman's ghost penalty, as used for
   * implicit MPM by Coombs), so that a node fed only by the edge of a
   * point's domain cannot make the system singular.
   *
   * The faces and their penalty matrices are chosen once per load step;
   * the penalty acts on the displacement increment, so a converged step is
   * in equilibrium with it. A coupling (the penalty's matrix is the
   * constant part of the load step's matrix); a scene that switches it off
   * creates none of this. Explicit steps solve no system and move the
   * points by the step's start forces alone: there the penalty chooses no
   * faces and adds no force (use_explicit_steps()), and the start-up
   * report says so.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class GhostStabilisation : public Coupling<dim>
  {
  public:
    /**
     * @brief Constructor.
     * @param parameters The scene's "Ghost stabilisation" subsection.
     * @param grid The background grid.
     * @param bodies The bodies: their stiffest material scales the penalty
     *   (gamma E h).
     */
    GhostStabilisation(const Parameters::Stabilisation &parameters,
                       const BackgroundGrid<dim>       &grid,
                       const std::vector<Body<dim>>    &bodies);

    /** @brief The coupling of a scene (Ghost stabilisation/Enabled). */
    explicit GhostStabilisation(const CouplingInputs<dim> &inputs);

    /** @brief Choose the step's faces (FaceJumpPenalty::choose_faces());
     *  adds no rows. */
    unsigned int
    prepare(const MaterialPoints<dim> &material_points,
            const LoadStepSystem<dim> &system,
            const std::vector<bool>   &touched) override;

    /** @brief The faces' DoFs in the system as dense blocks. */
    void
    setup(const MaterialPoints<dim>                         &material_points,
          const LoadStepSystem<dim>                         &system,
          const CouplingRows                                &rows,
          std::vector<std::vector<types::global_dof_index>> &blocks) override;

    /** @brief The penalty forces of the increment. */
    void
    add_forces(const LoadStepSystem<dim> &system,
               const NodalVector         &increment,
               NodalVector               &internal_force) override;

    /** @brief The energy the penalty took out of the converged step with
     *  increment @p increment: half its forces times the increment (they
     *  grow with the increment's jumps from zero in every step, as a
     *  spring charged and let go). Collective. */
    void
    add_step_energy(const LoadStepSystem<dim> &system,
                    const NodalVector         &increment,
                    StepEnergy                &energy) override;

    /** @brief The penalty matrices: constant over the step. */
    bool
    add_constant_matrix(const LoadStepSystem<dim>      &system,
                        TrilinosWrappers::SparseMatrix &matrix) override;

    /** @brief description(). */
    std::vector<std::string>
    descriptions() const override;

    /** @brief This step's face penalties. */
    const std::vector<typename FaceJumpPenalty<dim>::FacePenalty> &
    faces() const
    {
      return penalty.faces();
    }

    /** @brief Explicit steps: the penalty steps aside (it conditions the
     *  system an implicit step solves; an explicit step solves none, and a
     *  penalty force on its end would only shift the reactions). */
    void
    use_explicit_steps(double surface_stiffness) override;

    /** @brief A one-line description for the start-up report. */
    std::string
    description() const;

  private:
    const Parameters::Stabilisation parameters;
    /** Whether the steps are explicit: prepare() then chooses no faces,
     *  so the penalty adds no blocks, forces or matrix. */
    bool explicit_steps = false;
    /** The faces and their matrices (gamma E h). */
    FaceJumpPenalty<dim> penalty;
  };
} // namespace impm

#endif
