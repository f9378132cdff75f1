// The reader's fuzz target, run here over the corpus and a few thousand deterministic mutations of
// it (bit flips, truncations, insertions, duplicated and swapped chunks, length fields set to
// extremes), so that the normal test run keeps what the fuzzer once found.
#include "engine/record/RecordingFormat.h"
#include "engine/record/RecordingSession.h"
#include "tests/record/RecordTestRig.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
void fixRecordingCrcs(std::uint8_t* data, std::size_t size);

namespace {

std::vector<std::vector<std::uint8_t>> corpus() {
    std::vector<std::vector<std::uint8_t>> files;
    for (const auto& entry : std::filesystem::directory_iterator(PALPATE_RECORD_CORPUS_DIR))
        if (entry.is_regular_file()) files.push_back(palpate::test::readBytes(entry.path().string()));
    return files;
}

void run(const std::vector<std::uint8_t>& bytes) { LLVMFuzzerTestOneInput(bytes.data(), bytes.size()); }

}  // namespace

TEST(RecordFuzzCorpus, CorpusFilesPass) {
    const auto files = corpus();
    ASSERT_GE(files.size(), 4u) << PALPATE_RECORD_CORPUS_DIR;
    for (const auto& f : files) run(f);
}

TEST(RecordFuzzCorpus, DeterministicMutationsPass) {
    const auto files = corpus();
    ASSERT_FALSE(files.empty());
    std::mt19937_64 rng(20240601);
    const int kMutations = 4000;
    for (int i = 0; i < kMutations; ++i) {
        std::vector<std::uint8_t> m = files[rng() % files.size()];
        const int edits = 1 + int(rng() % 4);
        for (int e = 0; e < edits; ++e) {
            if (m.empty()) m.push_back(std::uint8_t(rng()));
            const std::size_t at = rng() % m.size();
            switch (rng() % 8) {
                case 0: m[at] ^= std::uint8_t(1u << (rng() % 8)); break;                   // bit flip
                case 1: m[at] = std::uint8_t(rng()); break;                                // byte
                case 2: m.resize(at); break;                                               // truncate
                case 3: m.insert(m.begin() + std::ptrdiff_t(at), std::size_t(rng() % 64), std::uint8_t(rng())); break;
                case 4: {                                                                  // duplicate a stretch
                    const std::size_t n = std::min<std::size_t>(m.size() - at, rng() % 300);
                    std::vector<std::uint8_t> copy(m.begin() + std::ptrdiff_t(at), m.begin() + std::ptrdiff_t(at + n));
                    m.insert(m.begin() + std::ptrdiff_t(rng() % (m.size() + 1)), copy.begin(), copy.end());
                    break;
                }
                case 5: {                                                                  // extreme 32-bit field
                    const std::uint32_t v = rng() % 2 ? 0xFFFFFFFFu : std::uint32_t(rng());
                    for (int b = 0; b < 4 && at + std::size_t(b) < m.size(); ++b) m[at + std::size_t(b)] = std::uint8_t(v >> (8 * b));
                    break;
                }
                case 6: m.erase(m.begin() + std::ptrdiff_t(at), m.begin() + std::ptrdiff_t(std::min(m.size(), at + rng() % 50))); break;
                default: {                                                                 // a chunk magic
                    const char magic[4] = {'P', 'C', 'H', 'K'};
                    for (int b = 0; b < 4 && at + std::size_t(b) < m.size(); ++b) m[at + std::size_t(b)] = std::uint8_t(magic[b]);
                }
            }
        }
        run(m);
        // The same bytes with their CRCs made right: the decoders behind the CRCs see garbage too.
        fixRecordingCrcs(m.data(), m.size());
        run(m);
    }
    SUCCEED() << kMutations << " mutations";
}

// Regenerates the corpus (run with --gtest_also_run_disabled_tests --gtest_filter=*WriteCorpus*):
// small recordings with every chunk and event kind, and a few damaged ones.
TEST(RecordFuzzCorpus, DISABLED_WriteCorpus) {
    using namespace palpate;
    using namespace palpate::test;
    TempDir dir;
    const std::filesystem::path out = PALPATE_RECORD_CORPUS_DIR;
    std::filesystem::create_directories(out);
    auto record = [&](const std::string& name, SimTrajectory trajectory, int ticks, const RecordingWriterDef& def,
                      bool events) {
        RecordRig rig = makeRecordRig(trajectory);
        rig.header.note = "corpus " + name;
        std::string error;
        auto session = RecordingSession::start(*rig.loop, dir.file(name), rig.header, error, def);
        ASSERT_TRUE(session) << error;
        for (int i = 0; i < ticks; ++i) {
            if (events && i == 40) {
                SlopeRingParams p;
                p.ringCount = 3;
                ASSERT_EQ(rig.loop->setModelParams(slopeRingModelDef(p)), "");
                session->mark("mark");
                session->exerciseEvent("{\"step\":1}");
                rig.loop->pause();
            }
            if (events && i == 50) rig.loop->resume();
            if (events && i == 60) {
                auto device = aimedDevice(rig.loop->scene().mesh(), SimTrajectory::Sine);
                const DeviceSpec spec = device->spec();
                ASSERT_EQ(session->swapDevice(std::move(device), {"sim:sine", spec}), "");
            }
            if (events && i == 70) {
                auto loaded = TissueMesh::load(smallSphereMeshPath());
                ASSERT_TRUE(loaded.mesh);
                const RecordedScene description = describeScene(*loaded.mesh, smallSphereMeshPath(), TissuePreset{});
                ASSERT_EQ(session->swapScene(HapticScene::create(std::move(*loaded.mesh), TissuePreset{}), description), "");
            }
            rig.loop->stepOnce();
        }
        ASSERT_EQ(session->stop(), "");
        rig.loop->collectRetired();
        const auto bytes = readBytes(dir.file(name));
        writeBytes((out / name).string(), bytes);
    };
    RecordingWriterDef small;
    small.ticksPerChunk = 16;
    record("events.palprec", SimTrajectory::Stroke, 120, small, true);
    record("press.palprec", SimTrajectory::PressHold, 1300, small, false);
    RecordingWriterDef gaps = small;
    gaps.ringCapacityTicks = 16;
    gaps.drainPeriodS = 0.1;
    record("gaps.palprec", SimTrajectory::Sine, 200, gaps, false);
    auto press = readBytes((out / "press.palprec").string());
    writeBytes((out / "truncated.palprec").string(), std::vector<std::uint8_t>(press.begin(), press.begin() + std::ptrdiff_t(press.size() * 2 / 3)));
    auto flipped = press;
    flipped[press.size() / 2] ^= 0x08;
    writeBytes((out / "flipped.palprec").string(), flipped);
    std::size_t headerBytes = 0;
    RecordingHeader header;
    std::string error;
    ASSERT_TRUE((error = decodeRecordingHeader(press.data(), press.size(), header, headerBytes)).empty());
    writeBytes((out / "header-only.palprec").string(), std::vector<std::uint8_t>(press.begin(), press.begin() + std::ptrdiff_t(headerBytes)));
}
