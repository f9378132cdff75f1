// The text parsers' fuzz targets (fuzz_*.cpp), run here over their corpora and a few thousand
// deterministic mutations each (bit flips, bytes, truncations, insertions of tokens the parsers
// must survive: 1e400, quotes, brackets, NUL, huge counts), so that the normal test run keeps
// what the fuzzers once found.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

int palpateFuzzPreset(const std::uint8_t* data, std::size_t size);
int palpateFuzzExercise(const std::uint8_t* data, std::size_t size);
int palpateFuzzWaypoint(const std::uint8_t* data, std::size_t size);
int palpateFuzzMeshProbe(const std::uint8_t* data, std::size_t size);
int palpateFuzzPolygonSoup(const std::uint8_t* data, std::size_t size);
int palpateFuzzJson(const std::uint8_t* data, std::size_t size);
int palpateFuzzBundle(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::vector<std::uint8_t>;
using Target = int (*)(const std::uint8_t*, std::size_t);

std::vector<Bytes> corpus(const std::string& parser) {
    std::vector<Bytes> files;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(PALPATE_IO_CORPUS_DIR) + "/" + parser)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        const std::string text = s.str();
        files.emplace_back(text.begin(), text.end());
    }
    return files;
}

void mutate(Bytes& m, std::mt19937_64& rng) {
    static const char* const kTokens[] = {"1e400",     "-1e999",   "1e308",
                                          "\"",        "{",        "}",
                                          "[",         "]",        ",",
                                          ":",         "null",     "\"name\": 1,",
                                          "\\u0000",   "\xff\xfe", "9999999999999999999",
                                          "-0",        "nan",      "inf",
                                          "#",         "\n",       "\r\n",
                                          "\t",        "OFF",      "facet",
                                          "end_header"};
    const int edits = 1 + int(rng() % 4);
    for (int e = 0; e < edits; ++e) {
        if (m.empty()) m.push_back(std::uint8_t(rng()));
        const std::size_t at = rng() % m.size();
        switch (rng() % 8) {
            case 0: m[at] ^= std::uint8_t(1u << (rng() % 8)); break;
            case 1: m[at] = std::uint8_t(rng()); break;
            case 2: m.resize(at); break;
            case 3: {
                const std::string t = kTokens[rng() % (sizeof kTokens / sizeof *kTokens)];
                m.insert(m.begin() + std::ptrdiff_t(at), t.begin(), t.end());
                break;
            }
            case 4: {  // a stretch duplicated elsewhere (a key or a line given twice)
                const std::size_t n = std::min<std::size_t>(m.size() - at, rng() % 200);
                const Bytes copy(m.begin() + std::ptrdiff_t(at), m.begin() + std::ptrdiff_t(at + n));
                m.insert(m.begin() + std::ptrdiff_t(rng() % (m.size() + 1)), copy.begin(), copy.end());
                break;
            }
            case 5: {  // a digit run replaced by a huge number
                const std::string big = rng() % 2 ? "4294967296" : "99999999999";
                m.insert(m.begin() + std::ptrdiff_t(at), big.begin(), big.end());
                break;
            }
            case 6:
                m.erase(m.begin() + std::ptrdiff_t(at),
                        m.begin() + std::ptrdiff_t(std::min(m.size(), at + rng() % 40)));
                break;
            default: m.insert(m.begin() + std::ptrdiff_t(at), std::size_t(rng() % 8), std::uint8_t(rng())); break;
        }
    }
}

void runCorpusAndMutations(const std::string& parser, Target target, int mutations, std::uint64_t seed) {
    const auto files = corpus(parser);
    ASSERT_GE(files.size(), 12u) << PALPATE_IO_CORPUS_DIR << "/" << parser;
    for (const Bytes& f : files) target(f.data(), f.size());
    std::mt19937_64 rng(seed);
    for (int i = 0; i < mutations; ++i) {
        Bytes m = files[rng() % files.size()];
        mutate(m, rng);
        target(m.data(), m.size());
    }
}

}  // namespace

TEST(IoFuzzCorpus, PresetCorpusAndMutationsPass) { runCorpusAndMutations("preset", palpateFuzzPreset, 3000, 1); }
TEST(IoFuzzCorpus, ExerciseCorpusAndMutationsPass) { runCorpusAndMutations("exercise", palpateFuzzExercise, 3000, 2); }
TEST(IoFuzzCorpus, WaypointCorpusAndMutationsPass) { runCorpusAndMutations("waypoint", palpateFuzzWaypoint, 4000, 3); }
TEST(IoFuzzCorpus, MeshProbeCorpusAndMutationsPass) { runCorpusAndMutations("mesh", palpateFuzzMeshProbe, 4000, 4); }
TEST(IoFuzzCorpus, PolygonSoupCorpusAndMutationsPass) { runCorpusAndMutations("mesh", palpateFuzzPolygonSoup, 4000, 6); }
TEST(IoFuzzCorpus, JsonCorpusAndMutationsPass) { runCorpusAndMutations("json", palpateFuzzJson, 4000, 5); }
TEST(IoFuzzCorpus, BundleCorpusAndMutationsPass) { runCorpusAndMutations("bundle", palpateFuzzBundle, 3000, 7); }
