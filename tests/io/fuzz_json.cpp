// libFuzzer target for the JSON reader every versioned file goes through (base/io/JsonReader):
// any bytes, no exception; a parse fails exactly when it records an error naming the source; what
// parses is written and parsed again to the same value. Built as `fuzz_json` by the `fuzz` preset;
// io_tests runs the same function over tests/io/corpus/json and deterministic mutations of it.
#include "base/io/JsonReader.h"
#include "tests/io/FuzzCheck.h"

#include <cstdint>
#include <exception>
#include <string>
#include <vector>

int palpateFuzzJson(const std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        std::vector<std::string> errors;
        JsonReader r(errors, "fuzz");
        const std::optional<Json> j = r.parse(text);
        fuzzCheck("fuzz_json", j.has_value() == errors.empty());
        fuzzCheck("fuzz_json", allNameTheSource(errors, "fuzz"));
        if (j) {
            std::vector<std::string> again;
            JsonReader r2(again, "fuzz");
            const std::optional<Json> k = r2.parse(j->dump());
            fuzzCheck("fuzz_json", k.has_value());
            fuzzCheck("fuzz_json", k->dump() == j->dump());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_json: exception escaped: %s\n", e.what());
        std::abort();
    }
    return 0;
}

#ifdef PALPATE_FUZZ_TARGET
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return palpateFuzzJson(data, size);
}
#endif
