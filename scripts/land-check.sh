#!/usr/bin/env bash
# The land check (docs/testing.md, "The land check"): CI's run as a fresh machine would make it, on
# a used one. A clean clone of the committed HEAD, `.ci/run` under `env -i` with only PATH, an empty
# HOME and TMPDIR, CI=true and no compiler cache; then the clone must hold no file the run wrote
# outside build/, and HOME must still be empty.
#
#   scripts/land-check.sh [--repeat N] [--random] [--keep] [DIR]
#
#   --repeat N  after CI's run, run the whole suite N more times in the same build, each with a
#               new empty HOME and TMPDIR (the suite must pass every time: no retries)
#   --random    then once more with `ctest --schedule-random -j2` (order and parallelism)
#   --keep      keep the clone and its build (default: removed when everything passed)
#   DIR         where to clone (default: a new folder under /tmp)
set -euo pipefail

repeat=0
random=0
keep=0
dir=""
while [ $# -gt 0 ]; do
  case "$1" in
    --repeat) repeat="${2:?--repeat needs a count}"; shift 2 ;;
    --random) random=1; shift ;;
    --keep) keep=1; shift ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "land-check: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) dir="$1"; shift ;;
  esac
done
case "$repeat" in ''|*[!0-9]*) echo "land-check: --repeat takes a whole number, not '$repeat'" >&2; exit 2 ;; esac

source_dir="$(cd "$(dirname "$0")/.." && pwd)"
if [ -n "$(git -C "$source_dir" status --porcelain --untracked-files=no)" ]; then
  echo "land-check: note: uncommitted changes in $source_dir are not checked (only HEAD is cloned)" >&2
fi
[ -n "$dir" ] || dir="$(mktemp -d /tmp/palpate-landcheck.XXXXXX)"
if [ -e "$dir" ] && [ -n "$(ls -A "$dir" 2>/dev/null)" ]; then
  echo "land-check: $dir is not empty; name a new folder" >&2
  exit 2
fi
git clone -q "$source_dir" "$dir"
echo "land-check: $(git -C "$dir" log -1 --format='%h %s') in $dir"

fresh_path=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
# Runs a command as a fresh machine's CI would: nothing inherited but PATH, an empty HOME and TMPDIR.
# Afterwards HOME must still be empty: no test writes to the user's home (docs/testing.md).
fresh() {
  local home tmp status=0 left
  home="$(mktemp -d /tmp/palpate-landcheck-home.XXXXXX)"
  tmp="$(mktemp -d /tmp/palpate-landcheck-tmp.XXXXXX)"
  (cd "$dir" && env -i PATH="$fresh_path" HOME="$home" TMPDIR="$tmp" CI=true CCACHE_DISABLE=1 "$@") || status=$?
  left="$(cd "$home" && find . -mindepth 1 -maxdepth 3 | head -20)"
  if [ -n "$left" ]; then
    echo "land-check: the run wrote into its HOME:" >&2
    echo "$left" >&2
    status=1
  fi
  left="$(cd "$tmp" && find . -mindepth 1 -maxdepth 1 | head -20)"
  [ -z "$left" ] || { echo "land-check: note: left in TMPDIR:"; echo "$left"; } >&2
  rm -rf "$home" "$tmp"
  return "$status"
}

started=$(date +%s)
fresh bash .ci/run
echo "land-check: CI's run passed in $(( $(date +%s) - started )) s"

for i in $(seq 1 "$repeat"); do
  t=$(date +%s)
  fresh ctest --preset default -j "$(nproc)" --timeout 600
  echo "land-check: repeat $i of $repeat passed in $(( $(date +%s) - t )) s"
done
if [ "$random" -eq 1 ]; then
  t=$(date +%s)
  fresh ctest --preset default --schedule-random -j2 --timeout 600
  echo "land-check: random order with -j2 passed in $(( $(date +%s) - t )) s"
fi

# No test writes into the source tree (docs/bench/, resources/, ...): only build/ may change.
changed="$(git -C "$dir" status --porcelain --ignored | grep -v '^!! build/$' || true)"
if [ -n "$changed" ]; then
  echo "land-check: the run changed the source tree:" >&2
  echo "$changed" >&2
  exit 1
fi
echo "land-check: passed in $(( $(date +%s) - started )) s; the source tree and HOME are as they were"
[ "$keep" -eq 1 ] || rm -rf "$dir"
