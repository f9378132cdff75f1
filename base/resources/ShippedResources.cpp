#include "base/resources/ShippedResources.h"

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace palpate {

std::string findResource(const std::string& relativePath) {
    namespace fs = std::filesystem;
    std::vector<fs::path> roots;
    if (const char* env = std::getenv("PALPATE_RESOURCES")) roots.emplace_back(env);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        roots.push_back(exe.parent_path() / ".." / "resources");
        roots.push_back(exe.parent_path() / ".." / ".." / "resources");
        roots.push_back(exe.parent_path() / ".." / "share" / "palpate");
    }
#ifdef PALPATE_SOURCE_DIR
    roots.emplace_back(fs::path(PALPATE_SOURCE_DIR) / "resources");
#endif
    for (const auto& root : roots) {
        const fs::path candidate = root / relativePath;
        if (fs::is_regular_file(candidate, ec)) return fs::weakly_canonical(candidate, ec).string();
    }
    return {};
}

}  // namespace palpate
