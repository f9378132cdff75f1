// libFuzzer target for the exercise bundle reader: any bytes, no crash, no exception, a bundle or
// an error (never both), the error naming the source, and a bundle's files all plain names with
// their exercise naming its own mesh. Built as `fuzz_bundle` by the `fuzz` preset; io_tests runs
// the same function over tests/io/corpus/bundle and deterministic mutations of it.
#include "engine/exercise/ExerciseBundle.h"
#include "tests/io/FuzzCheck.h"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <string>

int palpateFuzzBundle(const std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        std::string error;
        const auto bundle = parseExerciseBundle(text, "fuzz", error);
        fuzzCheck("fuzz_bundle", bundle.has_value() == error.empty());
        fuzzCheck("fuzz_bundle", bundle || error.rfind("fuzz", 0) == 0);
        if (bundle) {
            for (const ParsedBundle::File& f : bundle->files)
                fuzzCheck("fuzz_bundle", !f.name.empty() && f.name.find('/') == std::string::npos && f.name != "..");
            fuzzCheck("fuzz_bundle",
                      std::any_of(bundle->files.begin(), bundle->files.end(), [&](const ParsedBundle::File& f) {
                          return f.role == ParsedBundle::File::Role::Mesh && f.name == bundle->exercise.meshPath;
                      }));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_bundle: exception escaped: %s\n", e.what());
        std::abort();
    }
    return 0;
}

#ifdef PALPATE_FUZZ_TARGET
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return palpateFuzzBundle(data, size);
}
#endif
