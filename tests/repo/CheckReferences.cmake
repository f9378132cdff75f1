# Fails when a source, CMake, script, test or docs file cites a document a reader of the repository
# does not have: the design notes ("DESIGN §3", "DESIGN.md", "DESIGN section 7", "the DESIGN's")
# or an issue number ("issue 12", "Issue 8", "issues 7 and 8"). Comments cite docs/ pages instead.
# "#12" and "issue" without a number ("to issue a command") are not flagged.
#
#   cmake -DROOT=<source dir> -P tests/repo/CheckReferences.cmake
#
# Lists every hit as file:line: text and exits non-zero; prints the number of files read otherwise.
cmake_minimum_required(VERSION 3.20)

if(NOT DEFINED ROOT OR NOT IS_DIRECTORY "${ROOT}")
  message(FATAL_ERROR "CheckReferences: pass the source directory as -DROOT=<dir>")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
get_filename_component(SELF "${CMAKE_CURRENT_LIST_FILE}" ABSOLUTE)

# What is scanned: these folders (recursively) and files, relative to ROOT.
set(scan_dirs base device engine results report widgets app cmake tests scripts packaging resources docs)
set(scan_globs translations/*.cmake translations/*.md README.md CMakeLists.txt)
# Binary and bulk data formats: never read.
set(skip_ext_regex "\\.(png|jpe?g|gif|ico|pdf|qm|palprec|off|obj|ply|stl|om|sqlite|db|gz|xz|zip|deb|so|a|o)$")

# A citation, on one line. CMake regexes have no word boundaries, hence the explicit classes.
set(w "A-Za-z0-9_")
set(patterns
  "DESIGN[ ]*§"                            # DESIGN §3, DESIGN§3
  "DESIGN\\.md"                            # DESIGN.md, DESIGN.md's
  "DESIGN[ ]+[Ss]ection"                   # DESIGN section 7
  "(^|[^${w}])DESIGN([^${w}]|$)"           # the DESIGN's, (DESIGN: 5), DESIGN 3
  "(^|[^A-Za-z])[Ii]ssues?[ ]+[0-9]"       # issue 12, Issue 8, issues 7 and 8, Issue 8/9 (not "tissue 26")
  "(^|[^A-Za-z])ISSUES?[ ]+[0-9]"          # ISSUE 4
)
string(JOIN "|" any_pattern ${patterns})

set(files "")
foreach(dir IN LISTS scan_dirs)
  if(IS_DIRECTORY "${ROOT}/${dir}")
    file(GLOB_RECURSE found LIST_DIRECTORIES false "${ROOT}/${dir}/*")
    list(APPEND files ${found})
  endif()
endforeach()
foreach(glob IN LISTS scan_globs)
  file(GLOB found LIST_DIRECTORIES false "${ROOT}/${glob}")
  list(APPEND files ${found})
endforeach()
list(REMOVE_DUPLICATES files)
list(SORT files)

set(hits "")
set(read_count 0)
foreach(path IN LISTS files)
  file(RELATIVE_PATH rel "${ROOT}" "${path}")
  if(path STREQUAL SELF)
    continue()
  endif()
  if(rel MATCHES "(^|/)build[^/]*/" OR rel MATCHES "(^|/)\\.git/")
    continue()
  endif()
  string(TOLOWER "${rel}" rel_lower)
  if(rel_lower MATCHES "${skip_ext_regex}")
    continue()
  endif()
  # Binary: a NUL byte in the first 4 KiB (an even offset of the hex dump).
  file(READ "${path}" head LIMIT 4096 HEX)
  set(binary FALSE)
  set(from 0)
  while(TRUE)
    string(SUBSTRING "${head}" ${from} -1 rest)
    string(FIND "${rest}" "00" at)
    if(at EQUAL -1)
      break()
    endif()
    math(EXPR at "${from} + ${at}")
    math(EXPR parity "${at} % 2")
    if(parity EQUAL 0)
      set(binary TRUE)
      break()
    endif()
    math(EXPR from "${at} + 1")
  endwhile()
  if(binary)
    continue()
  endif()

  math(EXPR read_count "${read_count} + 1")
  file(READ "${path}" content)
  if(NOT content MATCHES "${any_pattern}")
    continue()
  endif()
  # Split into lines. List separators and brackets (which CMake's list splitting honours) and
  # backslashes (which would escape the separator) are replaced first, and put back when printed.
  string(REPLACE "\r" "" content "${content}")
  string(REPLACE "\\" "<BSL>" content "${content}")
  string(REPLACE ";" "<SEMI>" content "${content}")
  string(REPLACE "[" "<LBR>" content "${content}")
  string(REPLACE "]" "<RBR>" content "${content}")
  string(REPLACE "\n" ";" lines "${content}")
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    foreach(pattern IN LISTS patterns)
      if(line MATCHES "${pattern}")
        string(STRIP "${line}" shown)
        list(APPEND hits "${rel}:${number}: ${shown}")  # still escaped: see the report below
        break()
      endif()
    endforeach()
  endforeach()
endforeach()

list(LENGTH hits hit_count)
if(hit_count GREATER 0)
  foreach(hit IN LISTS hits)
    string(REPLACE "<BSL>" "\\" hit "${hit}")
    string(REPLACE "<SEMI>" ";" hit "${hit}")
    string(REPLACE "<LBR>" "[" hit "${hit}")
    string(REPLACE "<RBR>" "]" hit "${hit}")
    message("${hit}")
  endforeach()
  message(FATAL_ERROR "${hit_count} line(s) cite the design notes or an issue number; cite the docs/ page "
                      "that explains the point instead (and write it there if it is missing).")
endif()
message(STATUS "no_outside_references: ${read_count} files read, no DESIGN or issue-number citations")
