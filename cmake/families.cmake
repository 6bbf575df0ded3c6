# Resolves POLYPLAN_FAMILIES into POLYPLAN_BUILT_FAMILIES (the optional families to build, with
# the families they need) and POLYPLAN_FAMILY_DEFINITIONS (POLYPLAN_WITH_NAME=0|1 for each
# optional family: what the registry, the pictures and the program compile in).
set(wanted ${POLYPLAN_FAMILIES})
if(wanted STREQUAL "all")
  set(wanted ${POLYPLAN_OPTIONAL_FAMILIES})
endif()
list(REMOVE_ITEM wanted roadmaps)  # always built: the default planner of a polygon world
foreach(family ${wanted})
  if(NOT family IN_LIST POLYPLAN_OPTIONAL_FAMILIES)
    message(FATAL_ERROR "POLYPLAN_FAMILIES: unknown family '${family}' (all, roadmaps, ${POLYPLAN_OPTIONAL_FAMILIES})")
  endif()
endforeach()
include(${CMAKE_CURRENT_LIST_DIR}/family_needs.cmake)
foreach(family ${wanted})
  list(APPEND wanted ${needs_${family}})
endforeach()

set(POLYPLAN_BUILT_FAMILIES "")
set(POLYPLAN_FAMILY_DEFINITIONS "")
set(left_out "")
foreach(family ${POLYPLAN_OPTIONAL_FAMILIES})  # in their order: a family after those it needs
  string(TOUPPER ${family} upper)
  if(family IN_LIST wanted)
    list(APPEND POLYPLAN_BUILT_FAMILIES ${family})
    set(POLYPLAN_WITH_${upper} ON)
    list(APPEND POLYPLAN_FAMILY_DEFINITIONS POLYPLAN_WITH_${upper}=1)
  else()
    set(POLYPLAN_WITH_${upper} OFF)
    list(APPEND POLYPLAN_FAMILY_DEFINITIONS POLYPLAN_WITH_${upper}=0)
    list(APPEND left_out ${family})
  endif()
endforeach()
# Their names for messages (registry/families.cpp): "grids, incremental, ...", or "".
list(JOIN left_out ", " left_out)
list(APPEND POLYPLAN_FAMILY_DEFINITIONS "POLYPLAN_FAMILIES_LEFT_OUT=\"${left_out}\"")

# polyplan_family_sources(TARGET FAMILY SOURCE...): sources of TARGET compiled only when FAMILY is
# built, recorded for tests/layout/families_left_out.cmake (which lets them include the family).
function(polyplan_family_sources target family)
  list(TRANSFORM ARGN PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/ OUTPUT_VARIABLE sources)
  set_property(GLOBAL APPEND PROPERTY POLYPLAN_FAMILY_ONLY_SOURCES ${sources})
  if(family IN_LIST POLYPLAN_BUILT_FAMILIES)
    target_sources(${target} PRIVATE ${sources})
  endif()
endfunction()
list(LENGTH POLYPLAN_BUILT_FAMILIES built)
list(LENGTH POLYPLAN_OPTIONAL_FAMILIES every)
if(built LESS every)
  message(STATUS "polyplan: the roadmaps and ${POLYPLAN_BUILT_FAMILIES} (POLYPLAN_FAMILIES)")
  # The tests, examples, benchmarks and the Python module exercise every family.
  foreach(part POLYPLAN_BUILD_TESTS POLYPLAN_BUILD_EXAMPLES POLYPLAN_BUILD_BENCH POLYPLAN_PYTHON)
    if(${part})
      message(FATAL_ERROR "${part} needs every planner family: configure with -DPOLYPLAN_FAMILIES=all or -D${part}=OFF")
    endif()
  endforeach()
endif()
