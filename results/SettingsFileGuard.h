#pragma once
// The preferences file is read and written only when it is a regular file (docs/reliability.md,
// "Settings"): a palpate.conf that is a FIFO would block the start for ever, and one that is a
// link to a device would be "saved" by replacing the device (run as root, /dev/zero became a
// regular file). Anything else there makes this run keep its preferences in a private temporary
// folder instead: nothing is read from the file and nothing written over it.

#include <QString>

namespace palpate {

/// After setApplicationNames(), before the first QSettings. "" when the preferences file is a
/// regular file (or a link to one) or does not exist yet; else the message to show, naming the
/// file and what it is, and the run's preferences are redirected.
QString guardSettingsFile();
/// What the last guardSettingsFile() said ("" when the file is fine), for the window to show.
QString settingsFileProblem();

}  // namespace palpate
