#include "tests/scoring/ScoringTestRig.h"

#include "device/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace palpate::test {

std::string resourcesDir() { return std::string(PALPATE_SOURCE_DIR) + "/resources"; }

ResourceFinder testResourceFinder() {
    return [](const std::string& relative) -> std::string {
        const std::filesystem::path p = std::filesystem::path(resourcesDir()) / relative;
        std::error_code ec;
        return std::filesystem::is_regular_file(p, ec) ? p.string() : std::string();
    };
}

Exercise loadExampleExercise(const std::string& name) {
    const auto loaded = loadExercise(resourcesDir() + "/exercises/" + name + ".json");
    if (!loaded.exercise) throw std::runtime_error(loaded.error());
    return *loaded.exercise;
}

TraineeScript loadTraineeScript(const std::string& path) {
    TraineeScript script;
    std::string error;
    if (!(error = loadWaypointFile(path, script.waypoints)).empty()) throw std::runtime_error(error);
    WaypointButtons buttons;
    if (!(error = loadWaypointButtons(path, buttons)).empty()) throw std::runtime_error(error);
    script.marksS = buttons.marksS;
    script.doneS = buttons.doneS.value_or(-1.0);
    return script;
}

std::uint64_t runScriptedSession(const Exercise& exercise, const TraineeScript& script,
                                 const std::string& recordingPath, const SessionRunDef& def) {
    std::vector<std::string> errors;
    auto assets = loadExerciseAssets(exercise, testResourceFinder(), errors);
    if (!assets) throw std::runtime_error(errors.front());
    std::string error;
    auto scene = createExerciseScene(*assets, error);
    if (!scene) throw std::runtime_error(error);
    auto device = std::make_unique<SimulatedDevice>(script.waypoints);
    if (!device->open()) throw std::runtime_error("the scripted device does not open");
    HapticLoopDef loopDef;
    loopDef.rateHz = assets->preset.hapticRateHz;
    loopDef.trySchedFifo = false;
    const RecordingHeader header = makeExerciseRecordingHeader(*assets, "sim:path:script", device->spec(),
                                                               loopDef.safety, "scripted trainee", error);
    if (!error.empty()) throw std::runtime_error(error);
    HapticLoop loop(loopDef, std::move(scene), std::move(device));
    auto session = RecordingSession::start(loop, recordingPath, header, error, def.writer);
    if (!session) throw std::runtime_error(error);

    double seconds = def.seconds;
    if (seconds < 0.0) seconds = std::min(script.durationS() + 1.0, exercise.timeLimitS + 0.5);
    const auto ticks = std::uint64_t(std::llround(seconds * loopDef.rateHz));
    std::size_t nextMark = 0;
    int deferredMarks = 0;
    bool doneMarked = false;
    for (std::uint64_t i = 1; i <= ticks; ++i) {
        if (def.tickOverran) loop.stepAt(double(i - 1) * loop.periodS(), def.tickOverran(i));
        else loop.stepOnce();
        const double nowS = double(i) * loop.periodS();
        // A mark is the user's: taken at the tick the loop has just run, as a GUI key would be.
        while (nextMark < script.marksS.size() && nowS >= script.marksS[nextMark]) {
            if (def.marksAfterFlush) ++deferredMarks;
            else session->mark("lump here");
            ++nextMark;
        }
        if (!doneMarked && script.doneS >= 0.0 && nowS >= script.doneS) {
            session->mark(kExaminationDoneMark);
            doneMarked = true;
        }
        if (i % def.flushEveryTicks == 0 || i == ticks) {
            const std::string problem = session->flush();
            if (!problem.empty()) throw std::runtime_error(problem);
            if (def.afterFlush) def.afterFlush(i);
            for (; deferredMarks > 0; --deferredMarks) session->mark("lump here (late)");
        }
    }
    const std::uint64_t hash = loop.report().determinismHash;
    const std::string problem = session->stop();
    if (!problem.empty()) throw std::runtime_error(problem);
    return hash;
}

}  // namespace palpate::test
