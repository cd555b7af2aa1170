#ifndef impm_core_parameters_h
#define impm_core_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <impm/basis/basis_functions.h>
#include <impm/core/body.h>
#include <impm/core/rigid_body.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The parameters of a scene, one struct per subsection of the
   * `.prm` file, each with its `declare_parameters` and `parse_parameters`.
   */
  namespace Parameters
  {
    /**
     * @brief Parse a comma-separated list of @p n numbers of entry @p entry
     * in the current subsection (named @p section in messages); a wrong
     * count is an error that names the entry, its value and the count
     * expected.
     */
    std::vector<double>
    get_vector(const ParameterHandler &prm,
               const std::string      &section,
               const std::string      &entry,
               const unsigned int      n);

    /**
     * @brief As get_vector(), but an empty entry is allowed too (it returns
     * an empty list): for optional corners and extents.
     */
    std::vector<double>
    get_optional_vector(const ParameterHandler &prm,
                        const std::string      &section,
                        const std::string      &entry,
                        const unsigned int      n);

    /**
     * @brief Parse entry @p entry of the current subsection as a list of
     * points `x, y; x, y; ...`, each with @p n coordinates; a wrong count is
     * an error naming the entry (as `section/entry`) and its value.
     */
    std::vector<std::vector<double>>
    get_point_list(const ParameterHandler &prm,
                   const std::string      &section,
                   const std::string      &entry,
                   const unsigned int      n);

    /**
     * @brief Error for an entry whose value is out of its allowed range:
     * throws std::invalid_argument with one line naming the entry, the value
     * and what is allowed.
     */
    [[noreturn]] void
    bad_value(const std::string &entry,
              const std::string &value,
              const std::string &allowed);

    /** @brief The displacement condition on a grid face. */
    enum class FaceCondition
    {
      /** Free. */
      none,
      /** Normal component zero. */
      roller,
      /** All components zero. */
      fixed,
      /** All components follow the face's displacement (ramped). */
      prescribed,
      /** The normal component follows it, the others are free. */
      prescribed_normal,
      /** The tangential components zero, the normal one free (a face that
       *  moves only along its normal: the sides of a shear column). */
      normal_only
    };

    /** @brief The scene's names of the face conditions, in enum order. */
    constexpr std::array<const char *, 6> face_condition_names = {
      {"none",
       "roller",
       "fixed",
       "prescribed",
       "prescribed normal",
       "normal only"}};

    /**
     * @brief Whether @p condition on face @p face holds component
     * @p component of the displacement.
     */
    inline bool
    constrains(const FaceCondition condition,
               const unsigned int  face,
               const unsigned int  component)
    {
      switch (condition)
        {
          case FaceCondition::fixed:
          case FaceCondition::prescribed:
            return true;
          case FaceCondition::roller:
          case FaceCondition::prescribed_normal:
            return component == face / 2;
          case FaceCondition::normal_only:
            return component != face / 2;
          default:
            return false;
        }
    }

    /** @brief Whether @p condition moves the face. */
    inline bool
    is_prescribed(const FaceCondition condition)
    {
      return condition == FaceCondition::prescribed ||
             condition == FaceCondition::prescribed_normal;
    }

    /** @brief The statement of equilibrium. */
    enum class Formulation
    {
      /** The paper's eq. 9-10: the pulled-back stress on the start-of-step
       * grid. */
      previously_converged,
      /** Eq. 7-8: Cauchy stress with mapped gradients. */
      updated_lagrangian
    };

    /** @brief The scene's names of the formulations, in enum order. */
    constexpr std::array<const char *, 2> formulation_names = {
      {"previously converged", "updated Lagrangian"}};

    /** @brief The linear solver of each Newton iteration. */
    enum class LinearSolverType
    {
      /** KLU up to 'AMG coarse size' system DoFs, GMRES with AMG above. */
      automatic,
      /** Trilinos Amesos KLU (serial factorisation). */
      direct,
      /** Trilinos Amesos MUMPS (distributed factorisation). */
      mumps,
      /** GMRES preconditioned with Trilinos ML. */
      gmres_amg
    };

    /** @brief The scene's names of the linear solvers, in enum order. */
    constexpr std::array<const char *, 4> linear_solver_names = {
      {"automatic", "direct", "MUMPS", "GMRES with AMG"}};

    /** @brief An analytical solution to compare with. */
    enum class AnalyticalSolution
    {
      /** None. */
      none,
      /** The column under its own weight (the paper's eq. 12). */
      column
    };

    /** @brief The scene's names of the analytical solutions. */
    constexpr std::array<const char *, 2> analytical_solution_names = {
      {"none", "column"}};

    /** @brief The file format of the point output. */
    enum class PointFileFormat
    {
      /** One `.vtu` piece per process, a `.pvtu` record per output step and
       *  a `.pvd` series. */
      vtu,
      /** One `.h5` file per output step, written by all processes together
       *  (parallel HDF5), and an `.xdmf` series that describes them. */
      hdf5
    };

    /** @brief The names of PointFileFormat in the scene. */
    constexpr std::array<const char *, 2> point_file_format_names = {
      {"vtu", "hdf5"}};

    /**
     * @brief The index in @p names of @p value: for parsing a selection
     * once into its enum. A value not in the list (which the entry's
     * Patterns::Selection has already excluded) is an error naming the
     * entry.
     */
    template <std::size_t n>
    unsigned int
    selection_index(const std::array<const char *, n> &names,
                    const std::string                 &entry,
                    const std::string                 &value)
    {
      for (unsigned int i = 0; i < n; ++i)
        if (value == names[i])
          return i;
      std::string allowed;
      for (const char *name : names)
        allowed += (allowed.empty() ? "" : "|") + std::string(name);
      bad_value(entry, value, "allowed: " + allowed + ".");
    }

    /** @brief Scene name, dimension and where output goes. */
    struct Scene
    {
      /** Name written into the summary. */
      std::string name;
      /** Space dimension (2: plane strain, or 3). */
      unsigned int dimension;
      /** Directory for all output files; created if missing. */
      std::string output_directory;
      /** Whether a directory holding another scene's run is replaced. */
      bool overwrite_existing_output = false;
      /** The scene file (absolute path), or "default scene"; set by
       *  run_scene(), not read from the scene. */
      std::string file;
      /** Stop after this many converged load steps (0: run to the full
       *  load); from the command line (--stop-after-step), not the scene. */
      unsigned int stop_after_step = 0;

      /** @brief Declare the entries (top level). */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read the entries. */
      void
      parse_parameters(const ParameterHandler &prm);
    };

    /** @brief The Cartesian background grid and its boundary conditions. */
    template <int dim>
    struct Grid
    {
      /** Whether the 2D grid is the meridian plane (r, z) of a solid of
       *  revolution (CartesianGrid::axisymmetric). */
      bool axisymmetric = false;
      /** Lower corner. */
      Point<dim> lower_corner;
      /** Upper corner. */
      Point<dim> upper_corner;
      /** Cells in each direction. */
      std::array<unsigned int, dim> n_cells;
      /** Condition on each face, in the order x-, x+, y-, y+ (, z-, z+). */
      std::array<FaceCondition, 2 * dim> face_conditions;
      /** Displacement of prescribed faces at the full load (ramped). */
      std::array<Tensor<1, dim>, 2 * dim> face_displacements;
      /** Whether a face's condition is limited to a box of it. */
      std::array<bool, 2 * dim> face_has_region;
      /** That box, lower and upper corner. */
      std::array<std::pair<Point<dim>, Point<dim>>, 2 * dim> face_regions;

      /** @brief Declare the entries in subsection "Grid". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(ParameterHandler &prm);

    private:
      /** @brief Refuse an axisymmetric grid in 3D, across the axis, or
       *  reaching it without the radial displacement held there. */
      void
      check_axisymmetric_grid(const ParameterHandler &prm) const;
    };

    /** @brief How points and nodes are weighted. */
    struct MaterialPoints
    {
      /** GIMP or standard MPM. */
      BasisType basis;
      /** Whether GIMP domains stretch with the deformation. */
      bool update_domains;
      /** Whether the points move with the material (false: they stay where
       *  they were seeded, a small-displacement reference). */
      bool move_points;
      /** Whether the points' volume changes are averaged per cell and body
       *  (FBar). */
      bool f_bar;
      /** Whether F-bar's patches share a pressure, an unknown (FBar). */
      bool cell_pressure_unknowns;
      /** The factor of the penalty on the cell pressures' jumps. */
      double pressure_jump_stabilisation;
      /** Largest ratio of the most points on a process to the mean before
       *  the grid is repartitioned. */
      double load_imbalance_threshold;

      /** @brief Declare the entries in subsection "Material points". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(ParameterHandler &prm);
    };



    /**
     * @brief The scene's description: what it holds and where (the grid,
     * the bodies, the rigid bodies, the material points, gravity). How it
     * is solved, written and tested is parsed by the modules that do it
     * (Parameters::Solver, Output, Testing, Checkpoint; the couplings and
     * effects their own subsections), all declared by
     * declare_run_parameters() (simulator/run.h).
     */
    template <int dim>
    struct All
    {
      /** Scene. */
      Scene scene;
      /** Grid. */
      Grid<dim> grid;
      /** The bodies (Body 1 ... Body n). */
      std::vector<impm::Body<dim>> bodies;
      /** The rigid bodies (Rigid body 1 ... Rigid body n; none by
       *  default). */
      std::vector<impm::RigidBody<dim>> rigid_bodies;
      /** Material points. */
      MaterialPoints material_points;
      /** Whether gravity acts, and its acceleration (the Gravity effect's
       * parameters, read here for the analytical solution). */
      bool gravity_enabled;
      /** Gravitational acceleration. */
      Tensor<1, dim> gravity;

      /** @brief Read all subsections. */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /**
     * @brief Declare the entries of the scene's description (All) and of
     * its effects, for both dimensions (vector entries are lists whose
     * length is checked against the dimension).
     */
    void
    declare_all(ParameterHandler &prm);
  } // namespace Parameters
} // namespace impm

#endif
