#!/bin/sh
# Counts the fault-injection cases per family from the test binary's own tables (the counts in
# docs/reliability.md come from here): tests/fault/count_cases.sh build/release/tests/fault/fault_tests
set -eu
binary=${1:-build/release/tests/fault/fault_tests}
"$binary" --gtest_list_tests | awk '
  /^[^ ]/ { family = $0; sub(/\/.*/, "", family); next }
  /^  /   { count[family]++; total++ }
  END     { for (f in count) printf "%s %d\n", f, count[f]; printf "total %d\n", total }' | sort
