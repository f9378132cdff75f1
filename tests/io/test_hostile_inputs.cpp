// Every input file through its real loader, with what a tester gives it: a FIFO (never a hang), a
// device (never read), a 2 GB sparse file (refused by its size), a directory; and the mesh cases:
// a 1e308 coordinate, a full disk under `mesh generate`, more vertices than a mesh may have, and
// `calibrate` with a value out of range.
#include "device/WaypointFile.h"
#include "engine/core/MeshFileProbe.h"
#include "engine/core/MeshGenerator.h"
#include "engine/core/TissueMesh.h"
#include "engine/exercise/ExerciseFile.h"
#include "base/io/FileLimits.h"
#include "engine/lod/LevelCache.h"
#include "engine/scene/TissuePreset.h"
#include "engine/scoring/ExerciseSession.h"
#include "tests/support/ChildProcess.h"

#include <sys/resource.h>
#include "tests/io/IoTestDir.h"

#include <gtest/gtest.h>

#include <functional>

using namespace palpate;
using palpate::test::contains;
using palpate::test::IoTestDir;

namespace {

/// The first error each loader gives for `path`.
struct Loader {
    const char* name;
    const char* kindName;  ///< what the messages call the file
    std::function<std::string(const std::string&)> load;
};

std::vector<Loader> loaders() {
    return {
        {"preset", "a preset file", [](const std::string& p) { return loadTissuePreset(p).error(); }},
        {"exercise", "an exercise file", [](const std::string& p) { return loadExercise(p).error(); }},
        {"waypoint", "a waypoint file",
         [](const std::string& p) {
             std::vector<Waypoint> w;
             return loadWaypointFile(p, w);
         }},
        {"mesh", "a mesh file", [](const std::string& p) { return TissueMesh::load(p).error(); }},
        {"mesh probe", "a mesh file", [](const std::string& p) { return p + ": " + probeMeshFile(p); }},
    };
}

struct Cli {
    int exitCode = -1;
    std::string output;
};

Cli runCli(const std::vector<std::string>& args, rlim_t fileSizeLimit = RLIM_INFINITY) {
    std::vector<std::string> argv{PALPATE_CLI_PATH};
    argv.insert(argv.end(), args.begin(), args.end());
    test::ChildSpec spec;
    spec.argv = argv;
    if (fileSizeLimit != RLIM_INFINITY) spec.fileSizeBytes = fileSizeLimit;
    spec.timeoutS = 60.0;
    const test::ChildResult r = test::Child(spec).wait();
    return {r.exited ? r.exitCode : -1, r.out + r.err};
}

}  // namespace

TEST(HostileInputs, AFifoAsAnyInputIsRefusedWithoutAHang) {
    IoTestDir dir;
    for (const Loader& l : loaders()) {
        const std::string path = dir.fifo(std::string("pipe-") + l.name + ".off");
        EXPECT_EQ(l.load(path), path + ": is a FIFO, not " + l.kindName) << l.name;
    }
}

TEST(HostileInputs, ADeviceAsAnyInputIsRefusedWithoutReadingIt) {
    for (const Loader& l : loaders())
        EXPECT_EQ(l.load("/dev/zero"), std::string("/dev/zero: is a device, not ") + l.kindName) << l.name;
}

TEST(HostileInputs, A2GbSparseFileAsAnyInputIsRefusedBySize) {
    IoTestDir dir;
    for (const Loader& l : loaders()) {
        const std::string path = dir.sparse(std::string("big-") + l.name + ".off", 2ull << 30);
        const std::string error = l.load(path);
        EXPECT_TRUE(contains(error, path + ": 2147483648 bytes, more than the ")) << l.name << ": " << error;
        EXPECT_TRUE(contains(error, std::string(" ") + l.kindName + " may hold")) << l.name << ": " << error;
    }
}

TEST(HostileInputs, ADirectoryAsAnyInputIsNamed) {
    IoTestDir dir;
    for (const Loader& l : loaders()) {
        const std::string path = dir.directory(std::string("dir-") + l.name + ".off");
        EXPECT_EQ(l.load(path), path + ": is a directory, not " + l.kindName) << l.name;
    }
}

TEST(HostileInputs, AFifoAsThePresetAnExerciseNamesIsNamed) {
    // Found beside the exercise, then refused by the preset loader (not "was found neither beside
    // the exercise file nor under resources/").
    IoTestDir dir;
    const std::string fifo = dir.fifo("pipe.json");
    const std::string exercisePath = dir.write("ex.json",
                                               R"({"format": "palpate-exercise", "version": 1, "name": "p",
        "type": "press_targets", "mesh": ")" + std::string(PALPATE_SOURCE_DIR) +
                                                   R"(/resources/meshes/sphere_1442.off", "tissue_preset": "pipe.json",
        "time_limit_s": 30, "press_targets": {"targets": [{"vertex": 3}]}})");
    const auto exercise = loadExercise(exercisePath);
    ASSERT_TRUE(exercise.exercise) << exercise.error();
    std::vector<std::string> errors;
    EXPECT_FALSE(loadExerciseAssets(*exercise.exercise, {}, errors));
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors.front(), exercisePath + ": tissue_preset: " + fifo + ": is a FIFO, not a preset file");
}

TEST(HostileInputs, ALevelCacheIndexThatIsAFifoIsNotRead) {
    IoTestDir dir;
    auto mesh = generateMesh(GeneratedShape::Sphere, 300);
    ASSERT_TRUE(mesh.mesh);
    const std::string cache = dir.directory("m.off.levels");
    const std::string index = dir.fifo("m.off.levels/levels.json");
    std::string why;
    EXPECT_FALSE(readLevelCache(cache, *mesh.mesh, LevelDef{}, why));
    EXPECT_EQ(why, index + ": is a FIFO, not a level cache index");
}

TEST(HostileInputs, ACoordinateBeyondAFloatIsSaidToBeOutOfRange) {
    // OpenMesh reads it into a float, fails, and loses its place: "faces refer to vertices that do
    // not exist" was the message.
    IoTestDir dir;
    const std::string path = dir.write(
        "huge.off", "OFF\n4 4 0\n0 0 0\n1e308 0 0\n0 10 0\n0 0 10\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    const std::string error = TissueMesh::load(path).error();
    EXPECT_EQ(error, path +
                         ": has a coordinate out of range at OFF vertex 1: 1e308 (a coordinate must be within "
                         "+-3.4e38, a float's range; a tissue mesh is at most 100 m across anyway)");
    const std::string obj = dir.write("huge.obj", "v 0 0 0\nv 1 -1e300 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_TRUE(contains(TissueMesh::load(obj).error(), "coordinate out of range at line 2: -1e300"))
        << TissueMesh::load(obj).error();
}

TEST(HostileInputs, DeclaredMeshCountsBeyondTheLimitAreRefusedBeforeAnythingIsSized) {
    EXPECT_EQ(probeMeshBytes("OFF\n4000000000 4 0\n", "off"),
              "declares 4000000000 vertices, more than the " + std::to_string(kMaxMeshVertices) + " a mesh may have");
    std::string stl(84, '\0');
    stl[80] = stl[81] = stl[82] = stl[83] = char(0xff);
    EXPECT_EQ(probeMeshBytes(stl, "stl"),
              "declares 4294967295 faces, more than the " + std::to_string(kMaxMeshFaces) + " a mesh may have");
    EXPECT_EQ(probeMeshBytes(std::string("OMTB\xf0\xff\xff\xff\x04\0\0\0", 12), "om"),
              "declares 4294967280 vertices, more than the " + std::to_string(kMaxMeshVertices) + " a mesh may have");
    EXPECT_EQ(probeMeshBytes(std::string("OMTB\x04\0\0\0\x04\0\0\0", 12), "om"), "");
}

TEST(HostileInputs, MeshGenerateOnAFullDiskSaysSoAndLeavesNoFile) {
    IoTestDir dir;
    const std::string out = dir.file("s.off");
    const Cli r = runCli({"mesh", "generate", "--shape", "sphere", "--vertices", "5000", "--out", out}, 4096);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_EQ(r.output, out + ": cannot write mesh: writing failed: File too large\n");
    EXPECT_TRUE(dir.names().empty());  // neither a truncated mesh nor its temporary
}

TEST(HostileInputs, MeshGenerateRefusesMoreVerticesThanAMeshMayHave) {
    const Cli r = runCli({"mesh", "generate", "--shape", "sphere", "--vertices", "50000000", "--out",
                          "/nonexistent/x.off"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.output, "mesh generate: --vertices '50000000' must be a whole number from 8 to " +
                            std::to_string(kMaxMeshVertices) + " (the most a mesh may have)\n");
    EXPECT_FALSE(generateMesh(GeneratedShape::Sphere, std::size_t(kMaxMeshVertices) + 1).mesh);
}

TEST(HostileInputs, MeshWriteFailuresAlwaysSayWhy) {
    IoTestDir dir;
    auto mesh = generateMesh(GeneratedShape::Sphere, 100);
    ASSERT_TRUE(mesh.mesh);
    EXPECT_EQ(mesh.mesh->save("/dev/full"),
              "/dev/full: cannot write mesh: no extension (use .obj, .off, .ply, .stl or .om)");
    const std::string fifo = dir.fifo("pipe.off");
    EXPECT_EQ(mesh.mesh->save(fifo), fifo + ": cannot write mesh: is a FIFO, not a file that can be written");
    const std::string missing = dir.file("no/such/m.off");
    std::filesystem::remove(fifo);
    EXPECT_EQ(mesh.mesh->save(missing), missing + ": cannot write mesh: cannot be written: No such file or directory");
    const std::string unknown = dir.file("m.xyz");
    EXPECT_TRUE(contains(mesh.mesh->save(unknown), unknown + ": cannot write mesh: OpenMesh cannot write '.xyz' files"))
        << mesh.mesh->save(unknown);
}

TEST(HostileInputs, CalibrateNamesTheOptionOutOfRangeAndWhy) {
    const Cli r = runCli({"calibrate", "--youngs-kpa", "1e308"});
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_TRUE(contains(r.output,
                         "palpate-cli calibrate: --youngs-kpa 1e308 is out of range: Young's modulus 1e+308 kPa"))
        << r.output;
    EXPECT_TRUE(contains(r.output, "below the smallest a slope-ring renders")) << r.output;
    EXPECT_FALSE(contains(r.output, "slopes must decrease")) << r.output;
    const Cli radius = runCli({"calibrate", "--tool-radius", "1e-300"});
    EXPECT_TRUE(contains(radius.output, "--tool-radius 1e-300 is out of range")) << radius.output;
}
