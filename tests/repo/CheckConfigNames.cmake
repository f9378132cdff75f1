# Fails when a configuration struct is named other than *Params (a model's parameter set with a
# field table) or *Def (anything else that is built or run): no *Options, *Config or *Settings
# structs (docs/conventions.md).
#
#   cmake -DROOT=<source dir> -P tests/repo/CheckConfigNames.cmake
cmake_minimum_required(VERSION 3.20)
if(NOT DEFINED ROOT OR NOT IS_DIRECTORY "${ROOT}")
  message(FATAL_ERROR "CheckConfigNames: pass the source directory as -DROOT=<dir>")
endif()
set(hits "")
set(count 0)
foreach(dir base device engine results report widgets app)
  file(GLOB_RECURSE files "${ROOT}/${dir}/*.h" "${ROOT}/${dir}/*.cpp")
  foreach(file IN LISTS files)
    math(EXPR count "${count} + 1")
    file(STRINGS "${file}" lines REGEX "(struct|class)[ ]+[A-Za-z0-9_]+(Options|Config|Settings)[ ]*[{:;]")
    foreach(line IN LISTS lines)
      file(RELATIVE_PATH rel "${ROOT}" "${file}")
      string(APPEND hits "  ${rel}: ${line}\n")
    endforeach()
  endforeach()
endforeach()
if(hits)
  message(FATAL_ERROR "configuration structs must be *Params or *Def (docs/conventions.md):\n${hits}")
endif()
message(STATUS "configuration_names: ${count} files read, every configuration struct is *Params or *Def")
