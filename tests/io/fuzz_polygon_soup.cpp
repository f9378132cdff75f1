// libFuzzer target for the polygon-soup reader (engine/core/PolygonSoup.h) and the triangulation
// after it: any bytes under any extension it knows, no crash, no hang, and a soup that is either
// whole (every index in range) or empty with a problem named. The first byte picks the extension
// (as for fuzz_mesh_probe, so the two share tests/io/corpus/mesh), the rest is the file. Built as
// `fuzz_polygon_soup` by the `fuzz` preset; io_tests runs the same function over the corpus and
// mutations of it.
#include "engine/core/PolygonSoup.h"
#include "tests/io/FuzzCheck.h"

#include <cstdint>
#include <exception>
#include <string>

int palpateFuzzPolygonSoup(const std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    if (size == 0) return 0;
    static const char* const kExtensions[] = {"off", "obj", "stl", "ply", "om", "xyz"};
    const std::string extension = kExtensions[data[0] % 6];
    const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        PolygonSoup soup;
        const std::string problem = readPolygonSoupBytes(bytes, extension, soup);
        if (!problem.empty()) {
            fuzzCheck("fuzz_polygon_soup", soup.points.empty() && soup.polygons.empty());
            return 0;
        }
        fuzzCheck("fuzz_polygon_soup", extension != "xyz");
        fuzzCheck("fuzz_polygon_soup", !soup.points.empty() && !soup.polygons.empty());
        std::size_t maxTriangles = 0;
        for (const auto& polygon : soup.polygons) {
            for (std::uint32_t v : polygon) fuzzCheck("fuzz_polygon_soup", v < soup.points.size());
            if (polygon.size() >= 3) maxTriangles += polygon.size() - 2;
        }
        std::vector<std::string> notes;
        const auto triangles = triangulatePolygons(soup, notes);
        fuzzCheck("fuzz_polygon_soup", triangles.size() <= maxTriangles);
        for (const auto& t : triangles)
            for (std::uint32_t v : t) fuzzCheck("fuzz_polygon_soup", v < soup.points.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_polygon_soup: exception escaped: %s\n", e.what());
        std::abort();
    }
    return 0;
}

#ifdef PALPATE_FUZZ_TARGET
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return palpateFuzzPolygonSoup(data, size);
}
#endif
