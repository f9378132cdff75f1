// libFuzzer target for the tissue preset reader: any bytes, no crash, no exception, a result or
// errors (never both), every error naming the source, and a preset that loads writes JSON that
// loads back to the same preset. Built as `fuzz_preset` by the `fuzz` preset; io_tests runs the same
// function over tests/io/corpus/preset and deterministic mutations of it.
#include "engine/scene/TissuePreset.h"
#include "tests/io/FuzzCheck.h"

#include <cstdint>
#include <exception>
#include <string>

int palpateFuzzPreset(const std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const PresetLoadResult r = parseTissuePreset(text, "fuzz");
        fuzzCheck("fuzz_preset", r.preset.has_value() == r.errors.empty());
        fuzzCheck("fuzz_preset", allNameTheSource(r.errors, "fuzz"));
        if (r.preset) {
            const std::string written = tissuePresetToJson(*r.preset);
            const PresetLoadResult again = parseTissuePreset(written, "fuzz");
            fuzzCheck("fuzz_preset", again.preset.has_value());
            fuzzCheck("fuzz_preset", samePreset(*again.preset, *r.preset));
            fuzzCheck("fuzz_preset", tissuePresetToJson(*again.preset) == written);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_preset: exception escaped: %s\n", e.what());
        std::abort();
    }
    return 0;
}

#ifdef PALPATE_FUZZ_TARGET
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return palpateFuzzPreset(data, size);
}
#endif
