// palpate-cli score: the score of a recorded exercise session, with its breakdown. The recording
// is replayed through the engine (the exercise's physics from the recording's note) and scored
// tick by tick by the same scorer the live session uses (docs/scoring.md). --pdf writes the
// printable report the GUI exports, through the same report/ code.
#include "app/cli/Commands.h"
#include "app/cli/MeshOption.h"
#include "base/resources/ShippedResources.h"
#include "engine/exercise/RecordedExercise.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/ReplayScorer.h"
#include "results/ServerLocation.h"
#ifdef PALPATE_HAVE_CHARTS
#include "app/cli/ResultsLocation.h"
#include "app/cli/StoreSession.h"
#include "results/ResultSync.h"
#include "results/ResultsDatabase.h"
#include "report/ScoreReportFromRecording.h"
#include "report/ScoreReportPdf.h"

#include <QDir>
#include <QFileInfo>
#endif

#include <nlohmann/json.hpp>

#include <iostream>

namespace palpate::cli {

namespace {

#ifdef PALPATE_HAVE_CHARTS
/// Stores the scored recording as the trainee's session: in the SQLite file --db names (default:
/// the GUI's), or, for a --db server, on this workstation first (--local, default the GUI's) and
/// then sent with whatever else waits. A server that does not answer leaves it waiting: stored all
/// the same (exit 0), and said on stderr. --json adds "proficiency" (judged against the trainee's
/// sessions before this one) and "stored".
int storeScore(const Given& args, const ScoreReport& report, std::optional<Exercise> exercise,
               const std::string& recording) {
    const std::string trainee = *args.option("trainee");
    const std::string location = args.option("db").value_or(defaultDatabasePath());
    const bool server = isServerLocationText(location);
    const std::string localPath = server ? args.option("local").value_or(defaultDatabasePath()) : location;
    const RecordingReader reader = RecordingReader::open(recording);
    std::vector<std::string> noteErrors;
    const std::optional<Exercise> graded = exercise ? exercise : recordedExercise(reader.header(), noteErrors);
    const std::string exerciseFile = args.option("exercise").value_or("");
    auto j = nlohmann::json::parse(scoreReportToJson(report));
    // Judged before it is stored: the trainee's earlier sessions, then this one.
    bool known = false;
    if (QFileInfo::exists(QString::fromStdString(localPath))) {
        ResultsDatabase before;
        if (before.open(QString::fromStdString(localPath)))
            for (const TraineeRecord& t : before.trainees()) known |= t.name.toStdString() == trainee;
    }
    if (graded && known) {
        std::string error;
        const std::string proficiency =
            proficiencyJsonForScore(report, *graded, exerciseFile, localPath, trainee, error);
        if (!error.empty()) {
            std::cerr << "score: --db: " << error << "\n";
            return 1;
        }
        if (!proficiency.empty()) j["proficiency"] = nlohmann::json::parse(proficiency);
    }
    QDir().mkpath(QFileInfo(QString::fromStdString(localPath)).absolutePath());
    ResultsDatabase local;
    QString qerror;
    if (!local.open(QString::fromStdString(localPath), &qerror)) {
        std::cerr << "score: " << qerror.toStdString() << "\n";
        return 1;
    }
    const QString exercisePath = exerciseFile.empty() ? QString() : exerciseKey(QString::fromStdString(exerciseFile), QString());
    const StoredSession session = storeScoredSession(local, trainee, report, graded, exercisePath, reader, recording, false);
    if (!session.notice.empty()) std::cerr << "score: " << session.notice << "\n";
    if (!session.stored || !session.error.empty()) {
        std::cerr << "score: " << session.error << "\n";
        return 1;
    }
    nlohmann::json stored = {{"database", local.path().toStdString()}, {"result_id", session.resultId},
                             {"trainee", trainee}, {"staircase", session.staircase}};
    if (server) {
        ResultsDatabase remote;
        SyncReport sync;
        if (!remote.open(QString::fromStdString(location), &qerror)) {
            sync.waiting = int(local.unsyncedResults().size());
            sync.error = qerror;
        } else {
            sync = syncResults(local, remote);
        }
        stored["server"] = remote.isOpen() ? remote.path().toStdString() : location;
        stored["sent"] = sync.sent + sync.alreadyThere;
        stored["waiting"] = sync.waiting;
        stored["server_error"] = sync.error.toStdString();
        if (!sync.error.isEmpty())
            std::cerr << "score: stored on this workstation (" << local.path().toStdString() << "); " << sync.waiting
                      << " result(s) wait for the server: " << sync.error.toStdString()
                      << " (palpate-cli results sync, or the window, sends them when it answers)\n";
    }
    if (args.flag("json")) {
        j["stored"] = stored;
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << scoreReportToText(report) << "stored for " << trainee << " in " << local.path().toStdString()
                  << (server && stored["server_error"].get<std::string>().empty() ? " and on the server" : "") << "\n";
    }
    return 0;
}
#endif

int scoreCommand(const Given& args) {
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
    if (args.option("db") && !args.option("trainee")) {
        std::cerr << "score: --db LOCATION goes with --trainee NAME (whose result it stores)\n";
        return 2;
    }
    // --trainee stores the result (docs/results-store.md, "Command line"), unless --no-store: then
    // it only names the trainee on the --pdf report.
    const bool store = args.option("trainee") && !args.flag("no-store");
    if (args.flag("no-store") && !(args.option("trainee") && pdf && !args.option("db"))) {
        std::cerr << "score: --no-store goes with --trainee NAME and --pdf FILE (the name on the report), without --db\n";
        return 2;
    }
    if (args.option("local") && !(args.option("db") && isServerLocationText(*args.option("db")))) {
        std::cerr << "score: --local FILE goes with --db postgresql://... (where the result waits for the server)\n";
        return 2;
    }
#ifndef PALPATE_HAVE_CHARTS
    if (store) {
        std::cerr << "score: storing a result needs a build with the GUI (Qt SQL); this one has none (--no-store only names "
                     "the trainee on the report)\n";
        return 2;
    }
#endif
    if (pdf) {
        // The report never replaces what it is made from, nor the database the result goes to.
        const std::string db = args.option("db").value_or("");
        for (const auto& [input, what] : {std::pair{*recording, "recording"},
                                          {args.option("exercise").value_or(""), "exercise"},
                                          {args.option("mesh").value_or(""), "mesh"},
                                          {isServerLocationText(db) ? std::string() : db, "results database"},
                                          {args.option("local").value_or(""), "results database"}})
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
#ifdef PALPATE_HAVE_CHARTS
    if (store) return storeScore(args, report, exercise, *recording);
#endif
    if (args.flag("json")) std::cout << scoreReportToJson(report) << "\n";
    else std::cout << scoreReportToText(report);
    return 0;
}

}  // namespace

void defineScoreCommand(CommandLine& cli) {
    CLI::App* score = cli.command(cli.root(), "score",
                                  "a recorded exercise session's score and breakdown (docs/scoring.md)", scoreCommand);
    addValue(*score, "recording", "FILE", "the recorded session (or give it as RECORDING)");
    addPositional(*score, "RECORDING", "the recorded session, when --recording is not given");
    addValue(*score, "exercise", "FILE", "the exercise (default: the one the recording carries)");
    addValue(*score, "mesh", "FILE", "score on this mesh instead of the recorded one");
    addMeshUnitOption(*score);
    addFlag(*score, "json", "print JSON");
    addValue(*score, "pdf", "FILE", "also write the printable report");
    addValue(*score, "trainee", "NAME", "store the result as this trainee's (docs/results-store.md)");
    addValue(*score, "db", "LOCATION", "where to store it: an SQLite file (default: the GUI's) or postgresql://...");
    addValue(*score, "local", "FILE", "with a --db server: where the result waits for it (default: the GUI's file)");
    addFlag(*score, "no-store", "with --trainee and --pdf: only name the trainee on the report");
}

}  // namespace palpate::cli
