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
configure_file(${TEMPLATE} ${OUTPUT} @ONLY)
