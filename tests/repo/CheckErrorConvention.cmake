# Fails where the code drifts from the error convention (docs/conventions.md, "Errors"):
#   - a validator (validate*) that returns anything but Problems;
#   - a function that returns bool and reports why through a std::string& out-parameter (an action
#     that can fail returns the problem as std::string, empty on success);
#   - an error out-parameter spelled other than `error` (why, problem, message, reason, err).
#
#   cmake -DROOT=<source dir> -P tests/repo/CheckErrorConvention.cmake
# -DROOT may also point at a tree made to show the check failing (tests/repo/errors/).
cmake_minimum_required(VERSION 3.20)
if(NOT DEFINED ROOT OR NOT IS_DIRECTORY "${ROOT}")
  message(FATAL_ERROR "CheckErrorConvention: pass the source directory as -DROOT=<dir>")
endif()
set(hits "")
set(count 0)
# A parameter list without nested parentheses or braces; CMake's regex has no \b, so names are
# matched from a space or an opening parenthesis.
set(params "[^;{}()]*")
foreach(dir base device engine results report widgets app)
  file(GLOB_RECURSE files "${ROOT}/${dir}/*.h" "${ROOT}/${dir}/*.cpp")
  foreach(file IN LISTS files)
    math(EXPR count "${count} + 1")
    file(READ "${file}" text)
    # Semicolons would split the text into a CMake list: the patterns never need them.
    string(REPLACE ";" "\n" text "${text}")
    file(RELATIVE_PATH rel "${ROOT}" "${file}")
    string(REGEX MATCHALL "(std::string|std::vector<std::string>|const char ?\\*|bool) validate[A-Z][A-Za-z0-9_]*\\(" found "${text}")
    foreach(f IN LISTS found)
      string(APPEND hits "  ${rel}: a validator must return Problems: ${f}...\n")
    endforeach()
    string(REGEX MATCHALL "bool [A-Za-z0-9_:~]+\\((${params},)?[ \n]*std::string ?[&*] ?(error|why|problem|message|reason|err)[,) ]" found "${text}")
    foreach(f IN LISTS found)
      string(REGEX REPLACE "[ \n]+" " " f "${f}")
      string(APPEND hits "  ${rel}: return the problem as std::string instead of bool + out-parameter: ${f}\n")
    endforeach()
    string(REGEX MATCHALL "[(,][ \n]*std::string ?[&*] ?(why|problem|message|reason|err|errorOut|errorMessage)[,)= ]" found "${text}")
    foreach(f IN LISTS found)
      string(REGEX REPLACE "[ \n]+" " " f "${f}")
      string(APPEND hits "  ${rel}: name the error out-parameter `error`: ${f}\n")
    endforeach()
  endforeach()
endforeach()
if(hits)
  message(FATAL_ERROR "the error convention is not followed (docs/conventions.md, \"Errors\"):\n${hits}")
endif()
message(STATUS "error_convention: ${count} files read, validators return Problems, fallible actions return std::string")
