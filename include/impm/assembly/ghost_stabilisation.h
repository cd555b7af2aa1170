#ifndef impm_assembly_ghost_stabilisation_h
#define impm_assembly_ghost_stabilisation_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <impm/core/parameters.h>
#include <impm/coupling/coupling.h>
#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/system/dense_block_adder.h>

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
   * creates none of this.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class GhostStabilisation : public Coupling<dim>
  {
  public:
    /** @brief A face penalty, fixed during a load step. */
    struct FacePenalty
    {
      /** Local indices (nodal vectors) of both cells' DoFs, ascending,
       *  each once. */
      std::vector<unsigned int> dofs;
      /** The vector component of each of those DoFs. */
      std::vector<unsigned char> components;
      /** The penalty matrix on those DoFs (zero between components). */
      FullMatrix<double> matrix;
    };

    /**
     * @brief Constructor.
     * @param parameters The scene's "Ghost stabilisation" subsection.
     * @param grid The background grid.
     * @param bodies The bodies: their stiffest material scales the penalty.
     */
    GhostStabilisation(const Parameters::Stabilisation &parameters,
                       const BackgroundGrid<dim>       &grid,
                       const std::vector<Body<dim>>    &bodies);

    /** @brief The coupling of a scene (Ghost stabilisation/Enabled). */
    explicit GhostStabilisation(const CouplingInputs<dim> &inputs);

    /** @brief Choose the step's faces (choose_faces()); adds no rows. */
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

    /** @brief The penalty forces (add_penalty_forces()). */
    void
    add_forces(const LoadStepSystem<dim> &system,
               const NodalVector         &increment,
               NodalVector               &internal_force) override;

    /** @brief The penalty matrices (add_penalty_matrix()): constant over
     *  the step. */
    bool
    add_constant_matrix(const LoadStepSystem<dim>      &system,
                        TrilinosWrappers::SparseMatrix &matrix) override;

    /** @brief description(). */
    std::vector<std::string>
    descriptions() const override;

    /**
     * @brief Choose this step's faces: between two locally owned or ghost
     * cells whose DoFs are all touched by material, where either cell is
     * filled to less than the threshold. Collective.
     * @param material_points The points at the start of the step.
     * @param touched For each local DoF, whether a point's support has it.
     */
    void
    choose_faces(const MaterialPoints<dim> &material_points,
                 const std::vector<bool>   &touched);

    /** @brief This step's face penalties. */
    const std::vector<FacePenalty> &
    faces() const
    {
      return face_penalties;
    }

    /**
     * @brief Add the penalty forces of @p increment to @p internal_force
     * (before its compress()).
     */
    void
    add_penalty_forces(const NodalVector &increment,
                       NodalVector       &internal_force) const;

    /**
     * @brief Add the penalty matrices to the system matrix (before its
     * compress()).
     */
    void
    add_penalty_matrix(const LoadStepSystem<dim>      &system,
                       TrilinosWrappers::SparseMatrix &matrix) const;

    /** @brief A one-line description for the start-up report. */
    std::string
    description() const;

  private:
    const Parameters::Stabilisation parameters;
    const BackgroundGrid<dim>      &grid;
    /** The largest Young's modulus of the bodies. */
    double                   modulus = 0.;
    std::vector<FacePenalty> face_penalties;
    /** Adds the faces' blocks to the matrix. */
    mutable DenseBlockAdder block_adder;

    /**
     * @brief The penalty of a face from the matrix @p cell_matrix on the
     * two cells' DoFs @p cell_dofs (those of the shared nodes twice), of
     * vector components @p cell_components: each DoF once, its rows and
     * columns summed.
     */
    static FacePenalty
    merge_shared_dofs(const std::vector<unsigned int>  &cell_dofs,
                      const std::vector<unsigned char> &cell_components,
                      const FullMatrix<double>         &cell_matrix);
  };
} // namespace impm

#endif
