#!/usr/bin/env bash
# Installs what is missing, builds Palpate and runs it on its default scene with the simulated
# device. Without a display it runs headless: the same scene in the command-line demo, and a
# screenshot from the software renderer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset default
cmake --build --preset default -j "$(nproc)"
bin=build/release/app
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  # The scripted stroke shows the method at once; without --device the window starts in touch mode.
  exec "$bin/gui/palpate" --device sim:stroke "$@"
fi
echo "No display found: running headless."
"$bin/palpate-cli" demo
shot="build/release/palpate-headless.png"
QT_QPA_PLATFORM=offscreen "$bin/gui/palpate" --device sim:stroke --software-render --screenshot "$shot" "$@"
echo "Rendered the default scene with the software renderer to $shot"
