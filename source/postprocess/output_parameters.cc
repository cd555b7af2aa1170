#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/postprocess/output_parameters.h>

#include <algorithm>

// The scene's 'Output' and 'Testing' sections: what the postprocessors write
// and print.
namespace impm
{
  namespace Parameters
  {
    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Interval",
                        "1",
                        Patterns::Integer(0),
                        "Write the points (in the Format below) every "
                        "this many load steps; 0 writes none. The initial "
                        "and the last state are always written if > 0.");
      prm.declare_entry(
        "Format",
        "vtu",
        Patterns::Selection("vtu|hdf5"),
        "The point files' format, both read by ParaView: vtu (one .vtu piece "
        "per process, a .pvtu record per output step, the points.pvd "
        "series) or hdf5 (one .h5 file per output step written by all "
        "processes together, the points.xdmf series; for large runs: one "
        "file per step whatever the number of processes; deal.II 9.4 "
        "stores the fields in single precision, the positions in double; "
        "rigid bodies' surfaces, VTU files, in the series "
        "points_parts.pvd).");
      prm.declare_entry(
        "Compression",
        "best speed",
        Patterns::Selection("best speed|best compression|none"),
        "How the VTU files (points and grid fields) compress their data "
        "(zlib): best speed (the default: files about 10 % larger than "
        "best compression's, written 20-40 times faster), best compression "
        "(the smallest files, for runs kept long or copied far) or none "
        "(about ten times larger). ParaView reads all three alike.");
      prm.declare_entry("Analytical solution",
                        "none",
                        Patterns::Selection("none|column"),
                        "Compare with an analytical solution: column is the "
                        "vertical stress of a column under its own weight, "
                        "sigma_yy = -rho_0 g (l0 - Y) (the paper's eq. 12), "
                        "whose error (eq. 13) goes to steps.csv and "
                        "summary.json.");
      prm.declare_entry(
        "Fields",
        "all",
        Patterns::List(Patterns::Anything()),
        "Point data written to the point files: all (every field the "
        "scene's points have) or a list of displacement, initial_position, "
        "stress (all six components), von_mises_stress, volume, rank, body "
        "(scenes with several bodies only) and the state the scene's "
        "materials declare: plastic_multiplier (the plastic models). A name "
        "the scene's points do not store is an error.");
      prm.declare_entry(
        "Grid fields",
        "",
        Patterns::List(Patterns::Selection(
                         "all|displacement_increment|mass|internal_force|"
                         "external_force|reaction|velocity"),
                       0,
                       7),
        "Nodal fields written to grid files beside the point files (the "
        "grid.pvd series of grid_NNNNN.pvtu records, one .vtu piece per "
        "process, on the steps the point files are written after the "
        "start): empty for none (nothing is computed), all, or a list of "
        "displacement_increment (the load step's), mass (lumped), "
        "internal_force, external_force, reaction (internal minus external "
        "force on the DoFs a face condition holds, zero elsewhere) and "
        "velocity (scenes with inertia only: the points' momentum over the "
        "mass; 'all' includes it only there). Each written at the end of a "
        "converged step on the step's grid, before the points move; only "
        "the cells whose every node carries mass (the cells the points' "
        "supports cover) are written; VTU whatever 'Format', in single "
        "precision (deal.II 9.4).");
      prm.declare_entry(
        "Terminal interval",
        "1",
        Patterns::Integer(1),
        "Print the line of every this many converged load steps (or time "
        "steps) on the terminal; every failed attempt and the last step are "
        "printed whatever this is, and steps.csv holds every step. For long "
        "explicit runs, whose steps are many and short (e.g. 100).");
      prm.declare_entry("Quiet",
                        "false",
                        Patterns::Bool(),
                        "Print on the terminal only errors and the run's "
                        "final summary (no description of the scene, no "
                        "line per load step, no table of timings); the "
                        "command-line flag --quiet sets this. The files "
                        "are written as always.");
      prm.leave_subsection();
    }

    void
    Output::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      interval = prm.get_integer("Interval");
      format   = static_cast<PointFileFormat>(selection_index(
        point_file_format_names, "Output/Format", prm.get("Format")));
      const std::string compression_name = prm.get("Compression");
      compression                        = compression_name == "none" ?
                                             DataOutBase::VtkFlags::no_compression :
                                           compression_name == "best compression" ?
                                             DataOutBase::VtkFlags::best_compression :
                                             DataOutBase::VtkFlags::best_speed;
      analytical_solution                = static_cast<AnalyticalSolution>(
        selection_index(analytical_solution_names,
                        "Output/Analytical solution",
                        prm.get("Analytical solution")));
      quiet             = prm.get_bool("Quiet");
      terminal_interval = prm.get_integer("Terminal interval");
      const auto names  = Utilities::split_string_list(prm.get("Fields"));
      const auto wanted = [&names](const std::string &field) {
        for (const auto &name : names)
          if (name == "all" || name == field)
            return true;
        return false;
      };
      fields.displacement     = wanted("displacement");
      fields.initial_position = wanted("initial_position");
      fields.stress           = wanted("stress");
      fields.von_mises_stress = wanted("von_mises_stress");
      fields.volume           = wanted("volume");
      fields.rank             = wanted("rank");
      fields.body             = wanted("body");
      fields.all_declared     = wanted("all");
      fields.declared.clear();
      const std::vector<std::string> built_in = {"all",
                                                 "displacement",
                                                 "initial_position",
                                                 "stress",
                                                 "von_mises_stress",
                                                 "volume",
                                                 "rank",
                                                 "body"};
      for (const auto &name : names)
        if (std::find(built_in.begin(), built_in.end(), name) == built_in.end())
          fields.declared.push_back(name);
      parse_grid_fields(Utilities::split_string_list(prm.get("Grid fields")));
      prm.leave_subsection();
    }



    void
    Output::parse_grid_fields(const std::vector<std::string> &names)
    {
      const auto named = [&names](const std::string &field) {
        return std::find(names.begin(), names.end(), field) != names.end();
      };
      grid_fields.all = named("all");
      grid_fields.displacement_increment =
        grid_fields.all || named("displacement_increment");
      grid_fields.mass           = grid_fields.all || named("mass");
      grid_fields.internal_force = grid_fields.all || named("internal_force");
      grid_fields.external_force = grid_fields.all || named("external_force");
      grid_fields.reaction       = grid_fields.all || named("reaction");
      grid_fields.velocity       = named("velocity");
      if (grid_fields.any() && interval == 0)
        throw InputError("Output/Grid fields are written on the steps of the "
                         "point files: set 'Output/Interval' above 0.");
    }



    void
    Testing::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Testing");
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Print a deterministic summary for the test suite "
                        "(same on any number of processes) instead of "
                        "progress and timing.");
      prm.declare_entry("Printed points",
                        "3",
                        Patterns::Integer(0),
                        "Number of points, lowest ids first, whose final "
                        "state the test summary prints.");
      prm.declare_entry("Minimum Newton order",
                        "1.7",
                        Patterns::Double(1., 2.),
                        "The observed Newton order near the solution that "
                        "the test summary requires of every step, in [1, 2] "
                        "(quadratic convergence observed as 1.7 or more; a "
                        "scene whose points change return region in the "
                        "last iterations may say less, with its reason).");
      prm.declare_entry("Check tangent",
                        "false",
                        Patterns::Bool(),
                        "Compare every assembled matrix with central "
                        "differences of the internal force, one system DoF "
                        "at a time (two stress updates per DoF: for small "
                        "scenes only); the test summary says whether the "
                        "largest difference is within 1e-6 of the largest "
                        "entry.");
      prm.declare_entry("Significant digits",
                        "6",
                        Patterns::Integer(3, 17),
                        "Digits of the printed points: significant digits of "
                        "the position, decimals of the scaled displacement "
                        "and stresses; few enough for the test suite to "
                        "ignore round-off, up to 17 to compare two runs to "
                        "full precision.");
      prm.declare_entry("Reference length",
                        "1",
                        Patterns::Double(1e-300),
                        "Length L (m) the test summary divides lengths and "
                        "displacements by, e.g. the cell size: the printed "
                        "values are then checked to 1e-6 of L.");
      prm.declare_entry("Reference stress",
                        "1",
                        Patterns::Double(1e-300),
                        "Stress S (Pa) the test summary divides stresses by "
                        "(reactions by S L^(dim-1)), e.g. rho g l0 of a "
                        "column or a yield stress: the printed values are "
                        "then checked to 1e-6 of S.");
      prm.declare_entry("Reference extent",
                        "",
                        Patterns::List(Patterns::Double(), 0, 3),
                        "If given (one number per dimension), the test "
                        "summary checks that the upper corner of the final "
                        "points' bounding box is within 'Reference "
                        "tolerance' of it: a final state computed another "
                        "way.");
      prm.declare_entry("Probes",
                        "",
                        Patterns::Anything(),
                        "Initial positions 'x, y; x, y; ...': the test "
                        "summary prints the displacement and stress of the "
                        "point initially nearest to each.");
      prm.declare_entry("Reference tolerance",
                        "0",
                        Patterns::Double(0.),
                        "Allowed distance (in m, per direction) from "
                        "'Reference extent'.");
      prm.leave_subsection();
    }

    void
    Testing::parse_parameters(ParameterHandler  &prm,
                              const unsigned int dimension)
    {
      prm.enter_subsection("Testing");
      enabled              = prm.get_bool("Enabled");
      n_printed_points     = prm.get_integer("Printed points");
      minimum_newton_order = prm.get_double("Minimum Newton order");
      check_tangent        = prm.get_bool("Check tangent");
      significant_digits   = prm.get_integer("Significant digits");
      reference_extent =
        get_optional_vector(prm, "Testing", "Reference extent", dimension);
      reference_tolerance = prm.get_double("Reference tolerance");
      reference_length    = prm.get_double("Reference length");
      reference_stress    = prm.get_double("Reference stress");
      probes              = get_point_list(prm, "Testing", "Probes", dimension);
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace impm
