#pragma once
// A fresh folder under the test's temporary folder, removed with its contents when it goes out of
// scope. The one temporary folder of the Qt-free tests (Qt tests may use QTemporaryDir).

#include <filesystem>
#include <string>

namespace palpate::test {

class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return mPath; }
    /// Writes `bytes` to `name` inside the folder and returns the full path.
    std::string write(const std::string& name, const std::string& bytes) const;
    std::string file(const std::string& name) const { return (mPath / name).string(); }

private:
    std::filesystem::path mPath;
};

/// The whole file's bytes ("" when it cannot be read).
std::string readFile(const std::string& path);

}  // namespace palpate::test
