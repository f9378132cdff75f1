// Copying an exercise's mesh or preset into its folder (engine/exercise/ExerciseTravel.h): under its
// own name, reused when the same bytes are there, a new name when a different file holds it, never
// overwriting; errors name the file.
#include "engine/exercise/ExerciseTravel.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace palpate {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct ExerciseTravel : ::testing::Test {
    fs::path root;
    void SetUp() override {
        root = fs::temp_directory_path() /
               ("palpate-travel-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        fs::create_directories(root / "mine");
        fs::create_directories(root / "class");
    }
    void TearDown() override { fs::remove_all(root); }
};

TEST_F(ExerciseTravel, AFileIsCopiedUnderItsNameAndReusedWhenTheSameBytesAreThere) {
    write(root / "mine" / "organ.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    std::string error;
    auto name = copyIntoFolder((root / "mine" / "organ.off").string(), (root / "class").string(), error);
    ASSERT_TRUE(name) << error;
    EXPECT_EQ(*name, "organ.off");
    EXPECT_EQ(read(root / "class" / "organ.off"), read(root / "mine" / "organ.off"));
    // Again: the copy is there already, nothing new.
    name = copyIntoFolder((root / "mine" / "organ.off").string(), (root / "class").string(), error);
    ASSERT_TRUE(name) << error;
    EXPECT_EQ(*name, "organ.off");
    EXPECT_EQ(std::distance(fs::directory_iterator(root / "class"), fs::directory_iterator()), 1);
    // A file in the folder itself is its own copy.
    name = copyIntoFolder((root / "class" / "organ.off").string(), (root / "class").string(), error);
    ASSERT_TRUE(name) << error;
    EXPECT_EQ(*name, "organ.off");
}

TEST_F(ExerciseTravel, ADifferentFileOfTheSameNameIsNeverOverwritten) {
    write(root / "class" / "organ.off", "someone else's organ");
    write(root / "class" / "organ-2.off", "and another");
    write(root / "mine" / "organ.off", "mine");
    std::string error;
    const auto name = copyIntoFolder((root / "mine" / "organ.off").string(), (root / "class").string(), error);
    ASSERT_TRUE(name) << error;
    EXPECT_EQ(*name, "organ-3.off");
    EXPECT_EQ(read(root / "class" / "organ.off"), "someone else's organ");
    EXPECT_EQ(read(root / "class" / "organ-2.off"), "and another");
    EXPECT_EQ(read(root / "class" / "organ-3.off"), "mine");
}

TEST_F(ExerciseTravel, WhatCannotBeCopiedIsNamed) {
    std::string error;
    EXPECT_FALSE(copyIntoFolder((root / "mine" / "missing.off").string(), (root / "class").string(), error));
    EXPECT_NE(error.find("missing.off"), std::string::npos) << error;
    EXPECT_FALSE(copyIntoFolder((root / "mine").string(), (root / "class").string(), error));  // a folder
    EXPECT_NE(error.find("mine"), std::string::npos) << error;
    write(root / "mine" / "organ.off", "mine");
    error.clear();
    EXPECT_FALSE(copyIntoFolder((root / "mine" / "organ.off").string(), (root / "nowhere").string(), error));
    EXPECT_NE(error.find("organ.off"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(root / "nowhere"));
}

}  // namespace
}  // namespace palpate
