// build/impm [scene.prm] [--set "Subsection/Entry=value"]... : run a scene.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <impm/core/default_scene.h>
#include <impm/core/parameters.h>
#include <impm/core/run.h>

#include <iostream>
#include <string>
#include <vector>

namespace
{
  const char *usage =
    "Usage: impm [SCENE.prm] [options]\n"
    "\n"
    "Runs an implicit material point analysis of the scene in SCENE.prm\n"
    "(a deal.II parameter file); without SCENE.prm, runs the built-in\n"
    "default scene (prm/column_compaction.prm).\n"
    "\n"
    "Options:\n"
    "  --set \"Subsection/Entry=value\"  override one entry of the scene\n"
    "                                  (repeatable), e.g.\n"
    "                                  --set \"Grid/Number of cells=1, 64\"\n"
    "  --print-parameters              print every parameter with its\n"
    "                                  default and documentation, and exit\n"
    "  --help                          print this text and exit\n"
    "\n"
    "Run in parallel with: mpirun -np N impm SCENE.prm\n";

  /**
   * Apply "A/B/Entry=value" to @p prm, naming the override on error.
   */
  void
  apply_override(dealii::ParameterHandler &prm, const std::string &assignment)
  {
    const auto equals = assignment.find('=');
    if (equals == std::string::npos)
      throw std::runtime_error("--set '" + assignment +
                               "': expected \"Subsection/Entry=value\".");
    const std::string        path  = assignment.substr(0, equals);
    const std::string        value = assignment.substr(equals + 1);
    std::vector<std::string> parts;
    std::string::size_type   start = 0, slash;
    while ((slash = path.find('/', start)) != std::string::npos)
      {
        parts.push_back(path.substr(start, slash - start));
        start = slash + 1;
      }
    const std::string entry = path.substr(start);
    for (const auto &section : parts)
      prm.enter_subsection(section);
    try
      {
        prm.set(entry, value);
      }
    catch (const std::exception &e)
      {
        throw std::runtime_error("--set '" + assignment +
                                 "': " + std::string(e.what()));
      }
    for (unsigned int i = 0; i < parts.size(); ++i)
      prm.leave_subsection();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Errors are reported by their message; a user needs no stack trace.
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  const bool is_root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      std::string              scene_file;
      std::vector<std::string> overrides;
      bool                     print_parameters = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string argument = argv[i];
          if (argument == "--help" || argument == "-h")
            {
              if (is_root)
                std::cout << usage;
              return 0;
            }
          else if (argument == "--print-parameters")
            print_parameters = true;
          else if (argument == "--set")
            {
              if (i + 1 >= argc)
                throw std::runtime_error("--set needs an argument "
                                         "\"Subsection/Entry=value\".");
              overrides.push_back(argv[++i]);
            }
          else if (argument.rfind("--", 0) == 0)
            throw std::runtime_error("Unknown option '" + argument +
                                     "'; see impm --help.");
          else if (scene_file.empty())
            scene_file = argument;
          else
            throw std::runtime_error("Only one scene file may be given; got '" +
                                     scene_file + "' and '" + argument + "'.");
        }

      dealii::ParameterHandler prm;
      impm::Parameters::declare_all(prm);
      if (print_parameters)
        {
          if (is_root)
            prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
          return 0;
        }
      if (scene_file.empty())
        prm.parse_input_from_string(impm::default_scene, "default scene");
      else
        prm.parse_input(scene_file);
      for (const auto &assignment : overrides)
        apply_override(prm, assignment);

      if (prm.get_integer("Dimension") == 2)
        impm::run_scene<2>(prm, MPI_COMM_WORLD);
      else
        impm::run_scene<3>(prm, MPI_COMM_WORLD);
    }
  catch (const std::exception &exception)
    {
      if (is_root)
        std::cerr << "\nError: " << exception.what() << std::endl;
      return 1;
    }
  return 0;
}
