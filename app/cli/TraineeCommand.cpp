// palpate-cli trainee: trainees' sessions in the results database the GUI keeps (docs/scoring.md,
// "Proficiency" and "Staircase"): list them, add a scored session (an expert's sets the standard),
// the learning curve against the experts' pass marks (with --png a chart), the staircase's state.
// Also the proficiency object `palpate-cli score --db --trainee` adds to its JSON.
#include "app/cli/Commands.h"
#include "base/io/TerminalText.h"
#include "base/resources/ShippedResources.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/exercise/RecordedExercise.h"
#include "engine/record/RecordingReader.h"
#include "engine/scoring/Proficiency.h"
#include "engine/scoring/ReplayScorer.h"
#include "engine/scoring/Staircase.h"
#ifdef PALPATE_HAVE_CHARTS
#include "report/LearningCurveImage.h"
#include "results/LearningCurve.h"
#include "results/ResultsDatabase.h"
#include "app/cli/ResultsLocation.h"
#include "app/cli/StoreSession.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#endif

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>

namespace palpate::cli {

#ifndef PALPATE_HAVE_CHARTS
void defineTraineeCommands(CommandLine& cli) {
    cli.command(cli.root(), "trainee", "trainees' sessions (needs a build with the GUI)",
                [](const Given&) {
                    std::cerr << "trainee: needs a build with the GUI (Qt SQL); this one has none\n";
                    return 2;
                })
        ->allow_extras();
}

std::string proficiencyJsonForScore(const ScoreReport&, const Exercise&, const std::string&, const std::string&,
                                    const std::string&, std::string& error) {
    error = "the results database needs a build with the GUI (Qt SQL); this one has none";
    return {};
}
#else

namespace {

using Json = nlohmann::json;


Json optionalJson(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

Json standardJson(const ProficiencyStandard& s) {
    Json out = Json::object();
    for (const MetricStandard& m : s.metrics)
        out[m.metric] = {{"mean", m.mean}, {"sd", m.sd}, {"pass_mark", m.passMark},
                         {"higher_is_better", m.higherIsBetter}, {"deciding", m.deciding},
                         {"expert_sessions", m.expertSessions}};
    return out;
}

Json verdictMetricsJson(const SessionVerdict& v) {
    Json out = Json::object();
    for (const auto& [name, ok] : v.metrics) out[name] = ok ? Json(*ok) : Json(nullptr);
    return out;
}

bool openDatabase(ResultsDatabase& db, const Given& args, const char* command, bool mustExist) {
    const std::string path = args.option("db").value_or(defaultDatabasePath());
    if (mustExist && !QFileInfo::exists(QString::fromStdString(path))) {
        std::cerr << "trainee " << command << ": " << path << ": no results database there (give --db FILE)\n";
        return false;
    }
    if (!mustExist) QDir().mkpath(QFileInfo(QString::fromStdString(path)).absolutePath());
    QString error;
    if (!db.open(QString::fromStdString(path), &error)) {
        std::cerr << "trainee " << command << ": " << error.toStdString() << "\n";
        return false;
    }
    return true;
}

std::optional<qint64> findTrainee(const ResultsDatabase& db, const std::string& name, const char* command) {
    std::string known;
    for (const TraineeRecord& t : db.trainees()) {
        if (t.name.toStdString() == name) return t.id;
        known += (known.empty() ? "" : ", ") + t.name.toStdString();
    }
    std::cerr << "trainee " << command << ": no trainee '" << name << "' in " << db.path().toStdString()
              << (known.empty() ? std::string(" (it has none)") : " (trainees: " + known + ")") << "\n";
    return std::nullopt;
}

std::optional<Exercise> loadExerciseOption(const Given& args, const char* command, QString& path) {
    const auto file = args.option("exercise");
    if (!file) {
        std::cerr << "trainee " << command << ": --exercise FILE is required\n";
        return std::nullopt;
    }
    const auto loaded = loadExercise(*file);
    if (!loaded.exercise) {
        for (const auto& e : loaded.errors) std::cerr << "trainee " << command << ": " << e << "\n";
        return std::nullopt;
    }
    path = exerciseKey(QString::fromStdString(*file), QString());
    return loaded.exercise;
}

int listCommand(const Given& args) {
    ResultsDatabase db;
    if (!openDatabase(db, args, "list", true)) return 1;
    Json list = Json::array();
    for (const TraineeRecord& t : db.trainees()) {
        int sessions = 0, expert = 0;
        for (const ResultRecord& r : db.results(t.id)) ++sessions, expert += r.expert ? 1 : 0;
        list.push_back({{"name", t.name.toStdString()}, {"created", t.created.toString(Qt::ISODate).toStdString()},
                        {"sessions", sessions}, {"expert_sessions", expert}});
    }
    if (args.flag("json")) {
        std::cout << Json{{"database", db.path().toStdString()}, {"trainees", list}}.dump(2) << "\n";
        return 0;
    }
    if (list.empty()) std::cout << "no trainees in " << db.path().toStdString() << "\n";
    for (const Json& t : list)
        std::cout << terminalSafe(t["name"].get<std::string>()) << ": " << t["sessions"].get<int>() << " sessions ("
                  << t["expert_sessions"].get<int>() << " expert)\n";
    return 0;
}

int addSessionCommand(const Given& args) {
    if (!args.option("trainee") || !args.option("recording")) {
        std::cerr << "trainee add-session: --trainee NAME and --recording FILE are required\n";
        return 2;
    }
    std::optional<Exercise> exercise;
    QString exercisePath;
    if (args.option("exercise")) {
        exercise = loadExerciseOption(args, "add-session", exercisePath);
        if (!exercise) return 1;
    }
    const std::string recording = *args.option("recording");
    const RecordingReader reader = RecordingReader::open(recording);
    std::string error;
    ReplayScorerDef options;
    options.findResource = findResource;
    const ScoreReport report = scoreRecording(reader, exercise ? &*exercise : nullptr, error, options);
    if (!error.empty()) {
        std::cerr << "trainee add-session: " << error << "\n";
        return 1;
    }
    if (!exercise) {
        std::vector<std::string> errors;
        exercise = recordedExercise(reader.header(), errors);
    }
    ResultsDatabase db;
    if (!openDatabase(db, args, "add-session", false)) return 1;
    const bool expert = args.flag("expert");
    const StoredSession session =
        storeScoredSession(db, *args.option("trainee"), report, exercise, exercisePath, reader, recording, expert);
    if (!session.notice.empty()) std::cerr << "trainee add-session: " << session.notice << "\n";
    if (!session.error.empty()) {
        std::cerr << "trainee add-session: " << session.error << "\n";
        return 1;
    }
    const Json out = {{"result_id", session.resultId}, {"trainee", *args.option("trainee")},
                      {"exercise", session.exerciseName}, {"score", report.score}, {"expert", expert},
                      {"staircase", session.staircase}};
    if (args.flag("json")) std::cout << out.dump(2) << "\n";
    else
        std::cout << "stored session " << session.resultId << " of '" << terminalSafe(session.exerciseName) << "' for "
                  << terminalSafe(*args.option("trainee")) << (expert ? " (expert)" : "") << ": score " << report.score
                  << "\n";
    return 0;
}

int curveCommand(const Given& args) {
    if (!args.option("trainee")) {
        std::cerr << "trainee curve: --trainee NAME is required\n";
        return 2;
    }
    if (const auto png = args.option("png")) {
        // The chart never replaces what it is drawn from.
        const std::string problem =
            outputIsAnInput("png", *png, {{args.option("exercise").value_or(""), "exercise"},
                                            {args.option("db").value_or(defaultDatabasePath()), "results database"}});
        if (!problem.empty()) {
            std::cerr << "trainee curve: " << problem << "\n";
            return 2;
        }
    }
    QString path;
    const std::optional<Exercise> exercise = loadExerciseOption(args, "curve", path);
    if (!exercise) return args.option("exercise") ? 1 : 2;
    ResultsDatabase db;
    if (!openDatabase(db, args, "curve", true)) return 1;
    const auto trainee = findTrainee(db, *args.option("trainee"), "curve");
    if (!trainee) return 1;
    // Which metrics: those asked for, else the standard's deciding ones, else all the sessions have.
    std::vector<std::string> asked;
    if (const auto list = args.option("metric")) {
        for (const std::string& m : splitList(*list)) {
            if (!parseMetric(m)) {
                std::cerr << "trainee curve: --metric " << m << ": not a metric name (docs/scoring.md lists them)\n";
                return 2;
            }
            asked.push_back(m);
        }
    }
    const LearningCurve curve = learningCurve(db, *trainee, *exercise, path,
                                              QString::fromStdString(*args.option("trainee") + ": " + exercise->name), asked);
    if (curve.sessions.empty()) {
        std::cerr << "trainee curve: trainee '" << *args.option("trainee") << "' has no scored sessions of "
                  << path.toStdString() << " ('" << exercise->name << "')\n";
        return 1;
    }
    const std::vector<ResultRecord>& sessions = curve.sessions;
    const ProficiencyStandard& standard = curve.standard;
    const std::vector<MetricValues>& values = curve.values;
    const ProficiencyProgress& progress = curve.progress;
    const std::vector<std::string>& metrics = curve.metrics;
    Json out = {{"trainee", *args.option("trainee")}, {"exercise", exercise->name}, {"exercise_path", path.toStdString()},
                {"metrics", metrics}};
    out["standard"] = standard.valid() ? standardJson(standard) : Json(nullptr);
    if (!standard.valid()) out["no_standard"] = standard.problem;
    Json rows = Json::array();
    for (std::size_t i = 0; i < sessions.size(); ++i) {
        Json row = {{"session", i + 1}, {"id", sessions[i].id},
                    {"started_utc", sessions[i].startedUtc.toString(Qt::ISODate).toStdString()},
                    {"score", sessions[i].score}};
        Json v = Json::object();
        for (const std::string& m : metrics) {
            const auto it = values[i].find(m);
            v[m] = it == values[i].end() ? Json(nullptr) : optionalJson(it->second);
        }
        row["metrics"] = v;
        if (standard.valid()) {
            row["passed"] = progress.sessions[i].passed;
            row["metric_passed"] = verdictMetricsJson(progress.sessions[i]);
            row["consecutive_passes"] = progress.sessions[i].consecutivePasses;
        }
        rows.push_back(row);
    }
    out["sessions"] = rows;
    out["proficient"] = progress.proficient();
    out["proficient_at_session"] = progress.proficientAt ? Json(*progress.proficientAt + 1) : Json(nullptr);
    if (const auto png = args.option("png")) {
        const LearningCurveData& data = curve.chart;
        std::string error;
        if (!(error = renderLearningCurvePng(data, *png)).empty()) {
            std::cerr << "trainee curve: --png " << *png << ": " << error << "\n";
            return 1;
        }
        out["png"] = *png;
    }
    if (args.flag("json")) {
        std::cout << out.dump(2) << "\n";
        return 0;
    }
    std::cout << terminalSafe(*args.option("trainee")) << ", " << terminalSafe(exercise->name) << ": "
              << sessions.size() << " sessions\n";
    if (!standard.valid()) std::cout << standard.problem << "\n";
    else
        for (const MetricStandard& m : standard.metrics)
            std::cout << "  " << m.metric << ": expert mean " << m.mean << ", SD " << m.sd << ", pass "
                      << (m.higherIsBetter ? ">= " : "<= ") << m.passMark << (m.deciding ? "" : " (not deciding)")
                      << "\n";
    for (const Json& row : rows) {
        std::cout << "  session " << row["session"].get<std::size_t>() << ":";
        for (const std::string& m : metrics) std::cout << " " << m << "=" << row["metrics"][m].dump();
        if (row.contains("passed")) std::cout << (row["passed"].get<bool>() ? "  PASS" : "  fail");
        std::cout << "\n";
    }
    if (progress.proficientAt)
        std::cout << "proficient at session " << *progress.proficientAt + 1 << " (sessions " << *progress.proficientAt
                  << " and " << *progress.proficientAt + 1 << " passed)\n";
    else if (standard.valid())
        std::cout << "not yet proficient (two passing sessions in a row needed)\n";
    return 0;
}

int staircaseCommand(const Given& args) {
    if (!args.option("trainee")) {
        std::cerr << "trainee staircase: --trainee NAME is required\n";
        return 2;
    }
    QString path;
    const std::optional<Exercise> exercise = loadExerciseOption(args, "staircase", path);
    if (!exercise) return args.option("exercise") ? 1 : 2;
    if (!exercise->detectLumps.staircase) {
        std::cerr << "trainee staircase: " << path.toStdString() << " has no staircase (detect_lumps.staircase)\n";
        return 1;
    }
    ResultsDatabase db;
    if (!openDatabase(db, args, "staircase", true)) return 1;
    const auto trainee = findTrainee(db, *args.option("trainee"), "staircase");
    if (!trainee) return 1;
    const QString stored = db.staircase(*trainee, exerciseKey(path, QString::fromStdString(exercise->name)));
    std::optional<Staircase> s;
    if (stored.isEmpty()) {
        if (const std::string problem = staircaseDefProblem(*exercise->detectLumps.staircase); !problem.empty()) {
            std::cerr << "trainee staircase: " << path.toStdString() << ": " << problem << "\n";
            return 1;
        }
        s.emplace(*exercise->detectLumps.staircase);  // no trial yet: where the first one starts
    } else {
        std::string why;
        s = Staircase::fromJson(stored.toStdString(), why);
        if (!s) {
            std::cerr << "trainee staircase: " << why << "\n";
            return 1;
        }
    }
    Json history = Json::array();
    for (const StaircaseTrial& t : s->history()) history.push_back({{"level", t.level}, {"passed", t.passed}});
    const Json out = {{"trainee", *args.option("trainee")}, {"exercise", exercise->name},
                      {"parameter", staircaseParameterName(s->def().parameter)}, {"level", s->level()},
                      {"trials", s->history().size()}, {"history", history}, {"reversals", s->reversals()},
                      {"estimate", optionalJson(s->thresholdEstimate())}};
    if (args.flag("json")) std::cout << out.dump(2) << "\n";
    else
        std::cout << terminalSafe(*args.option("trainee")) << ", " << terminalSafe(exercise->name) << ": "
                  << staircaseParameterName(s->def().parameter) << " level " << s->level() << " after "
                  << s->history().size() << " trials, " << s->reversals().size() << " reversals, estimate "
                  << (s->thresholdEstimate() ? std::to_string(*s->thresholdEstimate()) : std::string("none yet"))
                  << "\n";
    return 0;
}

}  // namespace

std::string proficiencyJsonForScore(const ScoreReport& report, const Exercise& exercise, const std::string& exercisePath,
                                    const std::string& databasePath, const std::string& traineeName,
                                    std::string& error) {
    ResultsDatabase db;
    QString qerror;
    const std::string dbPath = databasePath.empty() ? defaultDatabasePath() : databasePath;
    if (!QFileInfo::exists(QString::fromStdString(dbPath))) {
        error = dbPath + ": no results database there";
        return {};
    }
    if (!db.open(QString::fromStdString(dbPath), &qerror)) {
        error = qerror.toStdString();
        return {};
    }
    std::optional<qint64> trainee;
    for (const TraineeRecord& t : db.trainees())
        if (t.name.toStdString() == traineeName) trainee = t.id;
    if (!trainee) {
        error = "no trainee '" + traineeName + "' in " + dbPath;
        return {};
    }
    const QString path = exerciseKey(QString::fromStdString(exercisePath), QString());
    const ProficiencyStandard standard = expertStandardFor(db, exercise, exercisePath.empty() ? QString() : path);
    if (standard.expertSessions == 0) return {};  // no expert sessions: nothing to add
    // The trainee's stored sessions, then this one (not stored by `score`).
    std::vector<MetricValues> values;
    for (const ResultRecord& r : traineeSessionsOf(db, *trainee, exercisePath.empty() ? QString() : path,
                                                 QString::fromStdString(exercise.name)))
        values.push_back(storedMetricValues(r));
    values.push_back(metricValues(report));
    Json out;
    if (!standard.valid()) {
        out = {{"standard", nullptr}, {"no_standard", standard.problem}};
        return out.dump();
    }
    const ProficiencyProgress progress = judgeSessions(standard, values);
    const SessionVerdict& last = progress.sessions.back();
    out = {{"standard", standardJson(standard)}, {"passed", last.passed}, {"metrics", verdictMetricsJson(last)},
           {"consecutive_passes", last.consecutivePasses}, {"proficient", progress.proficient()}};
    return out.dump();
}

void defineTraineeCommands(CommandLine& cli) {
    CLI::App* trainee = cli.group(cli.root(), "trainee",
                                  "trainees' sessions, learning curves and staircases (docs/scoring.md)");
    const std::string dbText = "the results database (default: the GUI's, results.sqlite in its data folder)";
    CLI::App* list = cli.command(*trainee, "list", "the trainees and their sessions", listCommand);
    addValue(*list, "db", "FILE", dbText);
    addFlag(*list, "json", "print JSON");

    CLI::App* add = cli.command(*trainee, "add-session", "score a recording and store it as a trainee's session",
                                addSessionCommand);
    addValue(*add, "trainee", "NAME", "the trainee (required)");
    addValue(*add, "recording", "FILE", "the recorded session (required)");
    addValue(*add, "exercise", "FILE", "the exercise (default: the one the recording carries)");
    addFlag(*add, "expert", "an expert's session: part of the exercise's standard");
    addValue(*add, "db", "FILE", dbText);
    addFlag(*add, "json", "print JSON");

    CLI::App* curve = cli.command(*trainee, "curve", "a trainee's learning curve on an exercise", curveCommand);
    addValue(*curve, "trainee", "NAME", "the trainee (required)");
    addValue(*curve, "exercise", "FILE", "the exercise (required)");
    addValue(*curve, "png", "FILE", "also draw the curve");
    addValue(*curve, "metric", "NAME,..", "the metrics to show (default: the exercise's)");
    addValue(*curve, "db", "FILE", dbText);
    addFlag(*curve, "json", "print JSON");

    CLI::App* staircase = cli.command(*trainee, "staircase", "where a trainee's staircase stands on an exercise",
                                      staircaseCommand);
    addValue(*staircase, "trainee", "NAME", "the trainee (required)");
    addValue(*staircase, "exercise", "FILE", "the exercise (required)");
    addValue(*staircase, "db", "FILE", dbText);
    addFlag(*staircase, "json", "print JSON");
}
#endif

}  // namespace palpate::cli
