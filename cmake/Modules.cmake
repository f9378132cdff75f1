# Modules: each source folder of engine/, device/, app/ and widgets/ is one library target whose
# module dependencies are declared here, one way only (docs/modules.md, "Engine modules").
#
#   palpate_module(<folder> TARGET <target> [DEPS <folder>...] [PRIVATE_DEPS <folder>...])
#
# declares the module <folder> (relative to the source root, e.g. engine/core) built as <target>
# (created by the caller: add_library/add_executable). At the end of configure
# (palpate_modules_finish, deferred to the end of the top-level CMakeLists.txt):
#   - each target is linked with its module deps' targets (DEPS PUBLIC, PRIVATE_DEPS PRIVATE; an
#     INTERFACE target links INTERFACE);
#   - the declared module graph must be acyclic: a cycle is a configure error naming it;
#   - the graph's transitive closure is written for cmake/CheckIncludes.cmake, which fails the build
#     (target palpate_include_check, in ALL) and the include_check test when a file of a module
#     includes a header of a module it does not (transitively) depend on.
# A file belongs to the module of the longest declared folder that holds it (engine/models/slopering/
# is part of engine/models; device/hid/ is its own module beside device/).

# The layers, bottom-up (docs/architecture.md): a module is in the layer its first folder names, and
# may depend on modules of its own layer and the layers below, never above. Configure refuses a
# declared dep that runs up; the include check refuses an include that does.
set(PALPATE_LAYERS base device engine results report widgets app)

set_property(GLOBAL PROPERTY PALPATE_MODULES "")
# Targets that link many modules for the callers (palpate_engine, palpate_device); no module links them.
set_property(GLOBAL PROPERTY PALPATE_MODULE_AGGREGATES palpate_engine palpate_device)

function(palpate_module folder)
  cmake_parse_arguments(PARSE_ARGV 1 M "" "TARGET" "DEPS;PRIVATE_DEPS")
  if(NOT M_TARGET)
    message(FATAL_ERROR "palpate_module(${folder}): TARGET missing")
  endif()
  string(MAKE_C_IDENTIFIER "${folder}" id)
  get_property(known GLOBAL PROPERTY PALPATE_MODULES)
  if(folder IN_LIST known)
    message(FATAL_ERROR "palpate_module(${folder}): declared twice")
  endif()
  set_property(GLOBAL APPEND PROPERTY PALPATE_MODULES "${folder}")
  set_property(GLOBAL PROPERTY PALPATE_MODULE_TARGET_${id} "${M_TARGET}")
  set_property(GLOBAL PROPERTY PALPATE_MODULE_DEPS_${id} "${M_DEPS}")
  set_property(GLOBAL PROPERTY PALPATE_MODULE_PRIVATE_DEPS_${id} "${M_PRIVATE_DEPS}")
endfunction()

# Depth-first search from `mod`; `path` is the chain of modules that led to it.
function(_palpate_module_dfs mod path)
  string(MAKE_C_IDENTIFIER "${mod}" id)
  get_property(color GLOBAL PROPERTY PALPATE_MODULE_COLOR_${id})
  if(color STREQUAL "done")
    return()
  endif()
  if(color STREQUAL "open")
    list(FIND path "${mod}" at)
    list(SUBLIST path ${at} -1 cycle)
    list(APPEND cycle "${mod}")
    list(JOIN cycle " -> " text)
    message(FATAL_ERROR "Module dependency cycle: ${text}\n"
      "(declared with palpate_module in the folders' CMakeLists.txt; links go one way only, see docs/modules.md)")
  endif()
  set_property(GLOBAL PROPERTY PALPATE_MODULE_COLOR_${id} "open")
  get_property(deps GLOBAL PROPERTY PALPATE_MODULE_DEPS_${id})
  get_property(pdeps GLOBAL PROPERTY PALPATE_MODULE_PRIVATE_DEPS_${id})
  set(closure "")
  foreach(dep IN LISTS deps pdeps)
    _palpate_module_dfs("${dep}" "${path};${mod}")
    string(MAKE_C_IDENTIFIER "${dep}" did)
    get_property(dclosure GLOBAL PROPERTY PALPATE_MODULE_CLOSURE_${did})
    list(APPEND closure "${dep}" ${dclosure})
  endforeach()
  list(REMOVE_DUPLICATES closure)
  set_property(GLOBAL PROPERTY PALPATE_MODULE_CLOSURE_${id} "${closure}")
  set_property(GLOBAL PROPERTY PALPATE_MODULE_COLOR_${id} "done")
endfunction()

function(palpate_modules_finish)
  get_property(modules GLOBAL PROPERTY PALPATE_MODULES)
  # Every dep must be a declared module.
  foreach(mod IN LISTS modules)
    string(MAKE_C_IDENTIFIER "${mod}" id)
    get_property(deps GLOBAL PROPERTY PALPATE_MODULE_DEPS_${id})
    get_property(pdeps GLOBAL PROPERTY PALPATE_MODULE_PRIVATE_DEPS_${id})
    foreach(dep IN LISTS deps pdeps)
      if(NOT dep IN_LIST modules)
        message(FATAL_ERROR "palpate_module(${mod}): dep ${dep} is not a declared module")
      endif()
    endforeach()
  endforeach()
  # Every dep is in the module's layer or below.
  foreach(mod IN LISTS modules)
    string(MAKE_C_IDENTIFIER "${mod}" id)
    get_property(deps GLOBAL PROPERTY PALPATE_MODULE_DEPS_${id})
    get_property(pdeps GLOBAL PROPERTY PALPATE_MODULE_PRIVATE_DEPS_${id})
    string(REGEX MATCH "^[^/]+" layer "${mod}")
    list(FIND PALPATE_LAYERS "${layer}" rank)
    if(rank LESS 0)
      message(FATAL_ERROR "palpate_module(${mod}): ${layer}/ is not a layer (${PALPATE_LAYERS}; cmake/Modules.cmake)")
    endif()
    foreach(dep IN LISTS deps pdeps)
      string(REGEX MATCH "^[^/]+" dlayer "${dep}")
      list(FIND PALPATE_LAYERS "${dlayer}" drank)
      if(drank GREATER rank)
        list(JOIN PALPATE_LAYERS " < " order)
        message(FATAL_ERROR "palpate_module(${mod}): the dep ${dep} runs up the layers (${order}; docs/architecture.md)")
      endif()
    endforeach()
  endforeach()
  # No module target links another module (or an aggregate of them: palpate_engine, palpate_device)
  # by hand: module links come from the declared deps only, so the graph below is the whole story.
  set(module_targets "")
  foreach(mod IN LISTS modules)
    string(MAKE_C_IDENTIFIER "${mod}" id)
    get_property(target GLOBAL PROPERTY PALPATE_MODULE_TARGET_${id})
    list(APPEND module_targets ${target})
  endforeach()
  get_property(aggregates GLOBAL PROPERTY PALPATE_MODULE_AGGREGATES)
  foreach(mod IN LISTS modules)
    string(MAKE_C_IDENTIFIER "${mod}" id)
    get_property(target GLOBAL PROPERTY PALPATE_MODULE_TARGET_${id})
    get_target_property(type ${target} TYPE)
    set(links "")
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(links ${target} LINK_LIBRARIES)
    endif()
    get_target_property(ilinks ${target} INTERFACE_LINK_LIBRARIES)
    foreach(link IN LISTS links ilinks)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
      if(link IN_LIST module_targets OR link IN_LIST aggregates)
        message(FATAL_ERROR "Module ${mod} (${target}) links ${link} by hand: declare the module dep "
          "in palpate_module(${mod} ... DEPS ...) instead (cmake/Modules.cmake, docs/modules.md)")
      endif()
    endforeach()
  endforeach()
  # Acyclic (DFS from every module), with each module's transitive closure.
  foreach(mod IN LISTS modules)
    _palpate_module_dfs("${mod}" "")
  endforeach()
  # Link each target with its module deps' targets.
  set(graph "# Generated by cmake/Modules.cmake: the declared modules and their transitive deps.\n")
  string(APPEND graph "set(PALPATE_MODULES \"${modules}\")\n")
  string(APPEND graph "set(PALPATE_LAYERS \"${PALPATE_LAYERS}\")\n")
  foreach(mod IN LISTS modules)
    string(MAKE_C_IDENTIFIER "${mod}" id)
    get_property(target GLOBAL PROPERTY PALPATE_MODULE_TARGET_${id})
    get_property(deps GLOBAL PROPERTY PALPATE_MODULE_DEPS_${id})
    get_property(pdeps GLOBAL PROPERTY PALPATE_MODULE_PRIVATE_DEPS_${id})
    get_target_property(type ${target} TYPE)
    foreach(kind IN ITEMS PUBLIC PRIVATE)
      if(kind STREQUAL "PUBLIC")
        set(list ${deps})
      else()
        set(list ${pdeps})
      endif()
      if(type STREQUAL "INTERFACE_LIBRARY")
        set(kind INTERFACE)
      endif()
      foreach(dep IN LISTS list)
        string(MAKE_C_IDENTIFIER "${dep}" did)
        get_property(dtarget GLOBAL PROPERTY PALPATE_MODULE_TARGET_${did})
        target_link_libraries(${target} ${kind} ${dtarget})
      endforeach()
    endforeach()
    get_property(closure GLOBAL PROPERTY PALPATE_MODULE_CLOSURE_${id})
    string(APPEND graph "set(PALPATE_MODULE_CLOSURE_${id} \"${closure}\")\n")
  endforeach()
  set(graph_file "${CMAKE_BINARY_DIR}/palpate_modules.cmake")
  file(CONFIGURE OUTPUT "${graph_file}" CONTENT "${graph}")

  # The include check: at build time (ALL, re-run when a module's file changes) and as a test.
  set(files "")
  foreach(mod IN LISTS modules)
    file(GLOB_RECURSE mfiles CONFIGURE_DEPENDS
      "${PROJECT_SOURCE_DIR}/${mod}/*.h" "${PROJECT_SOURCE_DIR}/${mod}/*.cpp")
    list(APPEND files ${mfiles})
  endforeach()
  list(REMOVE_DUPLICATES files)
  set(script "${PROJECT_SOURCE_DIR}/cmake/CheckIncludes.cmake")
  set(stamp "${CMAKE_BINARY_DIR}/palpate_include_check.stamp")
  add_custom_command(OUTPUT "${stamp}"
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DGRAPH=${graph_file} -DSTAMP=${stamp}
            -P "${script}"
    DEPENDS "${script}" "${graph_file}" ${files}
    COMMENT "Checking that every include follows the module graph (cmake/Modules.cmake)"
    VERBATIM)
  add_custom_target(palpate_include_check ALL DEPENDS "${stamp}")
  if(PALPATE_BUILD_TESTS)
    add_test(NAME include_check
      COMMAND ${PALPATE_TEST_WRAPPER} ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DGRAPH=${graph_file} -P "${script}")
  endif()
endfunction()

cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL palpate_modules_finish)

# palpate_library_module(<folder> <target> [SOURCES <file>...] [DEPS <folder>...] [PRIVATE_DEPS <folder>...])
# The Qt-free folder <folder> (base/<name> or engine/<name>) as <target>: STATIC, or INTERFACE when it
# has headers only; the source root on the include path, as every include is "folder/File.h".
function(palpate_library_module folder target)
  cmake_parse_arguments(PARSE_ARGV 2 M "" "" "SOURCES;DEPS;PRIVATE_DEPS")
  set(compiled ${M_SOURCES})
  list(FILTER compiled INCLUDE REGEX "\\.cpp$")
  if(compiled)
    add_library(${target} STATIC ${M_SOURCES})
    target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR})
    target_compile_definitions(${target} PUBLIC GLM_FORCE_XYZW_ONLY)
  else()
    add_library(${target} INTERFACE ${M_SOURCES})
    target_include_directories(${target} INTERFACE ${PROJECT_SOURCE_DIR})
    target_compile_definitions(${target} INTERFACE GLM_FORCE_XYZW_ONLY)
  endif()
  palpate_module(${folder} TARGET ${target} DEPS ${M_DEPS} PRIVATE_DEPS ${M_PRIVATE_DEPS})
endfunction()

# palpate_engine_module(<name> ...): engine/<name> as palpate_engine_<name> (palpate_library_module).
function(palpate_engine_module name)
  palpate_library_module(engine/${name} palpate_engine_${name} ${ARGN})
endfunction()

# palpate_base_module(<name> ...): base/<name> as palpate_base_<name> (palpate_library_module).
function(palpate_base_module name)
  palpate_library_module(base/${name} palpate_base_${name} ${ARGN})
endfunction()
