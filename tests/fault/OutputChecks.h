#pragma once
// The properties every writing case asserts (docs/reliability.md): the process ends by itself
// within its timeout; its inputs are byte-identical; no stray file is left beside the output; the
// output is absent, the previous file unchanged, or a file the product's reader accepts; success
// means a complete output; failure means a non-zero exit and a message naming the output's path.

#include "WriterCases.h"

#include <optional>
#include <string>

namespace palpate::fault {

enum class Expect { MustSucceed, MustFail, MayFail };

struct WriterCaseRun {
    const Writer* writer = nullptr;
    fs::path output;
    std::optional<std::string> previousDigest;  ///< when a previous output was in place
    std::map<std::string, std::string> inputsBefore;
    ChildResult result;
    Expect expect = Expect::MayFail;
    std::string context;  ///< the case, for messages
};

/// Adds a gtest failure for every property the run breaks.
void checkWriterRun(const Scratch& scratch, const WriterCaseRun& run);

}  // namespace palpate::fault
