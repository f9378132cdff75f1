#pragma once
// A fresh folder per test (tests run as parallel processes) and the hostile files the input tests
// make in it: a FIFO, a sparse file of any size, a directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace palpate::test {

class IoTestDir {
public:
    IoTestDir() {
        std::random_device rd;
        mPath = std::filesystem::temp_directory_path() /
                ("palpate_io_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
        std::filesystem::create_directories(mPath);
    }
    ~IoTestDir() {
        std::error_code ec;
        std::filesystem::remove_all(mPath, ec);
    }
    std::string file(const std::string& name) const { return (mPath / name).string(); }
    const std::filesystem::path& path() const { return mPath; }

    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(file(name), std::ios::binary) << text;
        return file(name);
    }
    std::string fifo(const std::string& name) const {
        EXPECT_EQ(::mkfifo(file(name).c_str(), 0600), 0);
        return file(name);
    }
    /// A file of `bytes` bytes that holds no data (truncate -s): its size is free to make.
    std::string sparse(const std::string& name, std::uint64_t bytes) const {
        { std::ofstream(file(name), std::ios::binary); }
        EXPECT_EQ(::truncate(file(name).c_str(), off_t(bytes)), 0);
        return file(name);
    }
    std::string directory(const std::string& name) const {
        std::filesystem::create_directories(mPath / name);
        return file(name);
    }
    /// The names in the folder, for "nothing else was left behind".
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& e : std::filesystem::directory_iterator(mPath)) out.push_back(e.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }

private:
    std::filesystem::path mPath;
};

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace palpate::test
