#include "OutputChecks.h"

#include <gtest/gtest.h>

namespace palpate::fault {

void checkWriterRun(const Scratch& scratch, const WriterCaseRun& run) {
    const ChildResult& r = run.result;
    SCOPED_TRACE(run.context + ": " + r.describe());
    EXPECT_TRUE(r.exited) << "the process must end by itself, neither killed by a signal nor hung";

    for (const auto& [path, before] : run.inputsBefore) EXPECT_EQ(digest(path), before) << "input changed: " << path;

    for (const auto& name : filesIn(run.output.parent_path())) {
        EXPECT_EQ(name, run.output.filename().string()) << "a file left beside the output";
    }

    const bool previousKept = run.previousDigest && digest(run.output) == *run.previousDigest;
    const OutputVerdict verdict = judgeOutput(scratch, *run.writer, run.output, r.out + r.err);
    if (verdict.exists && !previousKept) {
        EXPECT_TRUE(verdict.acceptable) << "an output the product's reader refuses: " << verdict.why;
    }

    if (r.succeeded()) {
        EXPECT_TRUE(verdict.complete) << "success reported, but the output is not complete: " << verdict.why;
        EXPECT_NE(run.expect, Expect::MustFail) << "success reported although the fault was met";
    } else if (r.exited) {
        EXPECT_NE(run.expect, Expect::MustSucceed) << "failed where nothing went wrong";
        EXPECT_TRUE(namesPath(r.err, run.output)) << "the message must name the output " << run.output;
        // A refusal without a fault must leave a previous file exactly as it was.
        if (run.expect == Expect::MayFail && run.previousDigest) {
            EXPECT_TRUE(previousKept) << "refused, and the previous file is gone: " << verdict.why;
        }
    }
}

}  // namespace palpate::fault
