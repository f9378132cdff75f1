#include "engine/io/AtomicFile.h"

#include <filesystem>
#include <fstream>

namespace palpate {

std::string writeFileAtomically(const std::string& path, const std::string& text) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) return path + ": cannot be written";
        out << text;
        out.flush();
        if (!out) return path + ": writing failed";
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        return path + ": cannot be replaced: " + ec.message();
    }
    return {};
}

}  // namespace palpate
