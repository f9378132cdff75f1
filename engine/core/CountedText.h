#pragma once
// A count in a message with its noun agreeing: "1 hole", "3 holes" (the mesh reports, the reader's
// notes, the repair's changes).

#include <cstddef>
#include <string>

namespace palpate {

inline std::string countedText(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace palpate
