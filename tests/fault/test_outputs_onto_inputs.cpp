// Family e of docs/reliability.md: an output named like one of the command's inputs (directly,
// through a symlink, a hard link or another spelling of the path), and a recording onto an existing
// recording without an explicit choice to replace it. An input is never overwritten by an output:
// every such command must refuse, name the file, and leave every input byte-identical.

#include "OutputChecks.h"

#include <unistd.h>

#include <gtest/gtest.h>

namespace palpate::fault {
namespace {

struct OntoCase {
    std::string name;
    // Prepares the inputs in scratch.in/, returns the command line and the files that must survive.
    std::function<std::pair<std::vector<std::string>, std::vector<fs::path>>(const Scratch&)> prepare;
    fs::path (*named)(const Scratch&);  ///< the path the message must name
};

void PrintTo(const OntoCase& c, std::ostream* os) { *os << c.name; }

fs::path meshIn(const Scratch& s) { return s.in("stomach.off"); }
fs::path presetIn(const Scratch& s) { return s.in("default.json"); }
fs::path exerciseIn(const Scratch& s) { return s.in("press_targets.json"); }
fs::path waypointsIn(const Scratch& s) { return s.in("trace.path"); }
fs::path recordingIn(const Scratch& s) { return s.in("session.rec"); }
fs::path linkIn(const Scratch& s) { return s.in("link.rec"); }
fs::path tissueIn(const Scratch& s) { return s.in("liver.json"); }

void copyAll(const Scratch& s) {
    copyFile(sourcePath("resources/meshes/stomach_1442.off"), meshIn(s));
    copyFile(sourcePath("resources/presets/default.json"), presetIn(s));
    copyFile(exercisePath(), exerciseIn(s));  // its mesh and preset are found among the resources
    copyFile(sourcePath("resources/exercises/trace.good.path"), waypointsIn(s));
    copyFile(fixtureRecording(), recordingIn(s));
    copyFile(sourcePath("resources/presets/tissues/liver.json"), tissueIn(s));
}

std::vector<fs::path> allInputs(const Scratch& s) {
    return {meshIn(s), presetIn(s), exerciseIn(s), waypointsIn(s), recordingIn(s), tissueIn(s)};
}

using Prepared = std::pair<std::vector<std::string>, std::vector<fs::path>>;

std::vector<std::string> runRecording(const Scratch& s, const std::string& record) {
    return {"run", "--seconds", "0.2", "--mesh", meshIn(s).string(), "--preset", presetIn(s).string(), "--record", record};
}

const std::vector<OntoCase>& ontoCases() {
    static const std::vector<OntoCase> all{
        {"run_record_onto_mesh", [](const Scratch& s) { return Prepared{runRecording(s, meshIn(s).string()), allInputs(s)}; },
         meshIn},
        {"run_record_onto_preset",
         [](const Scratch& s) { return Prepared{runRecording(s, presetIn(s).string()), allInputs(s)}; }, presetIn},
        {"run_record_onto_exercise",
         [](const Scratch& s) {
             return Prepared{{"run", "--seconds", "0.2", "--exercise", exerciseIn(s).string(), "--record",
                              exerciseIn(s).string()},
                             allInputs(s)};
         },
         exerciseIn},
        {"run_record_onto_waypoints",
         [](const Scratch& s) {
             return Prepared{{"run", "--seconds", "0.2", "--device", "sim:path:" + waypointsIn(s).string(), "--record",
                              waypointsIn(s).string()},
                             allInputs(s)};
         },
         waypointsIn},
        {"run_record_onto_mesh_through_a_symlink",
         [](const Scratch& s) {
             fs::create_symlink(meshIn(s), linkIn(s));
             return Prepared{runRecording(s, linkIn(s).string()), allInputs(s)};
         },
         linkIn},
        {"run_record_onto_mesh_through_a_hard_link",
         [](const Scratch& s) {
             fs::create_hard_link(meshIn(s), linkIn(s));
             return Prepared{runRecording(s, linkIn(s).string()), allInputs(s)};
         },
         linkIn},
        {"export_csv_onto_its_recording",
         [](const Scratch& s) {
             return Prepared{{"record", "export-csv", recordingIn(s).string(), "--out", recordingIn(s).string()}, allInputs(s)};
         },
         recordingIn},
        {"export_csv_onto_its_recording_spelt_otherwise",
         [](const Scratch& s) {
             const std::string other = (s.inDir() / ".." / "in" / "." / "session.rec").string();
             return Prepared{{"record", "export-csv", recordingIn(s).string(), "--out", other}, allInputs(s)};
         },
         recordingIn},
        {"score_pdf_onto_the_recording",
         [](const Scratch& s) {
             return Prepared{{"score", "--recording", recordingIn(s).string(), "--pdf", recordingIn(s).string()}, allInputs(s)};
         },
         recordingIn},
        {"score_pdf_onto_the_exercise",
         [](const Scratch& s) {
             return Prepared{{"score", "--recording", recordingIn(s).string(), "--exercise", exerciseIn(s).string(), "--pdf",
                              exerciseIn(s).string()},
                             allInputs(s)};
         },
         exerciseIn},
        {"calibrate_out_onto_its_preset",
         [](const Scratch& s) {
             return Prepared{{"calibrate", "--preset", tissueIn(s).string(), "--out", tissueIn(s).string()}, allInputs(s)};
         },
         tissueIn},
        // Not an input of this run, but a recording the user did not ask to replace.
        {"run_record_onto_an_existing_recording",
         [](const Scratch& s) { return Prepared{runRecording(s, recordingIn(s).string()), allInputs(s)}; }, recordingIn},
    };
    return all;
}

class OutputsOntoInputs : public testing::TestWithParam<OntoCase> {};

TEST_P(OutputsOntoInputs, RefusedAndEveryInputKept) {
    const OntoCase& c = GetParam();
    if (c.name.rfind("score_pdf", 0) == 0 && !havePdf()) GTEST_SKIP() << "this build has no score --pdf (PALPATE_BUILD_GUI=OFF)";
    Scratch scratch;
    copyAll(scratch);
    const auto [args, inputs] = c.prepare(scratch);
    const auto before = digests(inputs);
    const ChildResult r = runChild(cliSpec(scratch, args));
    SCOPED_TRACE(c.name + ": " + r.describe());
    EXPECT_TRUE(r.exited) << "the process must end by itself";
    EXPECT_NE(r.exitCode, 0) << "an output onto an input must be refused";
    EXPECT_TRUE(namesPath(r.err, c.named(scratch))) << "the message must name " << c.named(scratch);
    for (const auto& [path, digestBefore] : before) {
        EXPECT_EQ(digest(path), digestBefore) << "input overwritten: " << path;
    }
    for (const auto& name : filesIn(scratch.inDir())) {
        EXPECT_TRUE(name == "link.rec" || before.count(scratch.in(name).string())) << "a file left among the inputs: " << name;
    }
}

INSTANTIATE_TEST_SUITE_P(FamilyE, OutputsOntoInputs, testing::ValuesIn(ontoCases()),
                         [](const testing::TestParamInfo<OntoCase>& info) { return info.param.name; });

}  // namespace
}  // namespace palpate::fault
