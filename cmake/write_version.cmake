# Writes the header of IMPM's version and revision (run at every build by the
# target impm_version: `cmake -P`). The revision is `git describe --always
# --dirty` of the source tree ("unknown" outside a git checkout or without
# git); configure_file rewrites the header only when its text changes, so
# that a build at the same revision compiles nothing again.
# Input: SOURCE_DIR, TEMPLATE, OUTPUT, IMPM_VERSION, DEAL_II_VERSION.
set(IMPM_REVISION "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(
    COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} describe --always --dirty --abbrev=12
    OUTPUT_VARIABLE _revision OUTPUT_STRIP_TRAILING_WHITESPACE
    RESULT_VARIABLE _result ERROR_QUIET)
  if(_result EQUAL 0 AND NOT _revision STREQUAL "")
    set(IMPM_REVISION "${_revision}")
  endif()
endif()
# Several builds may run this at once (each deal.II-style test runs `make`
# for its target while others run): each writes a file of its own and
# renames it over the header only if the text differs, and a rename is
# atomic, so that no build sees the header half-written or a temporary
# file that another removed (configure_file alone shares one temporary
# name: a concurrent run failed with "No such file or directory").
string(TIMESTAMP _now "%s%f")
string(RANDOM LENGTH 16 RANDOM_SEED ${_now} _suffix)
set(_own "${OUTPUT}.${_now}.${_suffix}")
file(READ ${TEMPLATE} _template)
string(CONFIGURE "${_template}" _text @ONLY)
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} _current)
  if(_current STREQUAL _text)
    return()
  endif()
endif()
get_filename_component(_directory ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${_directory})
file(WRITE ${_own} "${_text}")
file(RENAME ${_own} ${OUTPUT})
