// Waypoint files (sim:path:FILE) are user input: a good file loads; every defect is an error that
// names the file and the line; directories and missing paths are errors, not crashes; and 300
// random mutations of a good file never crash the parser or yield an unusable path.

#include "device/SimulatedDevice.h"
#include "device/WaypointFile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <unistd.h>

namespace palpate {
namespace {

namespace fs = std::filesystem;

/// A fresh directory for one test, removed afterwards (tests run as parallel processes).
class TempDir {
public:
    TempDir() {
        static int counter = 0;
        mPath = fs::temp_directory_path() /
                ("palpate_device_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(mPath);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    std::string write(const std::string& name, const std::string& text) const {
        const fs::path p = mPath / name;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    const fs::path& path() const { return mPath; }

private:
    fs::path mPath;
};

const char* kGoodText =
    "# t_s  x_mm  y_mm  z_mm\n"
    "0      0     0     2\n"
    "\n"
    "0.5    0     0    -1.5   # pressing in\n"
    "1.0e0, 2.5,  0,   -1.5\r\n"
    "\t2 +1 -0.25 2\n";

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

TEST(WaypointFile, GoodFileLoads) {
    TempDir dir;
    const std::string path = dir.write("good.txt", kGoodText);
    std::vector<Waypoint> w;
    std::string error;
    ASSERT_TRUE((error = loadWaypointFile(path, w)).empty()) << error;
    EXPECT_TRUE(error.empty());
    ASSERT_EQ(w.size(), 4u);
    EXPECT_DOUBLE_EQ(w[0].timeS, 0.0);
    EXPECT_EQ(w[0].positionMm, glm::vec3(0, 0, 2));
    EXPECT_EQ(w[1].positionMm, glm::vec3(0, 0, -1.5f));
    EXPECT_DOUBLE_EQ(w[2].timeS, 1.0);
    EXPECT_EQ(w[2].positionMm, glm::vec3(2.5f, 0, -1.5f));
    EXPECT_EQ(w[3].positionMm, glm::vec3(1.0f, -0.25f, 2.0f));

    auto device = SimulatedDevice::fromWaypointFile(path, error);
    ASSERT_TRUE(device) << error;
    EXPECT_EQ(device->positionAtMm(0.75), glm::vec3(1.25f, 0, -1.5f));
}

struct BadCase {
    const char* name;
    const char* text;
    int line;             ///< expected line in the message (0: no line)
    const char* mention;  ///< expected words in the message
};

TEST(WaypointFile, DefectsNameTheFileAndLine) {
    const BadCase cases[] = {
        {"bad number", "0 0 0 2\n1 0 zero 2\n", 2, "'zero' is not a number (column 3, y_mm)"},
        {"trailing junk in a number", "0 0 0 2\n\n1 0 0 2mm\n", 3, "'2mm' is not a number"},
        {"missing column", "0 0 0 2\n1 0 0\n", 2, "expected 4 numbers (t_s x_mm y_mm z_mm), found 3 fields"},
        {"extra column", "0 0 0 2 7\n", 1, "found 5 fields"},
        {"one field", "# c\n5\n", 2, "found 1 field"},
        {"time not increasing", "0 0 0 2\n1 0 0 2\n1 0 0 3\n", 3, "not after the previous waypoint"},
        {"time going back", "0 0 0 2\n-1 0 0 2\n", 2, "times must increase"},
        {"nan", "0 nan 0 2\n", 1, "x_mm is not finite"},
        {"inf", "inf 0 0 2\n", 1, "t_s is not finite"},
        {"overflow", "0 0 0 1e999\n", 1, "'1e999' is not a number"},
        {"absurd", "0 0 0 2\n1 0 2e7 0\n", 2, "y_mm"},
        {"double sign", "0 +-1 0 2\n", 1, "is not a number"},
        {"binary", "0 0 0 2\n1 \x01\xff 0 0\n", 2, "'\\x01\\xff' is not a number"},
        {"empty", "", 0, "no waypoints"},
        {"only comments and blanks", "# nothing here\n\n   \n\t# still nothing\n", 0, "no waypoints"},
    };
    TempDir dir;
    int n = 0;
    for (const BadCase& c : cases) {
        const std::string path = dir.write("bad" + std::to_string(n++) + ".txt", c.text);
        std::vector<Waypoint> w = {{0.0, glm::vec3(1.0f)}};
        std::string error;
        EXPECT_FALSE((error = loadWaypointFile(path, w)).empty()) << c.name;
        EXPECT_TRUE(w.empty()) << c.name;
        const std::string where = c.line > 0 ? path + ":" + std::to_string(c.line) + ": " : path + ": ";
        EXPECT_EQ(error.rfind(where, 0), 0u) << c.name << ": " << error;
        EXPECT_TRUE(contains(error, c.mention)) << c.name << ": " << error;

        std::string deviceError;
        EXPECT_EQ(SimulatedDevice::fromWaypointFile(path, deviceError), nullptr) << c.name;
        EXPECT_EQ(deviceError, error) << c.name;
    }
}

// A scripted trainee's Mark and Finish presses ride in the file's comments.
TEST(WaypointFile, ButtonLinesAreReadAndTheirDefectsNamed) {
    WaypointButtons buttons;
    std::string error;
    ASSERT_TRUE((error = parseWaypointButtons("# a comment\n# mark-at 1.5\r\n0 0 0 0\n# mark-at 2\n# done-at 3.25 \n",
                                              "p.path", buttons))
                    .empty())
        << error;
    EXPECT_EQ(buttons.marksS, (std::vector<double>{1.5, 2.0}));
    ASSERT_TRUE(buttons.doneS);
    EXPECT_EQ(*buttons.doneS, 3.25);
    ASSERT_TRUE((error = parseWaypointButtons("0 0 0 0\n", "p.path", buttons)).empty());
    EXPECT_TRUE(buttons.marksS.empty());
    EXPECT_FALSE(buttons.doneS);
    EXPECT_FALSE((error = parseWaypointButtons("0 0 0 0\n# done-at soon\n", "p.path", buttons)).empty());
    EXPECT_NE(error.find("p.path:2:"), std::string::npos) << error;
    EXPECT_NE(error.find("soon"), std::string::npos) << error;
    EXPECT_FALSE((error = parseWaypointButtons("# mark-at -1\n", "p.path", buttons)).empty());
    EXPECT_NE(error.find("p.path:1:"), std::string::npos) << error;
    EXPECT_FALSE((error = parseWaypointButtons("# done-at 1\n# done-at 2\n", "p.path", buttons)).empty());
    EXPECT_NE(error.find("p.path:2: a second 'done-at'"), std::string::npos) << error;
}

TEST(WaypointFile, DirectoryIsAnErrorNamingIt) {
    TempDir dir;
    std::vector<Waypoint> w;
    std::string error;
    EXPECT_FALSE((error = loadWaypointFile(dir.path().string(), w)).empty());
    EXPECT_TRUE(contains(error, dir.path().string())) << error;
    EXPECT_TRUE(contains(error, "is a directory")) << error;
}

TEST(WaypointFile, MissingPathIsAnErrorNamingIt) {
    TempDir dir;
    const std::string path = (dir.path() / "no" / "such.txt").string();
    std::vector<Waypoint> w;
    std::string error;
    EXPECT_FALSE((error = loadWaypointFile(path, w)).empty());
    EXPECT_TRUE(contains(error, path)) << error;
    EXPECT_TRUE(contains(error, "no such file")) << error;
    EXPECT_FALSE((error = loadWaypointFile("", w)).empty());
    EXPECT_TRUE(contains(error, "no path")) << error;
}

TEST(WaypointFile, SingleWaypointIsAFixedPoint) {
    std::vector<Waypoint> w;
    std::string error;
    ASSERT_TRUE((error = parseWaypoints("3 1 2 3", "inline", w)).empty()) << error;  // no final newline
    SimulatedDevice d(w);
    EXPECT_EQ(d.positionAtMm(0.0), glm::vec3(1, 2, 3));
    EXPECT_EQ(d.positionAtMm(10.0), glm::vec3(1, 2, 3));
}

/// One random edit of the kind a damaged or hand-edited file shows.
void mutate(std::string& text, std::mt19937& rng) {
    static const char kAlphabet[] = "0123456789.-+eE \t,\n\r#xnaif\x00\xff";
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    const char c = kAlphabet[pick(sizeof(kAlphabet) - 1)];
    switch (pick(7)) {
        case 0: if (!text.empty()) text[pick(text.size())] = c; break;                              // replace
        case 1: text.insert(text.begin() + std::ptrdiff_t(pick(text.size() + 1)), c); break;      // insert
        case 2: if (!text.empty()) text.erase(pick(text.size()), 1 + pick(8)); break;             // delete
        case 3: text.resize(pick(text.size() + 1)); break;                                        // truncate
        case 4: {                                                                                 // duplicate
            if (text.empty()) break;
            const std::size_t from = pick(text.size());
            text.insert(pick(text.size()), text.substr(from, 1 + pick(20)));
            break;
        }
        case 5: if (!text.empty()) text[pick(text.size())] = char(pick(256)); break;              // any byte
        default: text.insert(pick(text.size() + 1), std::string(1 + pick(40), c)); break;         // run
    }
}

TEST(WaypointFile, FuzzedFilesNeverCrash) {
    TempDir dir;
    std::mt19937 rng(20240611);
    int accepted = 0, rejected = 0;
    for (int i = 0; i < 300; ++i) {
        std::string text = kGoodText;
        const int edits = 1 + int(rng() % 6);
        for (int e = 0; e < edits; ++e) mutate(text, rng);
        std::vector<Waypoint> w;
        std::string error;
        const std::string name = "fuzz" + std::to_string(i) + ".txt";
        // Every tenth goes through a real file, the rest through the parser directly.
        const bool ok = i % 10 == 0 ? (error = loadWaypointFile(dir.write(name, text), w)).empty()
                                    : (error = parseWaypoints(text, name, w)).empty();
        if (ok) {
            ++accepted;
            ASSERT_FALSE(w.empty());
            ASSERT_TRUE(error.empty());
            for (std::size_t k = 0; k < w.size(); ++k) {
                ASSERT_TRUE(std::isfinite(w[k].timeS));
                ASSERT_TRUE(std::isfinite(w[k].positionMm.x) && std::isfinite(w[k].positionMm.y) &&
                            std::isfinite(w[k].positionMm.z));
                if (k > 0) {
                    ASSERT_GT(w[k].timeS, w[k - 1].timeS);
                }
            }
            SimulatedDevice d(w);  // an accepted path is always playable
            for (double t = -1.0; t < 5.0; t += 0.1) {
                const glm::vec3 p = d.positionAtMm(t);
                ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
            }
        } else {
            ++rejected;
            ASSERT_TRUE(w.empty());
            ASSERT_TRUE(contains(error, name)) << error;
        }
    }
    // Both outcomes occur, so the fuzzer exercises more than one path.
    EXPECT_GT(accepted, 10);
    EXPECT_GT(rejected, 10);
}

}  // namespace
}  // namespace palpate
