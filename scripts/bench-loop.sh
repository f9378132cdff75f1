#!/usr/bin/env bash
# Measures the haptic loop at 1, 4 and 10 kHz on this machine and writes docs/bench/loop.csv.
# Run it on an otherwise idle machine: jitter is what the scheduler gives us.
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${PALPATE_CLI:-build/release/app/palpate-cli}
out=docs/bench/loop.csv
rm -f "$out"
"$cli" loop --rate 1000 --seconds "${SECONDS_1K:-60}" --csv "$out"
"$cli" loop --rate 4000 --seconds "${SECONDS_FAST:-20}" --csv "$out"
"$cli" loop --rate 10000 --seconds "${SECONDS_FAST:-20}" --csv "$out"
cat "$out"
