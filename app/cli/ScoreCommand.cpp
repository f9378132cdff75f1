// palpate-cli score: the score of a recorded exercise session, with its breakdown. The recording
// is replayed through the engine (the exercise's physics from the recording's note) and scored
// tick by tick by the same scorer the live session uses (docs/scoring.md). --pdf writes the
// printable report the GUI exports, through the same app/report code.
#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/MeshOption.h"
#include "app/common/DefaultScene.h"
#include "engine/exercise/RecordedExercise.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"
#ifdef PALPATE_HAVE_CHARTS
#include "app/report/ScoreReportFromRecording.h"
#include "app/report/ScoreReportPdf.h"
#endif

#include <nlohmann/json.hpp>

#include <iostream>

namespace palpate::cli {

int scoreCommand(const std::vector<std::string>& words) {
    Args args(words, {"json"}, {"exercise", "recording", "mesh", kMeshUnitOption, "pdf", "trainee", "db"});
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
    const std::optional<std::string> pdf = args.option("pdf");
#ifndef PALPATE_HAVE_CHARTS
    if (pdf) {
        std::cerr << "score: --pdf needs a build with the GUI (Qt); this one has none\n";
        return 2;
    }
#endif
    if (args.option("trainee") && !pdf && !args.option("db")) {
        std::cerr << "score: --trainee names the trainee on the --pdf report, or whose progress --db holds; give --pdf FILE "
                     "or --db FILE\n";
        return 2;
    }
    if (args.option("db") && !args.option("trainee")) {
        std::cerr << "score: --db FILE goes with --trainee NAME (the trainee whose proficiency to judge)\n";
        return 2;
    }
    if (pdf) {
        // The report never replaces what it is made from.
        for (const auto& [input, what] : {std::pair{*recording, "recording"},
                                          {args.option("exercise").value_or(""), "exercise"},
                                          {args.option("mesh").value_or(""), "mesh"}})
            if (!input.empty() && sameFile(*pdf, input)) {
                std::cerr << "score: --pdf " << *pdf << " is the " << what
                          << " file: the report is never written over an input; choose another file\n";
                return 2;
            }
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
    ReplayScorerDef options;
    options.findResource = findResource;
    options.meshPath = args.option("mesh").value_or("");
    // --mesh-unit: the unit of the --mesh file, when it is not the recorded one's.
    if (args.option(kMeshUnitOption)) {
        if (!args.option("mesh")) {
            std::cerr << "score: --mesh-unit goes with --mesh (the recording says its mesh's unit)\n";
            return 2;
        }
        std::string unitError;
        options.meshUnit = meshUnitFromArgs(args, unitError);
        if (!options.meshUnit) {
            std::cerr << "score: " << unitError << "\n";
            return 2;
        }
    }
    ScoreReport report;
#ifdef PALPATE_HAVE_CHARTS
    if (pdf) {
        // One replay gives the printed breakdown and the report's content.
        ScoreReportContent content;
        QString error;
        if (!scoreReportFromRecording(QString::fromStdString(*recording), exercise ? &*exercise : nullptr,
                                      QString::fromStdString(args.option("trainee").value_or("")), options, content,
                                      &error)) {
            std::cerr << "score: " << error.toStdString() << "\n";
            return 1;
        }
        if (!writeScoreReportPdf(QString::fromStdString(*pdf), content, &error)) {
            std::cerr << "score: " << error.toStdString() << "\n";
            return 1;
        }
        report = content.report;
    }
#endif
    if (!pdf) {
        const RecordingReader reader = RecordingReader::open(*recording);
        std::string error;
        report = scoreRecording(reader, exercise ? &*exercise : nullptr, error, options);
        if (!error.empty()) {
            std::cerr << "score: " << error << "\n";
            return 1;
        }
    }
    if (args.flag("json") && args.option("db")) {
        // The trainee's progress against the experts' standard (docs/scoring.md, "Proficiency").
        std::optional<Exercise> graded = exercise;
        if (!graded) {
            std::vector<std::string> errors;
            graded = recordedExercise(RecordingReader::open(*recording).header(), errors);
        }
        auto j = nlohmann::json::parse(scoreReportToJson(report));
        if (graded) {
            std::string error;
            const std::string proficiency =
                proficiencyJsonForScore(report, *graded, args.option("exercise").value_or(""), *args.option("db"),
                                        *args.option("trainee"), error);
            if (!error.empty()) {
                std::cerr << "score: --db: " << error << "\n";
                return 1;
            }
            if (!proficiency.empty()) j["proficiency"] = nlohmann::json::parse(proficiency);
        }
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    if (args.flag("json")) std::cout << scoreReportToJson(report) << "\n";
    else std::cout << scoreReportToText(report);
    return 0;
}

}  // namespace palpate::cli
