#!/usr/bin/env bash
# Builds the Debian package of an already built tree (cpack -G DEB), checks its file list and its
# declared dependencies, unpacks it and runs the unpacked binaries: palpate-cli --version, and
# palpate --headless, which must find the default mesh in the unpacked share/palpate (not in the
# source tree). Usage: check_package.sh BUILD_DIR. Exit 0 when everything is there.
set -euo pipefail
build="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/palpate-package.XXXXXX")"
trap 'rm -rf "$work"' EXIT

cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work/out" >"$work/cpack.log" 2>&1 || {
  cat "$work/cpack.log"; echo "FAIL: cpack -G DEB"; exit 1; }
deb="$(ls "$work"/out/palpate_*.deb 2>/dev/null | head -n1)"
[ -n "$deb" ] || { cat "$work/cpack.log"; echo "FAIL: no palpate_*.deb in $work/out"; exit 1; }
echo "package: $(basename "$deb") ($(stat -c %s "$deb") bytes)"

dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./|/|' >"$work/files"
failures=0
expect() {
  if grep -qx -- "$1" "$work/files"; then echo "ok: $1"; else echo "FAIL: missing $1"; failures=$((failures + 1)); fi
}
expect /usr/bin/palpate
expect /usr/bin/palpate-cli
expect /usr/share/applications/org.palpate.Palpate.desktop
expect /usr/share/metainfo/org.palpate.Palpate.metainfo.xml
expect /usr/share/icons/hicolor/scalable/apps/org.palpate.Palpate.svg
for size in 16 24 32 48 64 128 256; do
  expect "/usr/share/icons/hicolor/${size}x${size}/apps/org.palpate.Palpate.png"
done
expect /usr/share/palpate/meshes/stomach_3970.off
expect /usr/share/palpate/presets/default.json
expect /usr/share/palpate/presets/tissues/phantom_gel.json
expect /usr/share/palpate/exercises/press_targets.json
expect /usr/share/doc/palpate/user-guide.md
expect /usr/share/doc/palpate/copyright
expect /usr/share/doc/palpate/guide/welcome.png
# Every udev rule of the source tree, whatever the device work ships.
src="$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")"
rules=0
for rule in "$src"/resources/udev/*.rules; do
  expect "/usr/lib/udev/rules.d/$(basename "$rule")"
  rules=$((rules + 1))
done
[ "$rules" -gt 0 ] || { echo "FAIL: no udev rules in $src/resources/udev"; failures=$((failures + 1)); }

depends="$(dpkg-deb -f "$deb" Depends)"
echo "Depends: $depends"
for dep in libqt6widgets6 libqt6opengl6 libqt6charts6 libqt6sql6 libqt6sql6-sqlite qt6-qpa-plugins libc6; do
  if grep -Eq "(^|, )$dep( |,|$)" <<<"$depends"; then echo "ok: depends on $dep"; else echo "FAIL: no dependency on $dep"; failures=$((failures + 1)); fi
done
recommends="$(dpkg-deb -f "$deb" Recommends)"
echo "Recommends: $recommends"
if grep -Eq "(^|, )libqt6sql6-psql( |,|$)" <<<"$recommends"; then echo "ok: recommends libqt6sql6-psql"; else
  echo "FAIL: does not recommend libqt6sql6-psql (the class's server)"; failures=$((failures + 1)); fi
[ "$(dpkg-deb -f "$deb" Package)" = palpate ] || { echo "FAIL: package name is not palpate"; failures=$((failures + 1)); }

# The unpacked binaries run and find their resources where they are installed.
dpkg-deb -x "$deb" "$work/root"
root="$(cd "$work/root" && pwd -P)"
if out="$("$root/usr/bin/palpate-cli" --version 2>&1)"; then echo "palpate-cli --version: $out"; else
  echo "FAIL: palpate-cli --version: $out"; failures=$((failures + 1)); fi
if out="$(env -u PALPATE_RESOURCES QT_QPA_PLATFORM=offscreen "$root/usr/bin/palpate" --headless 2>&1)"; then
  echo "palpate --headless: $out"
  grep -q "^mesh $root/usr/share/palpate/meshes/stomach_3970.off:" <<<"$out" || {
    echo "FAIL: the default mesh did not come from the unpacked share/palpate"; failures=$((failures + 1)); }
else
  echo "FAIL: palpate --headless: $out"; failures=$((failures + 1))
fi

if [ "$failures" -ne 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all package checks passed"
