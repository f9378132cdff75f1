#pragma once
// Each test process gets its own QSettings file: ctest runs a binary's cases side by side, and a
// case that clears or writes the settings must not change another's (a remembered mesh unit, a
// window state). Call once in main(), before the first QSettings.

#include <QSettings>
#include <QTemporaryDir>

namespace palpate::test {

inline void isolateSettings() {
    static QTemporaryDir folder;  // removed with the process's end
    if (!folder.isValid()) return;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, folder.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder.path());
}

}  // namespace palpate::test
