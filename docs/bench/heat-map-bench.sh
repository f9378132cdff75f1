#!/usr/bin/env bash
# Frame rate of the main window with the coverage heat map over every vertex (as after a whole
# surface was examined: palpate --benchmark-viewport --heat-map) against the same window without
# it, in one run, for both renderers; writes docs/bench/heat_map.csv. fps_vs_no_heat is each
# row's fps over that of the same mesh, renderer and repetition without the heat map. The view
# stands still while sim:sine presses (the heat map is redrawn when the camera turns).
#
#   docs/bench/heat-map-bench.sh            (SECONDS_EACH=4 REPS=2 by default)
#
# Needs xvfb-run (no display needed) and a Release build in build/release.
set -euo pipefail
cd "$(dirname "$0")/../.."
BIN=build/release/app/gui/palpate
OUT=docs/bench/heat_map.csv
SECONDS_EACH=${SECONDS_EACH:-4}
REPS=${REPS:-2}
MESHES=(resources/meshes/sphere_8664.off resources/meshes/stomach_8664.off)
export HOME=${BENCH_HOME:-/tmp/palpate-bench-home}
mkdir -p "$HOME"
echo "run_utc,rep,mesh,renderer,heat_points,fps,mean_frame_ms,gui_cpu_ms_per_frame,load_1min,fps_vs_no_heat" > "$OUT"
for rep in $(seq 1 "$REPS"); do
  for mesh in "${MESHES[@]}"; do
    for renderer in --software-render --opengl-render; do
      base=""
      for heat in "" --heat-map; do
        line=$(timeout 180 xvfb-run -a -s "-screen 0 1600x1000x24" "$BIN" --benchmark-viewport --seconds "$SECONDS_EACH" \
                 --mesh "$mesh" $renderer $heat 2>/dev/null | grep '^frames=' || true)
        get() { sed -n "s/.*\<$1=\([^ ]*\).*/\1/p" <<< "$line"; }
        fps=$(get fps)
        [[ -z "$heat" ]] && base=$fps
        ratio=$(python3 -c "print(f'{float(\"$fps\")/float(\"$base\"):.2f}')" 2>/dev/null || echo "")
        echo "$(date -u +%FT%TZ),$rep,$(basename "$mesh"),$(get renderer),$(get heat_points),$fps,$(get mean_frame_ms),$(get gui_cpu_ms_per_frame),$(get load),$ratio" | tee -a "$OUT"
      done
    done
  done
done
