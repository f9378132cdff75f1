// palpate-cli score: the score of a recorded exercise session, with its breakdown. The recording
// is replayed through the engine (the exercise's physics from the recording's note) and scored
// tick by tick by the same scorer the live session uses (docs/scoring.md).
#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/common/DefaultScene.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"

#include <iostream>

namespace palpate::cli {

int scoreCommand(const std::vector<std::string>& words) {
    Args args(words, {"json"}, {"exercise", "recording", "mesh"});
    if (!args.ok()) {
        std::cerr << "score: " << args.error() << "\n";
        return 2;
    }
    std::optional<std::string> recording = args.option("recording");
    if (!recording && args.positional().size() == 1) recording = args.positional().front();
    else if (!args.positional().empty()) {
        std::cerr << "score: unexpected argument '" << args.positional().front() << "'\n";
        return 2;
    }
    if (!recording) {
        std::cerr << "score: --recording FILE is required (and --exercise FILE, unless the recording carries it)\n";
        return 2;
    }
    std::optional<Exercise> exercise;
    if (auto path = args.option("exercise")) {
        const auto loaded = loadExercise(*path);
        if (!loaded.exercise) {
            for (const auto& e : loaded.errors) std::cerr << "score: " << e << "\n";
            return 1;
        }
        exercise = *loaded.exercise;
    }
    const RecordingReader reader = RecordingReader::open(*recording);
    ReplayScorerDef options;
    options.findResource = findResource;
    options.meshPath = args.option("mesh").value_or("");
    std::string error;
    const ScoreReport report = scoreRecording(reader, exercise ? &*exercise : nullptr, error, options);
    if (!error.empty()) {
        std::cerr << "score: " << error << "\n";
        return 1;
    }
    if (args.flag("json")) std::cout << scoreReportToJson(report) << "\n";
    else std::cout << scoreReportToText(report);
    return 0;
}

}  // namespace palpate::cli
