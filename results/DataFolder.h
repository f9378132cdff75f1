#pragma once
// Where the window and the command line keep the trainees' results (results.sqlite) and the
// recordings (recordings/): the data folder set in Preferences, else Qt's application data folder
// (docs/results-store.md, "One store"). Defined once, so that a result stored by
// `palpate-cli score --trainee` is the window's, and reaches the class's server with it. Qt Core
// only; the application's names must be set first (FirstRun.h's setApplicationNames, or the CLI's).

#include <QString>

namespace palpate {

/// The preferences key of the data folder ("" or absent: the default).
inline constexpr const char* kDataFolderKey = "dataFolder";

/// Qt's application data folder (~/.local/share/palpate on Linux).
QString defaultDataFolder();
/// The data folder the preferences name, else the default. Reads the preferences file only when it
/// is a regular file (SettingsFileGuard.h).
QString dataFolder();
/// results.sqlite in `folder`.
QString resultsStorePath(const QString& folder);
/// resultsStorePath(dataFolder()): the store the window opens and the CLI uses without --db.
QString defaultResultsStore();

}  // namespace palpate
