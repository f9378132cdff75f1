#!/usr/bin/env python3
"""Fails when a translation is not complete: runs lupdate over app/gui, widgets, results, report and engine (its parameter tables) on a COPY of each
translations/*.ts (the committed files are never rewritten) and lists every entry that is unfinished
(a new or changed string) or obsolete/vanished (a string the sources no longer have).

Usage: check_translations.py LUPDATE SOURCE_DIR
Fix: cmake --build build/release --target update_translations, then translate what is unfinished.
"""
import glob
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET


def main():
    lupdate, source = sys.argv[1], os.path.abspath(sys.argv[2])
    ts_files = sorted(glob.glob(os.path.join(source, "translations", "*.ts")))
    if not ts_files:
        print("FAIL: no translations/*.ts")
        return 1
    failures = 0
    with tempfile.TemporaryDirectory(prefix="palpate-ts-") as work:
        for ts in ts_files:
            copy = os.path.join(work, os.path.basename(ts))
            shutil.copyfile(ts, copy)
            # The same sources and options as the update_translations target, except -no-obsolete:
            # here obsolete entries must show.
            run = subprocess.run([lupdate, "-locations", "none", "-I", source,
                                  "-tr-function-alias", "QT_TRANSLATE_NOOP+=PALPATE_TRANSLATE_NOOP,QT_TRANSLATE_N_NOOP+=PALPATE_TRANSLATE_N_NOOP",
                                  os.path.join(source, "app", "gui"), os.path.join(source, "widgets"),
                                  os.path.join(source, "results"), os.path.join(source, "report"),
                                  os.path.join(source, "engine"),
                                  "-ts", copy], capture_output=True, text=True)
            if run.returncode != 0:
                print(run.stdout, run.stderr)
                print(f"FAIL: lupdate on a copy of {ts}")
                failures += 1
                continue
            root = ET.parse(copy).getroot()
            total, bad = 0, []
            for context in root.iter("context"):
                name = context.findtext("name")
                for message in context.iter("message"):
                    total += 1
                    translation = message.find("translation")
                    kind = translation.get("type") if translation is not None else "unfinished"
                    empty = translation is None or (not (translation.text or "").strip() and
                                                    not any((n.text or "").strip() for n in translation.iter("numerusform")))
                    if kind in ("unfinished", "obsolete", "vanished") or empty:
                        bad.append(f"  {kind or 'empty'}: [{name}] {message.findtext('source')!r}")
            print(f"{os.path.basename(ts)} ({root.get('language')}): {total} entries, {len(bad)} not done")
            for line in bad[:200]:
                print(line)
            if len(bad) > 200:
                print(f"  ... and {len(bad) - 200} more")
            failures += bool(bad)
    if failures:
        print("Update and translate: cmake --build <build dir> --target update_translations "
              "(rewrites translations/*.ts), then translate the unfinished entries.")
        return 1
    print("all translations complete")
    return 0


if __name__ == "__main__":
    sys.exit(main())
