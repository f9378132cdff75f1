#pragma once
// What the text parsers' fuzz targets share (tests/io/fuzz_*.cpp): an invariant that fails is a
// bug the fuzzer found, so say which and crash, which makes libFuzzer keep the input.

#include <cstdio>
#include <cstdlib>
#include <string>

#define fuzzCheck(target, condition)                                                                    \
    do {                                                                                                \
        if (!(condition)) {                                                                             \
            std::fprintf(stderr, "%s: invariant failed: %s (line %d)\n", target, #condition, __LINE__); \
            std::abort();                                                                               \
        }                                                                                               \
    } while (0)

/// Every message of a parser starts with the source it was given ("fuzz: ...").
template <class Messages>
bool allNameTheSource(const Messages& messages, const char* source) {
    for (const auto& m : messages)
        if (m.rfind(std::string(source) + ":", 0) != 0) return false;
    return true;
}
