#pragma once
// Where the command line finds the results: the GUI's own database by default (the same data
// folder), or a --db location (an SQLite file or a postgresql:// URL, docs/results-store.md).

#include <string>

namespace palpate::cli {

/// results.sqlite in the GUI's data folder.
std::string defaultDatabasePath();

}  // namespace palpate::cli
