# Fails when a test does not start through the hermetic launcher, which gives it its own empty HOME,
# XDG folders and TMPDIR, a fixed locale, time zone and fonts (docs/testing.md, "Hermetic tests").
# Reads every test's command from CTest itself, so a test added any way at all is seen.
#
#   cmake -DBUILD_DIR=<build dir> -DWRAPPER=<launcher> -DCTEST=<ctest> -P tests/repo/CheckHermetic.cmake
cmake_minimum_required(VERSION 3.20)
foreach(var BUILD_DIR WRAPPER CTEST)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CheckHermetic: pass -D${var}=...")
  endif()
endforeach()
execute_process(COMMAND "${CTEST}" -N -V WORKING_DIRECTORY "${BUILD_DIR}"
                OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "CheckHermetic: ctest -N -V failed in ${BUILD_DIR} (${rc})")
endif()
string(REGEX MATCHALL "[0-9]+: Test command: [^\n]*" commands "${listing}")
string(REGEX MATCHALL "  Test +#[0-9]+: [^\n]*" names "${listing}")
list(LENGTH commands count)
list(LENGTH names tests)
if(count EQUAL 0 OR NOT count EQUAL tests)
  message(FATAL_ERROR "CheckHermetic: ${tests} tests listed but ${count} commands read from ctest -N -V")
endif()
set(bad "")
foreach(line IN LISTS commands)
  string(REGEX REPLACE "^[0-9]+: Test command: " "" command "${line}")
  string(FIND "${command}" "${WRAPPER} " at)
  if(NOT at EQUAL 0)
    string(APPEND bad "  ${line}\n")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "these tests do not start through ${WRAPPER} (set the target's launcher, or name "
                      "\${PALPATE_TEST_WRAPPER} first in add_test):\n${bad}")
endif()
message(STATUS "every_test_is_hermetic: all ${count} tests start through the hermetic launcher")
