#!/usr/bin/env bash
# Renders resources/icons/org.palpate.Palpate.svg into the committed PNG sizes
# (resources/icons/hicolor/NxN/apps/org.palpate.Palpate.png). Run after editing the SVG; needs
# rsvg-convert (Debian: librsvg2-bin, in scripts/install-deps.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)/resources/icons"
for size in 16 24 32 48 64 128 256; do
  mkdir -p "$here/hicolor/${size}x${size}/apps"
  rsvg-convert -w "$size" -h "$size" "$here/org.palpate.Palpate.svg" \
    -o "$here/hicolor/${size}x${size}/apps/org.palpate.Palpate.png"
done
echo "render-icons: wrote $(ls "$here"/hicolor/*/apps/*.png | wc -l) PNGs under $here/hicolor"
