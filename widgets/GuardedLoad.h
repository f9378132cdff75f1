#pragma once
// A file loader's call as the window makes it: the loaders return their errors (naming the file and
// the key), but should one throw all the same (no memory for a huge file, a bug), the exception
// becomes the load result's error naming the file, so that no file can abort the window
// (docs/reliability.md). The event loop catches the rest (app/gui/GuiApplication.h).

#include <exception>
#include <string>

namespace palpate {

/// `load()` (returning a result with `errors`, e.g. PresetLoadResult, ExerciseLoadResult), or an
/// empty result whose error is "path: what the exception says".
template <class Load>
auto guardedLoad(const std::string& path, Load&& load) -> decltype(load()) {
    try {
        return load();
    } catch (const std::exception& e) {
        decltype(load()) failed;
        failed.errors.push_back(path + ": " + e.what());
        return failed;
    }
}

}  // namespace palpate
