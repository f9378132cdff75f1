// The bounded reader (base/io/InputFile.h): a FIFO, a device and a directory are refused by what
// the opened descriptor is, without blocking or reading; a file beyond the format's limit is
// refused by its size before it is read; the limit itself is readable.
#include "base/io/InputFile.h"
#include "tests/io/IoTestDir.h"

#include <gtest/gtest.h>

using namespace palpate;
using palpate::test::contains;
using palpate::test::IoTestDir;

namespace {
constexpr InputKind kSmall{"a test file", 100};
}

TEST(InputFile, ReadsARegularFileWhole) {
    IoTestDir dir;
    const std::string path = dir.write("a.txt", "hello\n");
    std::string error;
    const auto text = readInputFile(path, kSmall, error);
    ASSERT_TRUE(text) << error;
    EXPECT_EQ(*text, "hello\n");
}

TEST(InputFile, AFileOfExactlyTheLimitIsReadOneByteMoreIsNot) {
    IoTestDir dir;
    std::string error;
    EXPECT_TRUE(readInputFile(dir.write("at.txt", std::string(100, 'x')), kSmall, error)) << error;
    const std::string over = dir.write("over.txt", std::string(101, 'x'));
    EXPECT_FALSE(readInputFile(over, kSmall, error));
    EXPECT_EQ(error, over + ": 101 bytes, more than the 100 bytes a test file may hold");
}

TEST(InputFile, AFifoIsRefusedWithoutBlocking) {
    // Without O_NONBLOCK the open waits for a writer forever (the test would hang, not fail).
    IoTestDir dir;
    const std::string path = dir.fifo("pipe.json");
    std::string error;
    EXPECT_FALSE(readInputFile(path, kPresetFile, error));
    EXPECT_EQ(error, path + ": is a FIFO, not a preset file");
    EXPECT_EQ(checkInputFile(path, kExerciseFile), path + ": is a FIFO, not an exercise file");
}

TEST(InputFile, ADeviceIsRefusedWithoutReadingIt) {
    // /dev/zero never ends: reading it whole grows memory until the process dies.
    std::string error;
    EXPECT_FALSE(readInputFile("/dev/zero", kPresetFile, error));
    EXPECT_EQ(error, "/dev/zero: is a device, not a preset file");
}

TEST(InputFile, ADirectoryIsRefused) {
    IoTestDir dir;
    const std::string path = dir.directory("presets.json");
    std::string error;
    EXPECT_FALSE(readInputFile(path, kPresetFile, error));
    EXPECT_EQ(error, path + ": is a directory, not a preset file");
}

TEST(InputFile, AnOversizedFileIsRefusedBeforeItIsRead) {
    // 2 GiB of holes: refused from fstat's size (reading it would take seconds and gigabytes).
    IoTestDir dir;
    const std::string path = dir.sparse("big.json", 2ull << 30);
    std::string error;
    EXPECT_FALSE(openInputFile(path, kPresetFile, error));
    EXPECT_EQ(error, path + ": 2147483648 bytes, more than the 1 MiB a preset file may hold");
    EXPECT_EQ(checkInputFile(path, kMeshFile), path + ": 2147483648 bytes, more than the 256 MiB a mesh file may hold");
}

TEST(InputFile, AMissingFileAndAnUnreadableOneAreNamed) {
    IoTestDir dir;
    std::string error;
    EXPECT_FALSE(readInputFile(dir.file("none.json"), kPresetFile, error));
    EXPECT_EQ(error, dir.file("none.json") + ": no such file");
    const std::string locked = dir.write("locked.json", "{}");
    ::chmod(locked.c_str(), 0);
    if (::geteuid() == 0) GTEST_SKIP() << "root reads any file";
    EXPECT_FALSE(readInputFile(locked, kPresetFile, error));
    EXPECT_EQ(error, locked + ": cannot be opened for reading: Permission denied");
}

TEST(InputFile, TheDescriptorIsRegularAndSized) {
    IoTestDir dir;
    const std::string path = dir.write("a.bin", std::string(42, 'a'));
    std::string error;
    auto fd = openInputFile(path, kSmall, error);
    ASSERT_TRUE(fd) << error;
    EXPECT_GE(fd->fd(), 0);
    EXPECT_EQ(fd->sizeBytes(), 42u);
    char c = 0;
    EXPECT_EQ(::read(fd->fd(), &c, 1), 1);  // blocking again, an ordinary descriptor
}

TEST(InputFile, LimitsAreSaidInTheirUnits) {
    EXPECT_EQ(describeByteCount(kMiB), "1 MiB");
    EXPECT_EQ(describeByteCount(4 * kKiB), "4 KiB");
    EXPECT_EQ(describeByteCount(1000), "1000 bytes");
}
