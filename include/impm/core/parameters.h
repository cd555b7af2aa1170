#ifndef impm_core_parameters_h
#define impm_core_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <impm/core/body.h>

#include <array>
#include <string>
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

    /** @brief Scene name, dimension and where output goes. */
    struct Scene
    {
      /** Name written into the summary. */
      std::string name;
      /** Space dimension (2: plane strain, or 3). */
      unsigned int dimension;
      /** Directory for all output files; created if missing. */
      std::string output_directory;

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
      /**
       * Condition on each face, in the order x-, x+, y-, y+ (, z-, z+):
       * "none", "roller" (normal displacement zero), "fixed", "prescribed"
       * (all components follow face_displacements) or "prescribed normal"
       * (the normal component follows it, the others are free).
       */
      std::array<std::string, 2 * dim> face_conditions;
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
      /** "GIMP" or "standard MPM". */
      std::string basis;
      /** Whether GIMP domains stretch with the deformation. */
      bool update_domains;

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
      /** "previously converged" (eq. 9-10) or "updated Lagrangian" (eq. 7-8,
       * with mapped derivatives): the same iterates, different cost. */
      std::string formulation;
      /** Number of equal load steps. */
      unsigned int n_load_steps;
      /** Convergence when |r| / |f_ext| falls below this. */
      double tolerance;
      /** Newton iterations allowed per load step. */
      unsigned int max_iterations;
      /** "direct" (Amesos KLU) or "GMRES with AMG" (Trilinos ML). */
      std::string linear_solver;
      /** Relative tolerance of the iterative linear solver. */
      double linear_tolerance;
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
      /** Compare with this analytical solution ("none", "column"). */
      std::string analytical_solution;
      /** Fields written to the point files ("all" or a list). */
      std::vector<std::string> fields;

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
      /** Significant digits of the printed points' numbers. */
      unsigned int significant_digits;
      /** Expected upper corner of the final points' bounding box (empty:
       * none), e.g. from a run with other settings. */
      std::vector<double> reference_extent;
      /** Allowed distance from the reference extent. */
      double reference_tolerance;
      /** Points nearest to these initial positions are printed too. */
      std::vector<std::vector<double>> probes;

      /** @brief Declare the entries in subsection "Testing". */
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
