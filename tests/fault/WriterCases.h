#pragma once
// The commands that write a file, and how the suite judges what each left behind: the product's
// own reader for recordings, meshes and presets; a comparison with a run without faults for the
// outputs it has no reader for (CSV, PDF). Shared by the write-fault, file-size and kill -9 cases.

#include "FaultRig.h"

#include <string>
#include <vector>

namespace palpate::fault {

enum class OutputKind { Recording, Csv, Mesh, Pdf, Preset };

struct Writer {
    std::string name;
    OutputKind kind;
    std::string outputName;  ///< the file name in out/
};

/// run --record, record export-csv --out, mesh generate --out, score --pdf, calibrate --out.
const std::vector<Writer>& writers();
const Writer& writerNamed(const std::string& name);

/// Copies the writer's inputs into scratch.in/ and returns them (to digest before and after).
std::vector<fs::path> prepareInputs(const Scratch& scratch, const Writer& writer);
/// The command line writing `output` (inputs as prepareInputs left them).
std::vector<std::string> writerArgs(const Scratch& scratch, const Writer& writer, const fs::path& output);
/// A valid file of the writer's kind, other than what the writer makes, to stand as the previous
/// output that a replacing write must not lose.
fs::path previousOutputFixture(const Writer& writer);

/// The writer's output from a run without faults (cached across processes).
fs::path baselineOutput(const Writer& writer);

/// The verdict on an output left behind. `printedTicks` is the count a run said it recorded.
struct OutputVerdict {
    bool exists = false;
    bool complete = false;  ///< what a run without faults makes (for recordings: intact, closed, ticks as printed)
    bool acceptable = false;  ///< complete, or a file the product's reader accepts (and as many ticks as printed)
    std::string why;  ///< for messages
};
OutputVerdict judgeOutput(const Scratch& scratch, const Writer& writer, const fs::path& output,
                          const std::string& commandOutput);

}  // namespace palpate::fault
