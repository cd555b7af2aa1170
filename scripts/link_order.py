#!/usr/bin/env python3
"""Find an order of deal.II's shared libraries that makes a program start faster.

Most of an `impm` start (0.25-0.5 s on the 2-core test machine) is the
dynamic loader binding the 320,000 symbols the 200 libraries of deal.II's
Debian build refer to: each lookup visits the libraries of the search scope
in turn until one defines the symbol, and in the order the linker gives (the
program's direct dependencies, then theirs) a lookup from the core library
visited 39 of them on average. Naming the libraries that define the most-looked-up symbols first on
the program's link line shortens that walk.

A library may only move ahead of others if no symbol changes its meaning: this
script moves a library ahead of the ones it jumps over only when every symbol
both define is weak in both (a C++ template or inline function, the same code
by the one-definition rule); C libraries that define the same function
(ScaLAPACK's copy of BLAS routines, PETSc's copies of MPI's Fortran
sentinels) keep their order. The program's own global scope (libc, libm,
libstdc++, libgcc_s) and LIBRARY itself stay first.

Usage: link_order.py LIBRARY PROGRAM [ARGUMENTS...]
  runs PROGRAM ARGUMENTS under LD_DEBUG (for IMPM, from a build configured
  with -DIMPM_ORDER_LIBRARIES=OFF: link_order.py libimpm_core.so
  build/impm --print-parameters), takes the order in which the libraries
  that LIBRARY (loaded by the program, or the program itself) brings are
  searched, prints the libraries to name first, one file name a line, and
  on standard error the mean number of libraries a lookup visits before and
  after.
The list printed is cmake/link_order.txt (see CMakeLists.txt); the figures
are in doc/benchmarks/start_and_progress.md.
"""
import collections
import os
import re
import subprocess
import sys
import tempfile

WEAK_TYPES = {"W", "V", "u", "w", "v"}
# Symbols the linker defines in every library (nothing looks them up).
LINKER_DEFINED = {"_end", "_edata", "__bss_start", "_init", "_fini"}


def loader_report(program, what):
    with tempfile.TemporaryDirectory() as directory:
        environment = dict(os.environ, LD_DEBUG=what,
                           LD_DEBUG_OUTPUT=os.path.join(directory, "ld"))
        subprocess.run(program, env=environment, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=False)
        text = ""
        for name in os.listdir(directory):
            with open(os.path.join(directory, name), errors="replace") as f:
                text += f.read()
        return text


def defined_symbols(library):
    """Map of the dynamic symbols LIBRARY defines to whether each is weak."""
    output = subprocess.run(["nm", "-D", "--defined-only", library],
                            capture_output=True, text=True).stdout
    symbols = {}
    for line in output.splitlines():
        fields = line.split()
        if len(fields) < 3:
            continue
        name = fields[2].split("@")[0]
        if name in LINKER_DEFINED:
            continue
        symbols[name] = fields[1] in WEAK_TYPES
    return symbols


def search_order(scope_text, library):
    """The global scope, then LIBRARY's own scope if it was loaded apart."""
    blocks = re.findall(r"object=(\S+) \[0\]\n(?:.*scope 0: (.*)\n)"
                        r"(?:.*scope 1: (.*)\n)?", scope_text)
    for name, global_scope, local_scope in blocks:
        if os.path.basename(name).startswith(library):
            order = global_scope.split()
            order += [x for x in local_scope.split() if x not in order]
            return order, len(global_scope.split()) + 1
    name, global_scope, _ = blocks[0]
    return global_scope.split(), 1


def main():
    library, program = sys.argv[1], sys.argv[2:]
    scope, n_fixed = search_order(loader_report(program, "scopes"), library)
    lookups = collections.Counter(
        re.findall(r" to (\S+) \[", loader_report(program, "bindings")))
    position = {name: i for i, name in enumerate(scope)}

    # The program's global scope (the C and C++ run-times) and the library
    # itself stay first.
    rest = scope[n_fixed:]
    symbols = {name: defined_symbols(name) for name in rest}

    moved = []
    for candidate, count in lookups.most_common():
        if candidate not in symbols or count < 500:
            continue
        jumped = [y for y in rest[:rest.index(candidate)] if y not in moved]
        conflict = False
        for y in jumped:
            for name in symbols[candidate].keys() & symbols[y].keys():
                if not (symbols[candidate][name] and symbols[y][name]):
                    conflict = True
                    break
            if conflict:
                break
        if not conflict:
            moved.append(candidate)

    new_scope = scope[:n_fixed] + moved + [y for y in rest if y not in moved]
    new_position = {name: i for i, name in enumerate(new_scope)}
    total = sum(lookups.values())

    def mean_depth(where):
        return sum(c * (where.get(f, len(scope)) + 1)
                   for f, c in lookups.items()) / total

    print(f"{total} lookups; libraries visited per lookup: "
          f"{mean_depth(position):.1f} in the linker's order, "
          f"{mean_depth(new_position):.1f} with {len(moved)} named first",
          file=sys.stderr)
    for name in moved:
        print(os.path.basename(name))


if __name__ == "__main__":
    main()
