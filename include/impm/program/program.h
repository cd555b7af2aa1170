#ifndef impm_program_program_h
#define impm_program_program_h

/**
 * @brief The program `impm`: read the command line, parse the scene and run
 * it (or print the parameters, or run a material test). The executable
 * `impm` is a thin launcher (source/main.cc) that links no deal.II, so that
 * `impm --help` starts at once; for everything else it loads the core
 * library and calls this function.
 *
 * @param argc The number of command-line arguments.
 * @param argv The command-line arguments.
 * @return The process's exit status.
 */
extern "C" int
impm_program_main(int argc, char **argv);

#endif
