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
      prescribed_normal
    };

    /** @brief The scene's names of the face conditions, in enum order. */
    constexpr std::array<const char *, 5> face_condition_names = {
      {"none", "roller", "fixed", "prescribed", "prescribed normal"}};

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
    };

    /** @brief How points and nodes are weighted. */
    struct MaterialPoints
    {
      /** GIMP or standard MPM. */
      BasisType basis;
      /** Whether GIMP domains stretch with the deformation. */
      bool update_domains;
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

    /** @brief Load stepping, Newton and the linear solver. */
    struct Solver
    {
      /** Previously converged (eq. 9-10) or updated Lagrangian (eq. 7-8,
       * with mapped derivatives): the same iterates, different cost. */
      Formulation formulation;
      /** Number of equal load steps. */
      unsigned int n_load_steps;
      /** Convergence when |r| / |f_ext| falls below this. */
      double tolerance;
      /** Newton also converges when the residual norm falls below this
       *  (N; 0: off). */
      double absolute_tolerance = 0.;
      /** Newton iterations allowed per load step. */
      unsigned int max_iterations;
      /** Direct (Amesos KLU) or GMRES with AMG (Trilinos ML). */
      LinearSolverType linear_solver;
      /** Relative tolerance of the iterative linear solver. */
      double linear_tolerance;
      /** Iterations allowed to the iterative linear solver per solve. */
      unsigned int linear_iterations;
      /** Tie the linear tolerance to the Newton residual. */
      bool adaptive_linear_tolerance;
      /** The loosest linear tolerance the adaptive choice gives. */
      double largest_linear_tolerance;
      /** Keep the AMG hierarchy while the Krylov iterations stay below this
       *  factor times those right after it was built (0: never keep). */
      double amg_reuse_factor;
      /** ML's aggregation threshold (the connections weaker than this
       *  fraction of the diagonal are dropped before aggregation). */
      double amg_aggregation_threshold;
      /** ML coarsens until a level has at most this many rows and solves
       *  that level directly. */
      unsigned int amg_coarse_size;
      /** 'automatic': the largest system whose failed GMRES solve KLU
       *  repeats (0: none). */
      unsigned int direct_rescue_size;
      /** Cut failed load steps and grow easy ones (else a failure stops). */
      bool step_control;
      /** Smallest load increment, as a fraction of the total load. */
      double minimum_step;
      /** A step has failed when the residual exceeds this times its first. */
      double divergence_factor;
      /** A step that needs at most this many iterations may grow the next. */
      unsigned int easy_iterations;
      /** Largest point displacement of one step, in cells (step control). */
      double maximum_point_increment;
      /** Estimate the condition number of each step's first matrix. */
      bool estimate_condition;

      /** @brief Declare the entries in subsection "Solver". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(ParameterHandler &prm);
    };

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

      /** @brief Declare the entries in subsection "Ghost stabilisation". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** @brief What is written, and how often. */
    struct Output
    {
      /** Write point files every this many load steps (0: never). */
      unsigned int interval;
      /** The point files' format. */
      PointFileFormat format;
      /** Compare with this analytical solution. */
      AnalyticalSolution analytical_solution;
      /** @brief The fields written to the point files. */
      struct Fields
      {
        /** Displacement x - X. */
        bool displacement = true;
        /** Initial position X. */
        bool initial_position = true;
        /** The six Cauchy stress components. */
        bool stress = true;
        /** The von Mises equivalent stress. */
        bool von_mises_stress = true;
        /** The current volume. */
        bool volume = true;
        /** The process that owns the point. */
        bool rank = true;
        /** The body (scenes with several bodies only). */
        bool body = true;
        /** Every field the materials and couplings declare as written. */
        bool all_declared = true;
        /** The declared fields named (checked against the scene's once
         *  its points are laid out). */
        std::vector<std::string> declared;
      } fields;

      /** @brief Declare the entries in subsection "Output". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** @brief A deterministic summary for the test suite. */
    struct Testing
    {
      /** Print the test summary instead of the progress and timing. */
      bool enabled;
      /** Number of points (by id) whose state is printed at the end. */
      unsigned int n_printed_points;
      /** The observed Newton order every step must reach. */
      double minimum_newton_order;
      /** Compare every assembled matrix with central differences. */
      bool check_tangent;
      /** Significant digits of the printed points' numbers. */
      unsigned int significant_digits;
      /** Expected upper corner of the final points' bounding box (empty:
       * none), e.g. from a run with other settings. */
      std::vector<double> reference_extent;
      /** Allowed distance from the reference extent. */
      double reference_tolerance;
      /** Length L the test summary divides lengths by (m). */
      double reference_length;
      /** Stress S the test summary divides stresses by (Pa). */
      double reference_stress;
      /** Points nearest to these initial positions are printed too. */
      std::vector<std::vector<double>> probes;

      /** @brief Declare the entries in subsection "Testing". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them; positions have @p dimension coordinates. */
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dimension);
    };

    /** @brief When the run saves its state (subsection "Checkpoint"). */
    struct Checkpoint
    {
      /** Save every this many converged load steps (0: never). */
      unsigned int interval = 0;
      /** Save and stop once the run has taken this many seconds of wall
       *  time (0: no limit). */
      double wall_time_limit = 0.;

      /** @brief Declare the entries in subsection "Checkpoint". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** @brief Everything a scene says. */
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
      /** Solver. */
      Solver solver;
      /** Ghost stabilisation. */
      Stabilisation stabilisation;
      /** Output. */
      Output output;
      /** Checkpoints. */
      Checkpoint checkpoint;
      /** Testing. */
      Testing testing;

      /** @brief Read all subsections. */
      void
      parse_parameters(ParameterHandler &prm);
    };

    /**
     * @brief Declare every entry of a scene, for both dimensions (vector
     * entries are lists whose length is checked against the dimension).
     */
    void
    declare_all(ParameterHandler &prm);
  } // namespace Parameters
} // namespace impm

#endif
