#ifndef impm_points_material_points_h
#define impm_points_material_points_h

#include <deal.II/base/mpi.h>

#include <deal.II/particles/particle_handler.h>

#include <impm/core/body.h>
#include <impm/core/effects.h>
#include <impm/core/point_properties.h>
#include <impm/grid/background_grid.h>
#include <impm/io/run_state.h>
#include <impm/points/point_step.h>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Global measures of the material points' state, the same on every
   * process.
   */
  template <int dim>
  struct PointMeasures
  {
    /** Sum of the points' masses. */
    double total_mass = 0.;
    /** Largest vertical (last axis) Cauchy stress, tension positive. */
    double max_tensile_vertical_stress = 0.;
    /** Bounding box of the initial positions: its lower corner. */
    Point<dim> initial_min;
    /** Bounding box of the initial positions: its upper corner. */
    Point<dim> initial_max;
    /** Bounding box of the current positions: its lower corner. */
    Point<dim> current_min;
    /** Bounding box of the current positions: its upper corner. */
    Point<dim> current_max;
  };

  /**
   * @brief The material points: seeded in the bodies, stored in deal.II's
   * particle handler with the properties of PointProperties and PointLayout
   * (laid out from the state the materials and couplings declare),
   * moved with the grid's displacement at the end of each load step and
   * re-sorted into cells and processes.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class MaterialPoints
  {
  public:
    /**
     * @brief Fill the bodies with points on the grid's cells.
     * @param bodies The scene's bodies (shapes, points per cell, density,
     *   material).
     * @param grid The background grid. Before seeding on several
     *   processes its cells are repartitioned by the points each will
     *   receive (BackgroundGrid::partition_by).
     * @param communicator The processes that share the points.
     * @param gravity_from_the_start The acceleration of gravity acting in
     *   full from the first load step (zero if none): the bodies with a
     *   geostatic start take their stress from it.
     * @param checkpoint_state If not null, instead of filling the bodies,
     *   take the points that a checkpoint attached to the grid (which
     *   BackgroundGrid has loaded) and their mass at creation from this
     *   state.
     * @param coupling_fields The point fields the scene's couplings declare
     *   (Coupling::point_fields()); the bodies' materials declare theirs
     *   (Material::state_fields()).
     */
    MaterialPoints(const std::vector<Body<dim>> &bodies,
                   BackgroundGrid<dim>          &grid,
                   const MPI_Comm                communicator,
                   const Tensor<1, dim>         &gravity_from_the_start,
                   const RunState               *checkpoint_state = nullptr,
                   const PointFields            &coupling_fields  = {});

    /**
     * @brief Store the values of the coupling field @p name (declared by a
     * coupling) of every local point: @p values holds the field's entries
     * of each point by the index of its step in @p point_steps.
     */
    void
    set_coupling_field(const std::string         &name,
                       const PointSteps<dim>     &point_steps,
                       const std::vector<double> &values);

    /**
     * @brief Set the coupling field @p name of every local point to what
     * @p value writes into its entries, given the point's state (initial
     * values at the start of a run).
     */
    void
    initialize_coupling_field(
      const std::string                                    &name,
      const std::function<void(const PointState<dim> &,
                               const ArrayView<double> &)> &value);

    /**
     * @brief Attach the points to the grid's cells for a checkpoint (call
     * before BackgroundGrid::save()).
     */
    void
    prepare_for_checkpoint();

    /**
     * @brief Save the points' replicated state (their mass at creation,
     * their number and their layout).
     */
    void
    save(RunState &state) const;

    /** @brief The particle handler that holds the points. */
    const Particles::ParticleHandler<dim> &
    particles() const
    {
      return particle_handler;
    }

    /** @brief The optional properties of this scene's points. */
    const PointLayout &
    layout() const
    {
      return property_layout;
    }

    /** @brief The processes that share the points. */
    MPI_Comm
    get_communicator() const
    {
      return communicator;
    }

    /** @brief Number of points on all processes. */
    types::particle_index
    n_global_points() const
    {
      return particle_handler.n_global_particles();
    }

    /** @brief Number of points on this process. */
    unsigned int
    n_local_points() const
    {
      return particle_handler.n_locally_owned_particles();
    }

    /** @brief The total mass when the points were created. */
    double
    initial_mass() const
    {
      return mass_at_creation;
    }

    /** @brief The body index (0-based) of a point's properties. */
    unsigned int
    body_of(const ArrayView<const double> &properties) const
    {
      return property_layout.body_index() == PointLayout::absent ?
               0 :
               static_cast<unsigned int>(
                 properties[property_layout.body_index()]);
    }

    /** @brief The material of a point's properties (of its body). */
    const Material &
    material_of(const ArrayView<const double> &properties) const
    {
      return *bodies[body_of(properties)].material;
    }

    /**
     * @brief The state variables of a point's material (in the order of
     * Material::state_fields()) within its @p properties.
     */
    ArrayView<const double>
    material_state(const ArrayView<const double> &properties) const
    {
      return {properties.data() + property_layout.material_state_first(),
              property_layout.n_material_state(body_of(properties))};
    }

    /** @brief The same, to write. */
    ArrayView<double>
    material_state(const ArrayView<double> &properties) const
    {
      return {properties.data() + property_layout.material_state_first(),
              property_layout.n_material_state(body_of(properties))};
    }

    /**
     * @brief What force effects may know of this process's points, in
     * iteration order.
     */
    std::vector<MaterialPointInfo<dim>>
    infos() const;

    /**
     * @brief The same, each point at the index of its step in @p
     * point_steps.
     */
    std::vector<MaterialPointInfo<dim>>
    infos(const PointSteps<dim> &point_steps) const;

    /**
     * @brief The volume fraction of each locally owned cell that its points
     * fill in the current configuration, by active cell index (zero for
     * other cells).
     */
    std::vector<double>
    cell_fill_fractions(const BackgroundGrid<dim> &grid) const;

    /**
     * @brief End a converged load step: move each point with the grid's
     * displacement increment, compose its deformation gradient, store the
     * new stress and its material's state (Material::store_state()) and
     * stretch its GIMP domain (if @p update_domains). The points are then
     * in the cells of the step's start: sort_into_cells() follows. With
     * @p move_points false a point keeps its position (everything else is
     * updated).
     *
     * A point that leaves the grid (or becomes non-finite) stops the run
     * with an error naming it, the step, its positions and the grid.
     *
     * @param point_steps The step's per-point data.
     * @param increment The converged displacement increment (ghosted).
     * @param update_domains Whether GIMP domains follow the stretch.
     * @param move_points Whether the points move with the increment.
     * @param load_step The step's number, for messages.
     */
    void
    advance(const PointSteps<dim> &point_steps,
            const NodalVector     &increment,
            const bool             update_domains,
            const bool             move_points,
            const unsigned int     load_step);

    /**
     * @brief Re-sort the points into the cells and processes of their new
     * positions (after advance()); stops the run if a point is lost. When
     * every point is still inside its cell (all_inside_their_cells()),
     * nothing is done: the points, their order and their cells are those
     * deal.II's sort would leave. deal.II's sorting makes buffers of the
     * size of the points' data for a moment: the solver frees the step's
     * per-point data before (0.24 GB per process at 10^6 points on two
     * processes). Collective.
     *
     * @param load_step The step's number, for messages.
     */
    void
    sort_into_cells(const unsigned int load_step);

    /** @brief Global measures of the current state. Collective. */
    PointMeasures<dim>
    measure() const;

    /**
     * @brief The most points a process holds over the mean per process: 1
     * when the points are balanced (collective).
     */
    double
    imbalance() const;

    /**
     * @brief A cell's weight in a repartition: its points, each weighing
     * as much as the cell itself (deal.II counts 1000 for a cell), since the
     * stress update and the assembly, per point, dominate the work.
     */
    unsigned int
    cell_weight(const typename Triangulation<dim>::cell_iterator &cell,
                const typename Triangulation<dim>::CellStatus     status) const;

    /** @brief Pack the points before the cells move between processes. */
    void
    prepare_for_repartition();

    /** @brief Unpack the points after the cells have moved. */
    void
    unpack_after_repartition();

  private:
    /**
     * @brief The initial stress of a point of @p body at @p position into
     * @p properties: zero, or the body's geostatic stress under gravity @p
     * g with the elastic strain its material gives it, and its material's
     * state at that stress; the first geostatic stress outside the yield
     * surface, or that the material's elastic law cannot reach (Modified
     * Cam-clay at p' <= 0), is described in @p outside_yield_surface, which
     * the seeding reports on every process.
     */
    void
    set_initial_stress(const Body<dim>     &body,
                       const Point<dim>    &position,
                       const double         g,
                       std::vector<double> &properties,
                       std::string         &outside_yield_surface) const;

    /**
     * @brief Refuse a body that holds no point (one line naming it), from
     * each body's points on this process, @p n_local. Collective.
     */
    void
    check_bodies_hold_points(const std::vector<unsigned int> &n_local) const;

    /** Weight of a point in a repartition: as much as a cell. */
    static constexpr unsigned int point_weight = 1000;

    /**
     * The lower corner and the structured index (the same on any number
     * of processes) of a cell of the Cartesian grid.
     */
    std::pair<Point<dim>, std::uint64_t>
    cell_origin(const typename Triangulation<dim>::cell_iterator &cell) const;

    /**
     * The position of lattice point @p q of a body with @p n points per
     * cell direction in the cell whose lower corner is @p cell_lower, and
     * its coordinates in the unit cell (@p reference).
     */
    Point<dim>
    lattice_position(const Point<dim>  &cell_lower,
                     const unsigned int n,
                     const unsigned int q,
                     Point<dim>        &reference) const;

    /** Whether every point on every process lies inside its cell, clear
     *  of the cell's faces (a position that is not finite is not).
     *  Collective. */
    bool
    all_inside_their_cells() const;

    /** The number of points seed() puts into @p cell (all bodies). */
    unsigned int
    n_seeded_points(
      const typename Triangulation<dim>::cell_iterator &cell) const;

    /** Seed the points of every body in the locally owned cells. */
    void
    seed(const BackgroundGrid<dim> &grid,
         const Tensor<1, dim>      &gravity_from_the_start);

    const std::vector<Body<dim>>   &bodies;
    const CartesianGrid<dim>       &grid;
    const MPI_Comm                  communicator;
    PointLayout                     property_layout;
    Particles::ParticleHandler<dim> particle_handler;
    double                          mass_at_creation = 0.;
  };
} // namespace impm

#endif
