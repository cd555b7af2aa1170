// build/impm [scene.prm] [--set "Subsection/Entry=value"]... : run a scene.
//
// A thin launcher that links no deal.II: loading deal.II and the libraries
// it links (about 200, whose symbols the dynamic loader binds) takes a
// quarter of a second, which `impm --help` need not pay. For everything else
// it loads the core library (beside the executable in the build tree, in the
// library directory of an installation) and calls impm_program_main().

#include <impm/base/version.h>
#include <impm/program/command_line_text.h>

#include <dlfcn.h>
#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <iostream>
#include <string>

namespace
{
  /** The directory of this executable ("" if it cannot be known). */
  std::string
  executable_directory()
  {
    char       path[PATH_MAX];
    const auto length = readlink("/proc/self/exe", path, sizeof(path) - 1);
    if (length <= 0)
      return "";
    const std::string file(path, static_cast<std::size_t>(length));
    return file.substr(0, file.rfind('/'));
  }



  /** Whether @p path names a file that exists. */
  bool
  exists(const std::string &path)
  {
    return access(path.c_str(), F_OK) == 0;
  }
} // namespace



int
main(int argc, char **argv)
{
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h")
      {
        if (impm::CommandLineText::launcher_rank() == 0)
          std::cout << impm::CommandLineText::usage;
        return 0;
      }
    else if (std::string(argv[i]) == "--version")
      {
        if (impm::CommandLineText::launcher_rank() == 0)
          std::cout << "IMPM " << impm::Version::impm << " (revision "
                    << impm::Version::revision << "), built against deal.II "
                    << impm::Version::deal_ii << std::endl;
        return 0;
      }
  // The stop signals wait (blocked, not lost) until the program has
  // installed its handlers: a SIGTERM while the libraries load would
  // otherwise end the run without a word.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  for (const int signal : {SIGTERM, SIGINT, SIGUSR1})
    sigaddset(&stop_signals, signal);
  sigprocmask(SIG_BLOCK, &stop_signals, nullptr);

  const std::string directory = executable_directory();
  std::string       library   = IMPM_CORE_LIBRARY;
  for (const std::string candidate :
       {directory + "/" + IMPM_CORE_LIBRARY,
        directory + "/" + IMPM_BIN_TO_LIB + "/" + IMPM_CORE_LIBRARY})
    if (!directory.empty() && exists(candidate))
      {
        library = candidate;
        break;
      }
  // Global: the plugins a scene loads, and Open MPI's own components,
  // resolve their symbols against it. Lazy: a function's symbol is bound
  // at its first call, so a run binds only what it calls (the core library
  // and deal.II are built together; a scene's own plugins are loaded with
  // every symbol bound at once, so a missing one is reported at the start).
  void *handle = dlopen(library.c_str(), RTLD_LAZY | RTLD_GLOBAL);
  if (handle == nullptr)
    {
      std::cerr << "Error: cannot load IMPM's library " << library << ": "
                << dlerror() << std::endl;
      return 1;
    }
  using Program = int (*)(int, char **);
  const auto program =
    reinterpret_cast<Program>(dlsym(handle, "impm_program_main"));
  if (program == nullptr)
    {
      std::cerr << "Error: " << library
                << " has no impm_program_main: " << dlerror() << std::endl;
      return 1;
    }
  return program(argc, argv);
}
