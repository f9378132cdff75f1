#!/bin/sh
# Runs one test command as a fresh machine would (docs/testing.md, "Hermetic tests"): its own empty
# HOME, XDG folders and TMPDIR, removed afterwards; a fixed locale and time zone; no display and
# none of the user's Qt overrides. CTest starts every test through this script, so no test reads or
# writes the user's ~/.config or ~/.local/share, and no test sees what an earlier one left behind.
# A test that uses one settings file across several processes names it inside its own HOME.
set -u
# Under /tmp, which every user can reach: a server a test starts as another user (pg_virtualenv's
# postgres) must get into the test's TMPDIR, and a caller's own TMPDIR may be private (mode 700).
root=$(mktemp -d /tmp/palpate-test.XXXXXX 2>/dev/null || mktemp -d "${TMPDIR:-/tmp}/palpate-test.XXXXXX") || exit 125
trap 'rm -rf "$root"' EXIT
trap 'exit 143' TERM
trap 'exit 130' INT
mkdir -p "$root/home" "$root/config" "$root/data" "$root/cache" "$root/state" "$root/runtime" "$root/tmp"
chmod 700 "$root/runtime"
# Like /tmp: that server writes there too.
chmod 755 "$root" && chmod 1777 "$root/tmp"

export HOME="$root/home"
export XDG_CONFIG_HOME="$root/config" XDG_DATA_HOME="$root/data" XDG_CACHE_HOME="$root/cache"
export XDG_STATE_HOME="$root/state" XDG_RUNTIME_DIR="$root/runtime" TMPDIR="$root/tmp"
# The system folders only, as on a machine nobody has configured.
export XDG_CONFIG_DIRS=/etc/xdg XDG_DATA_DIRS=/usr/local/share:/usr/share
export LANG=C.UTF-8 LC_ALL=C.UTF-8 TZ=UTC
# Only the fonts scripts/install-deps.sh installs: a dock's width follows its font's metrics.
export FONTCONFIG_FILE="$(cd "$(dirname "$0")" && pwd)/fonts.conf"
unset FONTCONFIG_PATH
unset LANGUAGE LC_CTYPE LC_NUMERIC LC_TIME LC_COLLATE LC_MONETARY LC_MESSAGES
# A display is what a test asks for (xvfb-run, QT_QPA_PLATFORM), never the developer's desktop.
unset DISPLAY WAYLAND_DISPLAY XAUTHORITY SESSION_MANAGER DBUS_SESSION_BUS_ADDRESS
unset QT_SCALE_FACTOR QT_SCREEN_SCALE_FACTORS QT_AUTO_SCREEN_SCALE_FACTOR QT_ENABLE_HIGHDPI_SCALING
unset QT_FONT_DPI QT_STYLE_OVERRIDE QT_QPA_PLATFORMTHEME QT_QUICK_CONTROLS_STYLE QT_LOGGING_RULES
# Libpq's own files and variables are the test's to set.
unset PGHOST PGPORT PGUSER PGDATABASE PGPASSWORD PGPASSFILE PGSERVICE PGSERVICEFILE PGSSLMODE

"$@"
