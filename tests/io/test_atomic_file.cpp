// Atomic writes (base/io/AtomicFile.h): a write that fails (a file-size limit stands in for a
// full disk) names the path and the reason, leaves the old file as it was and no temporary behind;
// the temporary's name is unique, so another writer's file is never touched; a special file in the
// target's place is not replaced.
#include "base/io/AtomicFile.h"
#include "tests/io/FileSizeLimit.h"
#include "tests/io/IoTestDir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <thread>

using namespace palpate;
using palpate::test::IoTestDir;

namespace {
std::string contentOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
}  // namespace

TEST(AtomicFile, ReplacesTheFileAndLeavesNothingElse) {
    IoTestDir dir;
    const std::string path = dir.file("a.json");
    ASSERT_EQ(writeFileAtomically(path, "first"), "");
    ASSERT_EQ(writeFileAtomically(path, "second"), "");
    EXPECT_EQ(contentOf(path), "second");
    EXPECT_EQ(dir.names(), std::vector<std::string>{"a.json"});
}

TEST(AtomicFile, TheReplacedFileKeepsItsPermissions) {
    IoTestDir dir;
    const std::string path = dir.write("private.json", "old");
    ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
    ASSERT_EQ(writeFileAtomically(path, "new"), "");
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600u);
}

TEST(AtomicFile, AFailedWriteNamesThePathAndTheReasonAndKeepsTheOldFile) {
    IoTestDir dir;
    const std::string path = dir.write("a.json", "old");
    const auto child = test::runWithFileSizeLimit(1000,
                                                  [&] { return writeFileAtomically(path, std::string(5000, 'x')); });
    ASSERT_EQ(child.exitCode, 0);
    EXPECT_EQ(child.output, path + ": writing failed: File too large");
    EXPECT_EQ(contentOf(path), "old");
    EXPECT_EQ(dir.names(), std::vector<std::string>{"a.json"});  // the temporary is gone
}

TEST(AtomicFile, AFailedWriteThroughAWriterRemovesItsTemporary) {
    IoTestDir dir;
    const std::string path = dir.file("m.off");
    std::string temporaryUsed;
    const std::string problem = writeFileAtomicallyVia(path, [&](const std::string& temporary) {
        temporaryUsed = temporary;
        std::ofstream(temporary) << "partial";
        return std::string("the writer failed");
    });
    EXPECT_EQ(problem, path + ": writing failed: the writer failed");
    EXPECT_EQ(std::filesystem::path(temporaryUsed).extension(), ".off");  // writers pick the format by it
    EXPECT_TRUE(dir.names().empty());
    ASSERT_EQ(writeFileAtomicallyVia(path,
                                     [](const std::string& t) {
                                         std::ofstream(t) << "whole";
                                         return std::string();
                                     }),
              "");
    EXPECT_EQ(contentOf(path), "whole");
}

TEST(AtomicFile, AnotherWritersTemporaryIsNeverTouched) {
    // A fixed "path.tmp" would be shared by two writers of one target (and taken over here).
    IoTestDir dir;
    const std::string path = dir.file("a.json");
    const std::string other = dir.write("a.json.tmp", "another writer's");
    ASSERT_EQ(writeFileAtomically(path, "mine"), "");
    EXPECT_EQ(contentOf(other), "another writer's");
    EXPECT_EQ(contentOf(path), "mine");
}

TEST(AtomicFile, TwoWritersOfOneFileLeaveOneWholeVersion) {
    // With one shared temporary, one writer's rename can take the other's half-written bytes.
    IoTestDir dir;
    const std::string path = dir.file("shared.json");
    const std::string a(200000, 'a'), b(150000, 'b');
    std::vector<std::string> problems(2);
    auto writer = [&](int i) {
        for (int k = 0; k < 40; ++k)
            if (std::string e = writeFileAtomically(path, i == 0 ? a : b); !e.empty()) problems[std::size_t(i)] = e;
    };
    std::thread first(writer, 0), second(writer, 1);
    first.join();
    second.join();
    EXPECT_EQ(problems, std::vector<std::string>(2));
    const std::string content = contentOf(path);
    EXPECT_TRUE(content == a || content == b) << content.size() << " bytes";
    EXPECT_EQ(dir.names(), std::vector<std::string>{"shared.json"});
}

TEST(AtomicFile, ASpecialFileInTheTargetsPlaceIsNotReplaced) {
    IoTestDir dir;
    const std::string fifo = dir.fifo("a.json");
    EXPECT_EQ(writeFileAtomically(fifo, "x"), fifo + ": is a FIFO, not a file that can be written");
    EXPECT_TRUE(std::filesystem::is_fifo(fifo));
    const std::string folder = dir.directory("b.json");
    EXPECT_EQ(writeFileAtomically(folder, "x"), folder + ": is a directory, not a file that can be written");
    EXPECT_EQ(dir.names(), (std::vector<std::string>{"a.json", "b.json"}));
}

TEST(AtomicFile, AMissingFolderIsNamedWithTheReason) {
    IoTestDir dir;
    const std::string path = dir.file("no/such/a.json");
    EXPECT_EQ(writeFileAtomically(path, "x"), path + ": cannot be written: No such file or directory");
}
