#pragma once
// Which results locations name a server (docs/results-store.md, "Two back-ends, one schema"): a
// postgresql:// or postgres:// URL; anything else is an SQLite file. Qt-free, so that palpate-cli
// built without the GUI can tell them apart too.

#include <string_view>

namespace palpate {

inline bool isServerLocationText(std::string_view location) {
    return location.starts_with("postgresql://") || location.starts_with("postgres://");
}

}  // namespace palpate
