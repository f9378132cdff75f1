// libFuzzer target for the exercise reader: any bytes, no crash, no exception, a result or errors
// (never both), every error naming the source, and an exercise that loads writes JSON that loads
// back to the same JSON. Built as `fuzz_exercise` by the `fuzz` preset; io_tests runs the same
// function over tests/io/corpus/exercise and deterministic mutations of it.
#include "engine/exercise/ExerciseFile.h"
#include "tests/io/FuzzCheck.h"

#include <cstdint>
#include <exception>
#include <string>

int palpateFuzzExercise(const std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const ExerciseLoadResult r = parseExercise(text, "fuzz");
        fuzzCheck("fuzz_exercise", r.exercise.has_value() == r.errors.empty());
        fuzzCheck("fuzz_exercise", allNameTheSource(r.errors, "fuzz"));
        if (r.exercise) {
            const std::string written = exerciseToJson(*r.exercise);
            const ExerciseLoadResult again = parseExercise(written, "fuzz");
            fuzzCheck("fuzz_exercise", again.exercise.has_value());
            fuzzCheck("fuzz_exercise", exerciseToJson(*again.exercise) == written);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_exercise: exception escaped: %s\n", e.what());
        std::abort();
    }
    return 0;
}

#ifdef PALPATE_FUZZ_TARGET
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return palpateFuzzExercise(data, size);
}
#endif
