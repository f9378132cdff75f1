#pragma once
// Where the command line finds the results: the window's own database by default (the data folder
// its Preferences set), or a --db location (an SQLite file or a postgresql:// URL, docs/results-store.md).

#include <string>

namespace palpate::cli {

/// results.sqlite in the window's data folder: the one its Preferences name, else the default.
std::string defaultDatabasePath();

}  // namespace palpate::cli
