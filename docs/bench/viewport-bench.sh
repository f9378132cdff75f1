#!/usr/bin/env bash
# Frame rate of the main window while sim:sine keeps pressing (palpate --benchmark-viewport), for
# the Table 1 meshes and the generated 100k-vertex sphere, with each renderer configuration, in one
# run; writes docs/bench/viewport.csv. The baseline is the old default's renderer settings on this
# machine (OpenGL with 4x multisampling, forced here with --opengl-render PALPATE_GL_SAMPLES=4):
# fps_vs_old is each row's fps over that row's of the same mesh and repetition.
#
#   docs/bench/viewport-bench.sh            (SECONDS_EACH=4 REPS=2 by default)
#
# Needs xvfb-run (no display needed) and a Release build in build/release.
set -euo pipefail
cd "$(dirname "$0")/../.."
BIN=build/release/app/gui/palpate
OUT=docs/bench/viewport.csv
SECONDS_EACH=${SECONDS_EACH:-4}
REPS=${REPS:-2}
MESHES=(resources/meshes/sphere_1442.off resources/meshes/sphere_3970.off resources/meshes/sphere_5762.off
        resources/meshes/sphere_8664.off resources/meshes/stomach_1442.off resources/meshes/stomach_3970.off
        resources/meshes/stomach_5762.off resources/meshes/stomach_8664.off generated-sphere-100000)
# name|environment|options
CONFIGS=("auto||" "software||--software-render" "opengl_no_msaa|PALPATE_GL_SAMPLES=0|--opengl-render"
         "old_opengl_4x|PALPATE_GL_SAMPLES=4|--opengl-render")
export HOME=${BENCH_HOME:-/tmp/palpate-bench-home}  # a fresh window state, not the user's
mkdir -p "$HOME"
RAW=$(mktemp)
echo "run_utc,rep,mesh,config,renderer,samples,vertices,seconds,frames,fps,mean_frame_ms,p95_frame_ms,gui_cpu_ms_per_frame,load_1min" > "$RAW"
for rep in $(seq 1 "$REPS"); do
  for mesh in "${MESHES[@]}"; do
    for config in "${CONFIGS[@]}"; do
      IFS='|' read -r name environment options <<< "$config"
      meshArg=()
      [[ "$mesh" == generated-* ]] || meshArg=(--mesh "$mesh")
      line=$(env $environment timeout 180 xvfb-run -a -s "-screen 0 1600x1000x24" "$BIN" --benchmark-viewport \
               --seconds "$SECONDS_EACH" "${meshArg[@]}" $options 2>/dev/null | grep '^frames=' || true)
      get() { sed -n "s/.*\<$1=\([^ ]*\).*/\1/p" <<< "$line"; }
      echo "$(date -u +%FT%TZ),$rep,$(basename "$mesh"),$name,$(get renderer),$(get samples),$(get vertices),$SECONDS_EACH,$(get frames),$(get fps),$(get mean_frame_ms),$(get p95_frame_ms),$(get gui_cpu_ms_per_frame),$(get load)" | tee -a "$RAW"
    done
  done
done
python3 - "$RAW" "$OUT" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
base = {(r["rep"], r["mesh"]): r["fps"] for r in rows if r["config"] == "old_opengl_4x"}
with open(sys.argv[2], "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(list(rows[0].keys()) + ["fps_vs_old"])
    for r in rows:
        b = base.get((r["rep"], r["mesh"]), "")
        ratio = "%.2f" % (float(r["fps"]) / float(b)) if r["fps"] and b and float(b) > 0 else ""
        w.writerow(list(r.values()) + [ratio])
PY
rm -f "$RAW"
echo "wrote $OUT"
