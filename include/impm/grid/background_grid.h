#ifndef impm_grid_background_grid_h
#define impm_grid_background_grid_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_cartesian.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <impm/basis/basis_functions.h>
#include <impm/core/parameters.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /** The distributed vectors of nodal values (full grid numbering). */
  using NodalVector = LinearAlgebra::distributed::Vector<double>;

  /**
   * @brief The background grid: the Cartesian
   * `parallel::distributed::Triangulation`, its Q1 degrees of freedom, the
   * grid-face conditions with their constraints, the prescribed DoFs, and the
   * DoFs whose reactions are summed per face and component.
   *
   * The grid never moves: each load step is solved on it and the material
   * points carry the deformation.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class BackgroundGrid
  {
  public:
    /**
     * @brief Make the triangulation and distribute the DoFs.
     * @param parameters The scene's "Grid" subsection.
     * @param communicator The processes that share the grid.
     * @param checkpoint_file If not empty, the grid saved by save() under
     *   this name is loaded (on any number of processes; the cells are
     *   then balanced by number, and the points' data attached to them
     *   waits for MaterialPoints to unpack it).
     */
    BackgroundGrid(const Parameters::Grid<dim> &parameters,
                   const MPI_Comm               communicator,
                   const std::string           &checkpoint_file = "");

    /**
     * @brief Save the triangulation with the data attached to its cells
     * (collective). @p prepare attaches the data (the points).
     */
    void
    save(const std::string &file_name, const std::function<void()> &prepare);

    /** @brief The weight of a cell in a repartition (see
     *  Triangulation::Signals::weight). */
    using CellWeight = std::function<
      unsigned int(const typename Triangulation<dim>::cell_iterator &,
                   const typename Triangulation<dim>::CellStatus)>;

    /**
     * @brief Add @p weight to every cell's weight in repartition().
     */
    void
    connect_cell_weight(const CellWeight &weight);

    /**
     * @brief Repartition the cells by @p weight alone (added to deal.II's
     * 1000 per cell), while no data is attached to them, and distribute the
     * DoFs anew (collective). Used before the points are seeded, with the
     * number of points each cell will receive, so that every process seeds
     * its share instead of the processes whose cells hold the bodies.
     */
    void
    partition_by(const CellWeight &weight);

    /**
     * @brief Repartition the cells over the processes by their weights and
     * distribute the DoFs, constraints, reaction DoFs and node map anew.
     * @param prepare Called before the cells move (e.g. to pack the
     * particles).
     * @param unpack Called after they have moved.
     */
    void
    repartition(const std::function<void()> &prepare,
                const std::function<void()> &unpack);

    /** @brief The triangulation. */
    const parallel::distributed::Triangulation<dim> &
    get_triangulation() const
    {
      return triangulation;
    }

    /** @brief The DoF handler of the displacement (Q1^dim). */
    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /** @brief The finite element, Q1^dim. */
    const FESystem<dim> &
    get_fe() const
    {
      return fe;
    }

    /** @brief The mapping of the cells: every cell is an axis-aligned box
     *  (a subdivided rectangle refined globally), so the Cartesian mapping,
     *  whose inverse (a point's place in its cell, asked for every point
     *  each time the points are sorted into cells) is a scaling, not a
     *  Newton iteration as MappingQ1's. */
    const MappingCartesian<dim> &
    get_mapping() const
    {
      return mapping;
    }

    /** @brief The grid's structure: corners, cell sizes, node numbering. */
    const CartesianGrid<dim> &
    cartesian() const
    {
      return grid;
    }

    /** @brief The constraints of the grid-face conditions. */
    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }

    /** @brief The displacement component of the local DoF @p local. */
    unsigned int
    component(const unsigned int local) const
    {
      return component_of_local_dof[local];
    }

    /** @brief The position of the grid node of the local DoF @p local. */
    const Point<dim> &
    position(const unsigned int local) const
    {
      return position_of_local_dof[local];
    }

    /** @brief The DoFs this process owns. */
    const IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }

    /** @brief Number of DoFs this process owns (the first local indices). */
    unsigned int
    n_locally_owned_dofs() const
    {
      return owned_dofs.n_elements();
    }

    /** @brief Number of local DoFs: owned, then ghosts. */
    unsigned int
    n_local_dofs() const;

    /**
     * @brief The local index (owned, then ghosts) of a locally relevant DoF.
     */
    unsigned int
    local_index(const types::global_dof_index dof) const
    {
      return partitioner->global_to_local(dof);
    }

    /**
     * @brief Size @p vector for the owned and ghost DoFs (zeroed).
     */
    void
    reinit_vector(NodalVector &vector) const;

    /**
     * @brief The local indices of the DoFs of grid node @p node (its index
     * in the Cartesian numbering), or nullptr if the node is outside this
     * process's ghost layer.
     */
    const std::array<unsigned int, dim> *
    node_dofs(const std::uint64_t node) const
    {
      const auto found = dofs_of_node.find(node);
      return found == dofs_of_node.end() ? nullptr : &found->second;
    }

    /**
     * @brief Set the prescribed DoFs of @p increment (ghosts included) to
     * their share of a load increment @p load_increment.
     */
    void
    apply_prescribed_increment(const double load_increment,
                               NodalVector &increment) const;

    /**
     * @brief The prescribed DoFs' share of a load increment
     * @p load_increment on the local DoFs (owned, then ghosts; zero at
     * every other DoF), as apply_prescribed_increment() sets them.
     */
    std::vector<double>
    local_prescribed_increment(const double load_increment) const;

    /**
     * @brief The faces (boundary ids) with a non-zero prescribed
     * displacement none of whose prescribed DoFs a point's support reaches
     * (@p touched: local DoFs, as LoadStepSystem::touched_dofs()): such a
     * face moves no material. Empty in a scene without prescribed faces
     * (then nothing is communicated). Collective.
     */
    std::vector<unsigned int>
    prescribed_faces_without_material(const std::vector<bool> &touched) const;

    /** @brief Whether any process has a DoF a face's non-zero prescribed
     *  displacement moves. */
    bool
    moves_faces() const
    {
      return any_prescribed_dof;
    }

    /**
     * @brief The (face * dim + component) pairs that carry reactions, in
     * the order of the face numbering.
     */
    const std::vector<unsigned int> &
    reaction_columns() const
    {
      return columns_with_reactions;
    }

    /** @brief Reactions, summed per face and component. */
    struct Reactions
    {
      /** By face * dim + component (2 dim * dim entries). */
      std::vector<double> by_column;
      /**
       * |sum of reactions + external force| / |external force|, or a
       * negative number when there is no load or no reaction to balance it.
       */
      double imbalance = -1.;
    };

    /**
     * @brief The reactions R = f_int - f_ext on the constrained DoFs (the
     * supports' force on the material) and their balance with the load and
     * @p rigid_body_force, the force of the material on the rigid bodies,
     * which carry load too. Collective.
     */
    Reactions
    compute_reactions(
      const NodalVector    &internal_force,
      const NodalVector    &external_force,
      const Tensor<1, dim> &rigid_body_force = Tensor<1, dim>()) const;

    /**
     * @brief A one-line description of each face condition the scene sets.
     */
    std::vector<std::string>
    face_descriptions() const;

  private:
    /** Make the triangulation from a coarse mesh refined globally. */
    void
    make_triangulation(const std::string &checkpoint_file);
    /** Distribute the DoFs and build everything that depends on them. */
    void
    distribute_dofs();

    /** Constraints, prescribed and reaction DoFs of the face conditions. */
    void
    apply_face_conditions();

    /** The map from grid nodes to their DoFs. */
    void
    map_nodes_to_dofs();

    const Parameters::Grid<dim>              &parameters;
    const MPI_Comm                            communicator;
    parallel::distributed::Triangulation<dim> triangulation;
    const MappingCartesian<dim>               mapping;
    const FESystem<dim>                       fe;
    DoFHandler<dim>                           dof_handler;
    CartesianGrid<dim>                        grid;
    IndexSet                                  owned_dofs;
    IndexSet                                  relevant_dofs;
    /** Owned and ghost DoFs, for local indices. */
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
    AffineConstraints<double>                          constraints;

    /** The component of each local DoF. */
    std::vector<unsigned char> component_of_local_dof;
    /** The position of each local DoF's grid node. */
    std::vector<Point<dim>> position_of_local_dof;
    /** Local indices (owned and ghost) of each grid node's DoFs. */
    std::unordered_map<std::uint64_t, std::array<unsigned int, dim>>
      dofs_of_node;
    /** Prescribed DoFs (local index) and their displacement at full load. */
    std::vector<std::pair<unsigned int, double>> prescribed_dofs;
    /** The face (boundary id) of each of prescribed_dofs. */
    std::vector<unsigned int> prescribed_dof_faces;
    /** Whether any process has a prescribed DoF (set with them). */
    bool any_prescribed_dof = false;
    /** Owned constrained DoFs (local index) and their face * dim + comp. */
    std::vector<std::pair<unsigned int, unsigned int>> reaction_dofs;
    /** The (face * dim + component) pairs that carry reactions. */
    std::vector<unsigned int> columns_with_reactions;
  };
} // namespace impm

#endif
