# impm_order_libraries(TARGET): name deal.II's most-looked-up libraries
# (cmake/link_order.txt, made by scripts/link_order.py) first on TARGET's
# link line, so that its dependencies are searched in that order at start-up.
# Nothing changes if deal.II is not the one the list was made for (a name in
# it that is not among deal.II's dependencies), or if ldd is missing.
set(IMPM_LINK_ORDER_FILE ${CMAKE_CURRENT_LIST_DIR}/link_order.txt)

function(impm_order_libraries target)
  string(TOUPPER "${CMAKE_BUILD_TYPE}" _build)
  list(GET DEAL_II_LIBRARIES_${_build} 0 _deal_ii)
  get_filename_component(_deal_ii ${_deal_ii} REALPATH)
  execute_process(COMMAND ldd ${_deal_ii} OUTPUT_VARIABLE _ldd
    RESULT_VARIABLE _status ERROR_QUIET)
  if(NOT _status EQUAL 0)
    message(STATUS "deal.II's libraries linked in the linker's order "
      "(ldd ${_deal_ii} failed)")
    return()
  endif()
  get_filename_component(_name ${_deal_ii} NAME)
  set("_path_${_name}" ${_deal_ii})
  string(REPLACE "\n" ";" _lines "${_ldd}")
  foreach(_line ${_lines})
    if(_line MATCHES "^[ \t]*([^ \t]+) => (/[^ \t]+) ")
      set("_path_${CMAKE_MATCH_1}" "${CMAKE_MATCH_2}")
    endif()
  endforeach()

  file(STRINGS ${IMPM_LINK_ORDER_FILE} _names REGEX "^[^#]")
  set(_paths)
  foreach(_name ${_names})
    if(NOT DEFINED "_path_${_name}")
      message(STATUS "deal.II's libraries linked in the linker's order "
        "(${_name} of cmake/link_order.txt is not one of ${_deal_ii}'s)")
      return()
    endif()
    list(APPEND _paths "${_path_${_name}}")
  endforeach()
  list(LENGTH _paths _n)
  message(STATUS "deal.II's ${_n} most-looked-up libraries named first "
    "(cmake/link_order.txt)")
  target_link_options(${target} PRIVATE
    "LINKER:--push-state,--no-as-needed" ${_paths} "LINKER:--pop-state")
endfunction()
