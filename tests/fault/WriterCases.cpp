#include "WriterCases.h"

#include <fstream>
#include <stdexcept>

namespace palpate::fault {

const std::vector<Writer>& writers() {
    static const std::vector<Writer> all{
        {"run_record", OutputKind::Recording, "session.rec"},
        {"export_csv", OutputKind::Csv, "session.csv"},
        {"mesh_generate", OutputKind::Mesh, "generated.off"},
        {"score_pdf", OutputKind::Pdf, "report.pdf"},
        {"calibrate_preset", OutputKind::Preset, "calibrated.json"},
    };
    return all;
}

const Writer& writerNamed(const std::string& name) {
    for (const auto& w : writers())
        if (w.name == name) return w;
    throw std::invalid_argument("no writer " + name);
}

std::vector<fs::path> prepareInputs(const Scratch& scratch, const Writer& writer) {
    switch (writer.kind) {
    case OutputKind::Recording:
        copyFile(sourcePath("resources/meshes/stomach_1442.off"), scratch.in("stomach.off"));
        copyFile(sourcePath("resources/presets/default.json"), scratch.in("default.json"));
        return {scratch.in("stomach.off"), scratch.in("default.json")};
    case OutputKind::Csv:
        copyFile(fixtureRecording(), scratch.in("session.rec"));
        return {scratch.in("session.rec")};
    case OutputKind::Mesh:
        return {};
    case OutputKind::Pdf:
        copyFile(fixtureRecording(), scratch.in("session.rec"));
        // The recording names the exercise; the exercise and what it names are read in place.
        return {scratch.in("session.rec"), exercisePath()};
    case OutputKind::Preset:
        copyFile(sourcePath("resources/presets/tissues/liver.json"), scratch.in("liver.json"));
        return {scratch.in("liver.json")};
    }
    return {};
}

std::vector<std::string> writerArgs(const Scratch& scratch, const Writer& writer, const fs::path& output) {
    switch (writer.kind) {
    case OutputKind::Recording:
        return {"run", "--seconds", "0.3", "--mesh", scratch.in("stomach.off").string(), "--preset",
                scratch.in("default.json").string(), "--record", output.string()};
    case OutputKind::Csv:
        return {"record", "export-csv", scratch.in("session.rec").string(), "--out", output.string()};
    case OutputKind::Mesh:
        return {"mesh", "generate", "--shape", "sphere", "--vertices", "3000", "--out", output.string()};
    case OutputKind::Pdf:
        return {"score", "--recording", scratch.in("session.rec").string(), "--pdf", output.string()};
    case OutputKind::Preset:
        return {"calibrate", "--preset", scratch.in("liver.json").string(), "--out", output.string()};
    }
    return {};
}

fs::path baselineOutput(const Writer& writer) {
    const fs::path dir = cachedFixture("baseline-" + writer.name, [&](const fs::path& into) {
        Scratch scratch;
        prepareInputs(scratch, writer);
        const fs::path output = scratch.out(writer.outputName);
        const ChildResult r = runChild(cliSpec(scratch, writerArgs(scratch, writer, output)));
        if (!r.succeeded() || !fs::exists(output))
            throw std::runtime_error(writer.name + " without faults failed: " + r.describe());
        copyFile(output, into / writer.outputName);
    });
    return dir / writer.outputName;
}

fs::path previousOutputFixture(const Writer& writer) {
    const fs::path dir = cachedFixture("previous-" + writer.name, [&](const fs::path& into) {
        const fs::path file = into / writer.outputName;
        Scratch scratch;
        ChildResult r;
        switch (writer.kind) {
        case OutputKind::Recording: copyFile(fixtureRecording(), file); return;
        case OutputKind::Mesh: copyFile(sourcePath("resources/meshes/sphere_1442.off"), file); return;
        case OutputKind::Preset: copyFile(sourcePath("resources/presets/tissues/fat.json"), file); return;
        case OutputKind::Csv:
            r = runChild(cliSpec(scratch, {"record", "export-csv", fixtureRecording().string(), "--out", file.string()}));
            break;
        case OutputKind::Pdf:
            r = runChild(cliSpec(scratch, {"score", "--recording", fixtureRecording().string(), "--pdf", file.string()}));
            break;
        }
        if (!r.succeeded()) throw std::runtime_error("previous " + writer.name + ": " + r.describe());
        // Differ from what the writer makes, so that "the previous file" and "the new file" are told apart.
        if (writer.kind == OutputKind::Csv) {
            std::string text = readText(file);
            text.resize(text.size() / 2);
            text = text.substr(0, text.rfind('\n') + 1);
            std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
        }
    });
    return dir / writer.outputName;
}

namespace {

bool pdfComplete(const std::string& bytes, const std::string& baseline) {
    const std::string trailer = "%%EOF";
    return bytes.size() == baseline.size() && bytes.rfind("%PDF-", 0) == 0 &&
           bytes.find(trailer, bytes.size() > 16 ? bytes.size() - 16 : 0) != std::string::npos;
}

}  // namespace

OutputVerdict judgeOutput(const Scratch& scratch, const Writer& writer, const fs::path& output,
                          const std::string& commandOutput) {
    OutputVerdict v;
    v.exists = fs::exists(output);
    if (!v.exists) {
        v.why = "no output";
        return v;
    }
    const auto printed = printedRecordedTicks(commandOutput, output);
    switch (writer.kind) {
    case OutputKind::Recording: {
        const RecordingVerdict r = recordInfo(scratch, output);
        const bool ticksAsPrinted = !printed || r.ticks == *printed;
        v.acceptable = r.accepted && ticksAsPrinted;
        v.complete = v.acceptable && r.intact && r.closedCleanly && r.ticks > 0;
        v.why = r.accepted ? "record info: " + std::to_string(r.ticks) + " ticks" +
                                 (printed ? ", printed " + std::to_string(*printed) : std::string(", none printed")) +
                                 (r.intact ? ", intact" : ", damaged") + (r.closedCleanly ? ", closed" : ", not closed")
                           : "record info refuses it: " + r.problem;
        return v;
    }
    case OutputKind::Mesh: {
        v.complete = readText(output) == readText(baselineOutput(writer));
        std::string problem;
        v.acceptable = v.complete || meshAccepted(scratch, output, &problem);
        v.why = v.complete ? "complete" : v.acceptable ? "incomplete but mesh check accepts it" : "mesh check: " + problem;
        return v;
    }
    case OutputKind::Preset: {
        v.complete = readText(output) == readText(baselineOutput(writer));
        std::string problem;
        v.acceptable = v.complete || presetAccepted(scratch, output, &problem);
        v.why = v.complete ? "complete" : v.acceptable ? "other but loads" : "preset refused: " + problem;
        return v;
    }
    case OutputKind::Csv:
        v.complete = readText(output) == readText(baselineOutput(writer));
        v.acceptable = v.complete;  // no reader of its own: only the whole export will do
        v.why = v.complete ? "complete" : "a CSV that differs from the export without faults (" +
                                              std::to_string(fs::file_size(output)) + " bytes)";
        return v;
    case OutputKind::Pdf:
        v.complete = pdfComplete(readText(output), readText(baselineOutput(writer)));
        v.acceptable = v.complete;
        v.why = v.complete ? "complete" : "an incomplete PDF (" + std::to_string(fs::file_size(output)) + " bytes)";
        return v;
    }
    return v;
}

}  // namespace palpate::fault
