#ifndef impm_system_face_jump_penalty_h
#define impm_system_face_jump_penalty_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/system/dense_block_adder.h>
#include <impm/system/load_step_system.h>

#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief A penalty on the jump of the normal gradient of a nodal field
   * across the interior faces of cells that material barely fills
   * (Burman's ghost penalty), as a set of face matrices chosen once per
   * load step:
   * @f[ G_{IJ} = \gamma\, C\, h^p \sum_F \int_F [\![\partial_n
   * N_I]\!]\,[\![\partial_n N_J]\!]\, dA, @f]
   * component by component, where h is the cell's extent normal to the
   * face, C a coefficient of the material and p a power of h that give
   * the penalty the units of the operator it stabilises: C = E, p = 1 for
   * the stiffness (GhostStabilisation), C = rho, p = 3 for the mass
   * (Inertia's 'Mass ghost penalty'). In axisymmetry the face is a ring
   * (its length times 2 pi r at its centre). The penalty of a linear field
   * is zero, so it does not act on rigid motions or on uniform strains.
   *
   * It knows nothing of what the field is: its owner applies it to a
   * field (add_forces()) and adds it to a matrix (add_matrix()) with the
   * factor its statement needs.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class FaceJumpPenalty
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
     * @param grid The background grid.
     * @param scale The dimensionless penalty scale gamma.
     * @param coefficient The material coefficient C.
     * @param h_power The power p of the cell size.
     * @param fill_threshold Cells whose points fill less than this
     *   fraction of them are stabilised.
     */
    FaceJumpPenalty(const BackgroundGrid<dim> &grid,
                    const double               scale,
                    const double               coefficient,
                    const unsigned int         h_power,
                    const double               fill_threshold);

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
     * @brief Each face's DoFs in the system (sorted system indices), one
     * dense block per face, appended to @p blocks for the sparsity pattern.
     */
    void
    add_blocks(const LoadStepSystem<dim>                         &system,
               std::vector<std::vector<types::global_dof_index>> &blocks) const;

    /**
     * @brief Add @p factor times the penalty of the nodal field @p values
     * (ghosted) to @p force (before its compress()).
     */
    void
    add_forces(const NodalVector &values,
               const double       factor,
               NodalVector       &force) const;

    /**
     * @brief Add @p factor times the penalty matrices to the system matrix
     * (before its compress()); rows and columns outside the system are
     * left out.
     */
    void
    add_matrix(const LoadStepSystem<dim>      &system,
               TrilinosWrappers::SparseMatrix &matrix,
               const double                    factor) const;

  private:
    const BackgroundGrid<dim> &grid;
    /** gamma C, the penalty's factor before the cell size. */
    const double             coefficient;
    const unsigned int       h_power;
    const double             fill_threshold;
    std::vector<FacePenalty> face_penalties;
    /** Adds the faces' blocks to the matrix. */
    mutable DenseBlockAdder block_adder;
    /** A face's matrix times a factor other than 1 (add_matrix()). */
    mutable FullMatrix<double> scaled_matrix;

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
