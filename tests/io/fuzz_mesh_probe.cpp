// libFuzzer target for the mesh file probe: any bytes under any of the extensions it knows, no
// crash and no allocation beyond the file's own size (a declared count never sizes anything).
// The first byte picks the extension, the rest is the file. Built as `fuzz_mesh_probe` by the
// `fuzz` preset; io_tests runs the same function over tests/io/corpus/mesh and mutations of it.
#include "engine/core/MeshFileProbe.h"
#include "tests/io/FuzzCheck.h"

#include <cstdint>
#include <exception>
#include <string>

int palpateFuzzMeshProbe(const std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    if (size == 0) return 0;
    static const char* const kExtensions[] = {"off", "obj", "stl", "ply", "om", "xyz"};
    const std::string extension = kExtensions[data[0] % 6];
    const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        const std::string problem = probeMeshBytes(bytes, extension);
        if (extension == "xyz") fuzzCheck("fuzz_mesh_probe", !problem.empty());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_mesh_probe: exception escaped: %s\n", e.what());
        std::abort();
    }
    return 0;
}

#ifdef PALPATE_FUZZ_TARGET
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return palpateFuzzMeshProbe(data, size);
}
#endif
