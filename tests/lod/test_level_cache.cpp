// The levels cache beside the mesh: written once, read back identical, and regenerated (never a
// crash) when the mesh changed, the options changed, or any part of it is missing or corrupt.
#include "engine/lod/LevelCache.h"
#include "engine/core/MeshHash.h"
#include "tests/engine/TestMeshes.h"
#include "tests/lod/LodTestMeshes.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

namespace palpate {
namespace {

namespace fs = std::filesystem;

class LevelCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        meshPath = dir.file("sphere.obj");
        const TissueMesh& generatedMesh = test::generated(GeneratedShape::Sphere, 1442);
        ASSERT_EQ(generatedMesh.save(meshPath), "");
        auto loaded = TissueMesh::load(meshPath);
        ASSERT_TRUE(loaded.mesh) << loaded.error();
        mesh.emplace(std::move(*loaded.mesh));
        options.minVertices = 150;
    }
    LevelCacheResult run(bool useCache = true) { return loadOrGenerateLevels(meshPath, *mesh, options, {}, nullptr, useCache); }
    std::string cacheDir() const { return levelCacheDir(meshPath); }
    void overwrite(const std::string& name, const std::string& bytes) const {
        std::ofstream(fs::path(cacheDir()) / name, std::ios::binary | std::ios::trunc) << bytes;
    }

    test::TempDir dir;
    std::string meshPath;
    std::optional<TissueMesh> mesh;
    LevelDef options;
};

/// The same levels: vertex counts and hashes.
void expectSameLevels(const MeshLevels& a, const MeshLevels& b) {
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (std::size_t k = 0; k < a.levels.size(); ++k) {
        EXPECT_EQ(meshHash(a.levels[k].mesh), meshHash(b.levels[k].mesh)) << "level " << k;
        EXPECT_EQ(a.levels[k].fineOnLevel.size(), b.levels[k].fineOnLevel.size());
        EXPECT_EQ(a.levels[k].levelOnFine.size(), b.levels[k].levelOnFine.size());
    }
    EXPECT_EQ(a.sourceHash, b.sourceHash);
}

TEST_F(LevelCacheTest, WrittenOnceThenReadBackIdentical) {
    const LevelCacheResult first = run();
    EXPECT_FALSE(first.fromCache);
    EXPECT_EQ(first.writeError, "");
    EXPECT_NE(first.cacheStatus.find("no cache"), std::string::npos) << first.cacheStatus;
    ASSERT_TRUE(fs::exists(fs::path(cacheDir()) / "levels.json"));
    ASSERT_GE(first.levels.levels.size(), 3u);
    for (const auto& entry : fs::directory_iterator(cacheDir()))
        EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();  // atomic writes leave no temporaries

    const LevelCacheResult second = run();
    EXPECT_TRUE(second.fromCache) << second.cacheStatus;
    expectSameLevels(first.levels, second.levels);
    // The mapping computed on load works like the generated one.
    const auto& fineRest = second.levels.levels[0].mesh.restPositionsMm();
    const auto shown = second.levels.toFine(2, second.levels.levels[2].mesh.restPositionsMm());
    for (std::size_t v = 0; v < fineRest.size(); ++v) EXPECT_LT(glm::length(shown[v] - fineRest[v]), 1e-3f);
}

TEST_F(LevelCacheTest, NotUsedWhenAskedNot) {
    run();
    const LevelCacheResult fresh = run(false);
    EXPECT_FALSE(fresh.fromCache);
    EXPECT_NE(fresh.cacheStatus.find("not used"), std::string::npos);
}

TEST_F(LevelCacheTest, StaleWhenTheMeshOrTheOptionsChange) {
    const LevelCacheResult first = run();
    // Another mesh written to the same path: its hash differs.
    ASSERT_EQ(test::generated(GeneratedShape::Stomach, 1442).save(meshPath), "");
    auto other = TissueMesh::load(meshPath);
    ASSERT_TRUE(other.mesh);
    mesh.emplace(std::move(*other.mesh));
    const LevelCacheResult afterMeshChange = run();
    EXPECT_FALSE(afterMeshChange.fromCache);
    EXPECT_NE(afterMeshChange.cacheStatus.find("stale"), std::string::npos) << afterMeshChange.cacheStatus;
    EXPECT_NE(meshHash(afterMeshChange.levels.levels[1].mesh), meshHash(first.levels.levels[1].mesh));
    EXPECT_TRUE(run().fromCache);  // and the new cache is used next time

    options.guards.maxAspectRatio = 8.0;
    const LevelCacheResult afterOptionChange = run();
    EXPECT_FALSE(afterOptionChange.fromCache);
    EXPECT_NE(afterOptionChange.cacheStatus.find("options"), std::string::npos) << afterOptionChange.cacheStatus;
}

TEST_F(LevelCacheTest, CorruptCachesAreRegeneratedNeverTrusted) {
    const LevelCacheResult good = run();
    const std::string index = test::readFile((fs::path(cacheDir()) / "levels.json").string());
    struct Damage {
        const char* what;
        std::function<void()> apply;
    };
    const std::vector<Damage> damages = {
        {"garbage index", [&] { overwrite("levels.json", std::string("\x01\x02{not json", 11)); }},
        {"empty index", [&] { overwrite("levels.json", ""); }},
        {"index of another kind", [&] { overwrite("levels.json", R"({"format": "palpate-exercise", "version": 1})"); }},
        {"index with a wrong type", [&] {
             std::string t = index;
             t.replace(t.find("\"levels\": ["), 11, "\"levels\": 5, \"x\": [");
             overwrite("levels.json", t);
         }},
        {"future version", [&] {
             std::string t = index;
             t.replace(t.find("\"version\": 1"), 12, "\"version\": 99");
             overwrite("levels.json", t);
         }},
        {"level file path escapes the folder", [&] {
             std::string t = index;
             t.replace(t.find("\"level1.obj\""), 12, "\"../sphere.obj\"");
             overwrite("levels.json", t);
         }},
        {"truncated level", [&] {
             const std::string level = test::readFile((fs::path(cacheDir()) / "level2.obj").string());
             overwrite("level2.obj", level.substr(0, level.size() / 2));
         }},
        {"missing level", [&] { fs::remove(fs::path(cacheDir()) / "level1.obj"); }},
        {"another level's file", [&] {
             fs::copy_file(fs::path(cacheDir()) / "level2.obj", fs::path(cacheDir()) / "level1.obj",
                           fs::copy_options::overwrite_existing);
         }},
    };
    for (const Damage& d : damages) {
        SCOPED_TRACE(d.what);
        ASSERT_TRUE(run().fromCache);  // intact before each damage
        d.apply();
        const LevelCacheResult r = run();
        EXPECT_FALSE(r.fromCache);
        EXPECT_EQ(r.cacheStatus.find("read from"), std::string::npos) << r.cacheStatus;
        expectSameLevels(good.levels, r.levels);
    }
}

TEST_F(LevelCacheTest, AnUnwritableCacheIsReportedAndTheLevelsAreStillGood) {
    // A plain file where the cache folder would go.
    std::ofstream(cacheDir()) << "in the way";
    const LevelCacheResult r = run();
    EXPECT_FALSE(r.fromCache);
    EXPECT_NE(r.writeError, "");
    EXPECT_NE(r.writeError.find(cacheDir()), std::string::npos) << r.writeError;
    EXPECT_GE(r.levels.levels.size(), 3u);
}

}  // namespace
}  // namespace palpate
