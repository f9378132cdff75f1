#include "engine/io/TextFile.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace palpate {

std::optional<std::string> readTextFile(const std::string& path, const std::string& kind, std::string& error) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
        error = path + ": no such file";
        return std::nullopt;
    }
    if (fs::is_directory(status)) {
        error = path + ": is a directory, not " + (kind.empty() ? std::string("a file") : kind);
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path + ": cannot be opened for reading";
        return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace palpate
