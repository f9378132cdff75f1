# cmake -DSOURCE_DIR=<root> -DGRAPH=<build>/palpate_modules.cmake [-DSTAMP=<file>] -P CheckIncludes.cmake
#
# Fails (listing file:line: include) when a file of a module includes a header of a module in a
# higher layer (PALPATE_LAYERS: base < device < engine < results < report < widgets < app), of a
# module that it does not depend on, directly or transitively, by the graph declared with
# palpate_module (cmake/Modules.cmake), or a project header that belongs to no module. Writes STAMP
# on success.
# Quoted includes only: the project's own headers are included as "folder/File.h" from the root.
cmake_minimum_required(VERSION 3.25)
include("${GRAPH}")

# The module of a path (relative to SOURCE_DIR): the longest declared folder that holds it.
function(module_of path out)
  set(best "")
  string(LENGTH "" bestlen)
  foreach(mod IN LISTS PALPATE_MODULES)
    string(LENGTH "${mod}/" len)
    string(SUBSTRING "${path}" 0 ${len} head)
    if(head STREQUAL "${mod}/" AND len GREATER bestlen)
      set(best "${mod}")
      set(bestlen ${len})
    endif()
  endforeach()
  set(${out} "${best}" PARENT_SCOPE)
endfunction()

set(project_roots ${PALPATE_LAYERS} tests)
list(JOIN PALPATE_LAYERS " < " order)
set(violations "")
set(checked 0)
foreach(mod IN LISTS PALPATE_MODULES)
  string(MAKE_C_IDENTIFIER "${mod}" id)
  set(allowed "${mod}" ${PALPATE_MODULE_CLOSURE_${id}})
  string(REGEX MATCH "^[^/]+" layer "${mod}")
  list(FIND PALPATE_LAYERS "${layer}" rank)
  file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/${mod}/*.h" "${SOURCE_DIR}/${mod}/*.cpp")
  foreach(file IN LISTS files)
    module_of("${file}" owner)
    if(NOT owner STREQUAL mod)
      continue()  # a nested module's file, checked with that module
    endif()
    math(EXPR checked "${checked} + 1")
    file(STRINGS "${SOURCE_DIR}/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"]+\"")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" header "${line}")
      string(REGEX MATCH "^[^/]+" root "${header}")
      if(NOT root IN_LIST project_roots)
        continue()  # not a project header (a generated or third-party one)
      endif()
      module_of("${header}" target)
      list(FIND PALPATE_LAYERS "${root}" header_rank)
      if(target STREQUAL "")
        set(why "belongs to no module")
      elseif(header_rank GREATER rank)
        set(why "${root}/ is a higher layer than ${layer}/ (${order})")
      elseif(target IN_LIST allowed)
        continue()
      else()
        set(why "${mod} does not depend on ${target}")
      endif()
      # The line number: count the newlines before the include.
      file(READ "${SOURCE_DIR}/${file}" text)
      string(FIND "${text}" "\"${header}\"" at)
      string(SUBSTRING "${text}" 0 ${at} before)
      string(REGEX MATCHALL "\n" newlines "${before}")
      list(LENGTH newlines n)
      math(EXPR n "${n} + 1")
      list(APPEND violations "${file}:${n}: #include \"${header}\": ${why}")
    endforeach()
  endforeach()
endforeach()

if(violations)
  list(LENGTH violations count)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "Include check: ${count} include(s) against the module graph "
    "(cmake/Modules.cmake, docs/modules.md):\n  ${text}\n"
    "Include only from the module itself and the modules it depends on; to add a dependency, add it "
    "to the module's palpate_module(... DEPS ...) if that keeps the graph acyclic.")
endif()
message(STATUS "Include check: ${checked} files follow the module graph")
if(STAMP)
  file(TOUCH "${STAMP}")
endif()
