#ifndef impm_postprocess_output_parameters_h
#define impm_postprocess_output_parameters_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>

#include <impm/core/parameters.h>
#include <impm/io/point_output.h>

#include <string>
#include <vector>

namespace impm
{
  namespace Parameters
  {
    /** @brief What is written, and how often. */
    struct Output
    {
      /** Write point files every this many load steps (0: never). */
      unsigned int interval;
      /** The point files' format. */
      PointFileFormat format;
      /** The zlib level of the VTU files' data (points and grid fields):
       *  the entry `Compression`. The fastest level writes 10 % larger
       *  files 20-40 times faster than the smallest (doc/benchmarks/
       *  start_and_progress.md, "Writing the files"). */
      DataOutBase::VtkFlags::ZlibCompressionLevel compression =
        DataOutBase::VtkFlags::best_speed;
      /** Compare with this analytical solution. */
      AnalyticalSolution analytical_solution;
      /** Print only errors and the run's final summary on the terminal
       *  (no description of the scene, no line per load step, no table of
       *  timings): the entry `Quiet`, or the flag --quiet. */
      bool quiet = false;
      /** Print every this many converged steps' lines (failed attempts and
       *  the last step always): the entry `Terminal interval`. */
      unsigned int terminal_interval = 1;
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
      };
      /** The point files' fields. */
      Fields fields;

      /** @brief The nodal fields written to the grid files (GridFiles in
       *  postprocess/grid_files.cc; none of them: no grid files). */
      struct GridFields
      {
        /** The last load step's displacement increment. */
        bool displacement_increment = false;
        /** The lumped nodal mass. */
        bool mass = false;
        /** The internal force (with the couplings' forces). */
        bool internal_force = false;
        /** The external force. */
        bool external_force = false;
        /** The reaction: internal minus external force on constrained
         *  DoFs, zero elsewhere. */
        bool reaction = false;
        /** The nodal velocity (scenes with inertia only). */
        bool velocity = false;
        /** Whether 'all' was named (then velocity only with inertia). */
        bool all = false;

        /** @brief Whether any field is asked for. */
        bool
        any() const
        {
          return displacement_increment || mass || internal_force ||
                 external_force || reaction || velocity;
        }
      };
      /** The grid files' fields. */
      GridFields grid_fields;

      /** @brief Declare the entries in subsection "Output". */
      static void
      declare_parameters(ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(ParameterHandler &prm);

    private:
      /** @brief Set grid_fields from the names of 'Grid fields'; refuse
       *  them with 'Interval' = 0. */
      void
      parse_grid_fields(const std::vector<std::string> &names);
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
  } // namespace Parameters
} // namespace impm

#endif
