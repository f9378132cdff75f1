// palpate-cli results: the stored results of a workstation or of a class's server
// (docs/results-store.md). list and export read any database; sync copies this workstation's
// results that the server has not acknowledged (local first: nothing is lost while it is away).
#include "app/cli/Commands.h"

#include "base/io/CsvField.h"
#include "base/io/TerminalText.h"

#include <iostream>

#ifndef PALPATE_HAVE_CHARTS
namespace palpate::cli {
void defineResultsCommands(CommandLine& cli) {
    cli.command(cli.root(), "results", "the stored results (needs a build with the GUI)",
                [](const Given&) {
                    std::cerr << "results: needs a build with the GUI (Qt SQL); this one has none\n";
                    return 2;
                })
        ->allow_extras();
}
}  // namespace palpate::cli
#else
#include "app/cli/ResultsLocation.h"
#include "base/resources/ShippedResources.h"
#include "results/ClassSummary.h"
#include "results/ResultSync.h"
#include "results/ResultsRoles.h"
#include "results/ResultsDatabase.h"

#include <QDir>
#include <QFileInfo>

#include <nlohmann/json.hpp>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace palpate::cli {

namespace {

using Json = nlohmann::ordered_json;

/// A shipped exercise: its folder holds the examples a class trains on.
constexpr const char* kExampleExercise = "exercises/press_targets.json";

/// Opens `location`; a missing SQLite file is an error here (these commands only read it).
bool openExisting(ResultsDatabase& db, const std::string& location, const char* command) {
    const QString where = QString::fromStdString(location);
    if (!isServerLocation(where) && !QFileInfo::exists(where)) {
        std::cerr << "results " << command << ": " << location << ": no results database there (give --db)\n";
        return false;
    }
    QString error;
    if (!db.open(where, &error)) {
        std::cerr << "results " << command << ": " << error.toStdString() << "\n";
        return false;
    }
    return true;
}

std::string text(const QString& s) { return s.toStdString(); }

/// A name as the terminal shows it: its control characters escaped (TerminalText.h).
std::string shown(const QString& s) { return terminalSafe(s.toStdString()); }

int listCommand(const Given& args) {
    ResultsDatabase db;
    if (!openExisting(db, args.option("db").value_or(defaultDatabasePath()), "list")) return 1;
    const std::vector<ResultRecord> results = db.allResults();
    if (args.flag("json")) {
        Json list = Json::array();
        for (const ResultRecord& r : results)
            list.push_back({{"trainee", text(r.traineeName)},
                            {"exercise", text(r.exerciseName)},
                            {"score", r.score},
                            {"time", text(r.startedUtc.toString(Qt::ISODate))},
                            {"outcome", text(outcomeKey(r.outcome))},
                            {"expert", r.expert},
                            {"uid", text(r.uid)},
                            {"workstation", text(r.workstation)},
                            {"class", text(r.traineeClass)},
                            {"submitted_by", text(r.submittedBy)},
                            {"synced", db.isServer() ? Json(nullptr) : Json(!r.syncedUtc.isEmpty())}});
        Json out{{"database", text(db.path())}};
        if (db.isServer())
            out["connection"] = {{"role", text(db.serverRole())}, {"class", text(db.className())}, {"tls", db.isEncrypted()}};
        out["results"] = list;
        std::cout << out.dump(2) << "\n";
        return 0;
    }
    if (db.isServer()) std::cout << text(db.path()) << " (" << text(db.connectionDescription()) << ")\n";
    if (results.empty()) std::cout << "no results in " << text(db.path()) << "\n";
    for (const ResultRecord& r : results)
        std::cout << text(r.startedUtc.toString(Qt::ISODate)) << "  " << std::left << std::setw(16)
                  << shown(r.traineeName) << std::setw(28) << shown(r.exerciseName) << std::right << std::fixed
                  << std::setprecision(1) << std::setw(6) << r.score << "  " << text(outcomeKey(r.outcome))
                  << (db.isServer() || !r.syncedUtc.isEmpty() ? "" : "  (waiting for the server)") << "\n";
    return 0;
}

int exportCommand(const Given& args) {
    const auto csv = args.option("csv");
    if (!csv) {
        std::cerr << "results export: --csv FILE is required\n";
        return 2;
    }
    const std::string location = args.option("db").value_or(defaultDatabasePath());
    if (const std::string refused = outputIsAnInput("csv", *csv, {{location, "db"}}); !refused.empty()) {
        std::cerr << "results export: " << refused << "\n";
        return 2;
    }
    ResultsDatabase db;
    if (!openExisting(db, location, "export")) return 1;
    std::ostringstream out;
    out << "trainee,class,exercise,exercise_path,time,duration_s,score,outcome,expert,workstation,uid\n";
    for (const ResultRecord& r : db.allResults())
        out << csvTextField(text(r.traineeName)) << ',' << csvTextField(text(r.traineeClass)) << ','
            << csvTextField(text(r.exerciseName)) << ',' << csvTextField(text(r.exercisePath)) << ','
            << text(r.startedUtc.toString(Qt::ISODate)) << ',' << r.durationS << ',' << r.score << ','
            << text(outcomeKey(r.outcome)) << ',' << (r.expert ? 1 : 0) << ',' << csvTextField(text(r.workstation))
            << ',' << text(r.uid) << '\n';
    std::ofstream file(*csv);
    file << out.str();
    if (!file) {
        std::cerr << "results export: " << *csv << ": cannot be written\n";
        return 1;
    }
    return 0;
}

/// The instructor's class view: per trainee and exercise, sessions, latest and best, the verdict.
int classCommand(const Given& args) {
    const std::string location = args.option("db").value_or(defaultDatabasePath());
    if (const auto csv = args.option("csv"))
        if (const std::string refused = outputIsAnInput("csv", *csv, {{location, "db"}}); !refused.empty()) {
            std::cerr << "results class: " << refused << "\n";
            return 2;
        }
    ResultsDatabase db;
    if (!openExisting(db, location, "class")) return 1;
    std::vector<ResultRecord> results = db.allResults();
    if (const auto only = args.option("class"))
        std::erase_if(results, [&](const ResultRecord& r) { return r.traineeClass != QString::fromStdString(*only); });
    const std::vector<ClassRow> rows =
        classSummary(results, defaultExerciseLookup(QFileInfo(QString::fromStdString(findResource(kExampleExercise))).absolutePath()));
    if (const auto csv = args.option("csv")) {
        std::ofstream file(*csv);
        file << classSummaryCsv(rows).toStdString();
        if (!file) {
            std::cerr << "results class: " << *csv << ": cannot be written\n";
            return 1;
        }
    }
    if (args.flag("json")) {
        Json list = Json::array();
        for (const ClassRow& r : rows)
            list.push_back({{"trainee", text(r.trainee)},
                            {"class", text(r.className)},
                            {"exercise", text(r.exercise)},
                            {"sessions", r.sessions},
                            {"latest_score", r.latestScore},
                            {"latest_time", text(r.latestUtc.toString(Qt::ISODate))},
                            {"best_score", r.bestScore},
                            {"verdict", text(r.verdict)},
                            {"note", text(r.standardNote)}});
        std::cout << Json{{"database", text(db.path())}, {"rows", list}}.dump(2) << "\n";
        return 0;
    }
    if (rows.empty()) std::cout << "no trainee has a scored session in " << text(db.path()) << "\n";
    for (const ClassRow& r : rows)
        std::cout << std::left << std::setw(8) << (r.className.isEmpty() ? std::string("-") : shown(r.className))
                  << std::setw(16) << shown(r.trainee) << std::setw(28) << shown(r.exercise) << std::right
                  << std::setw(4) << r.sessions << std::fixed << std::setprecision(1) << std::setw(8) << r.latestScore
                  << std::setw(8) << r.bestScore << "  " << text(r.verdict)
                  << (r.standardNote.isEmpty() ? "" : " (" + text(r.standardNote) + ")") << "\n";
    return 0;
}

Json refusedJson(const SyncReport& report) {
    Json list = Json::array();
    for (const RefusedResult& r : report.refused)
        list.push_back({{"uid", text(r.uid)},
                        {"trainee", text(r.trainee)},
                        {"exercise", text(r.exercise)},
                        {"time", text(r.startedUtc.toString(Qt::ISODate))},
                        {"why", text(r.why)}});
    return list;
}

int syncCommand(const Given& args) {
    const auto url = args.option("db");
    if (!url || !isServerLocation(QString::fromStdString(*url))) {
        std::cerr << "results sync: --db postgresql://host/database (the class's server) is required\n";
        return 2;
    }
    ResultsDatabase local;
    if (!openExisting(local, args.option("local").value_or(defaultDatabasePath()), "sync")) return 1;
    ResultsDatabase server;
    QString error;
    SyncReport report;
    if (!server.open(QString::fromStdString(*url), &error)) {
        report.waiting = int(local.unsyncedResults().size());
        report.error = error;
    } else {
        report = syncResults(local, server);
    }
    if (args.flag("json"))
        std::cout << Json{{"local", text(local.path())},
                          {"server", text(server.isOpen() ? server.path() : QString::fromStdString(*url))},
                          {"sent", report.sent},
                          {"already_there", report.alreadyThere},
                          {"waiting", report.waiting},
                          {"error", text(report.error)},
                          {"refused", refusedJson(report)},
                          {"connection", text(report.connection)}}
                         .dump(2)
                  << "\n";
    else
        std::cout << report.sent << " sent, " << report.alreadyThere << " already on the server, " << report.waiting
                  << " waiting\n";
    for (const QString& line : report.refusedText().split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        std::cerr << "results sync: " << shown(line) << "\n";
    if (!report.error.isEmpty()) {
        std::cerr << "results sync: " << text(report.error) << " (" << report.waiting
                  << " results wait on this workstation; run sync again when the server answers)\n";
        return 1;
    }
    return report.refused.empty() ? 0 : 1;  // a refused result waits for someone to act
}

/// The server's roles: a workstation of a class, or an instructor (docs/results-store.md, "Roles").
int grantCommand(const Given& args) {
    const auto url = args.option("db");
    const auto workstation = args.option("workstation"), instructor = args.option("instructor");
    if (!url || !isServerLocation(QString::fromStdString(*url))) {
        std::cerr << "results grant: --db postgresql://host/database (the class's server) is required\n";
        return 2;
    }
    if (bool(workstation) == bool(instructor) || (workstation && !args.option("class")) ||
        (instructor && args.option("class"))) {
        std::cerr << "results grant: give --workstation ROLE --class NAME, or --instructor ROLE\n";
        return 2;
    }
    ResultsDatabase server;
    QString error;
    if (!server.open(QString::fromStdString(*url), &error)) {
        std::cerr << "results grant: " << text(error) << "\n";
        return 1;
    }
    const bool ok = workstation ? grantWorkstation(server, QString::fromStdString(*workstation),
                                                   QString::fromStdString(*args.option("class")), &error)
                                : grantInstructor(server, QString::fromStdString(*instructor), &error);
    if (!ok) {
        std::cerr << "results grant: " << text(error) << "\n";
        return 1;
    }
    if (workstation)
        std::cout << *workstation << ": a workstation of class " << *args.option("class")
                  << " (adds its class's trainees, sends its own results, reads its class)\n";
    else
        std::cout << *instructor << ": an instructor (reads every class)\n";
    return 0;
}

/// Takes a role's kind away (docs/results-store.md, "Roles").
int revokeCommand(const Given& args) {
    const auto url = args.option("db");
    const auto role = args.option("role");
    if (!url || !isServerLocation(QString::fromStdString(*url)) || !role) {
        std::cerr << "results revoke: --db postgresql://host/database and --role ROLE are required\n";
        return 2;
    }
    ResultsDatabase server;
    QString error;
    if (!server.open(QString::fromStdString(*url), &error) || !revokeRole(server, QString::fromStdString(*role), &error)) {
        std::cerr << "results revoke: " << text(error) << "\n";
        return 1;
    }
    std::cout << *role << ": neither a workstation nor an instructor now (what it sent stays)\n";
    return 0;
}

}  // namespace

void defineResultsCommands(CommandLine& cli) {
    CLI::App* results = cli.group(cli.root(), "results",
                                  "the stored results, and the class's server (docs/results-store.md)");
    results->footer(
        "LOCATION: an SQLite file (default: the GUI's results.sqlite) or postgresql://[user@]host[:port]/db;\n"
        "a server's password comes from ~/.pgpass or PGPASSFILE, never from the URL.");
    const std::string locationText = "an SQLite file (default: the GUI's) or postgresql://[user@]host[:port]/db";

    CLI::App* list = cli.command(*results, "list", "the trainees and their results", listCommand);
    addValue(*list, "db", "LOCATION", locationText);
    addFlag(*list, "json", "print JSON");

    CLI::App* exporting = cli.command(*results, "export", "every result as CSV", exportCommand);
    addValue(*exporting, "csv", "FILE", "the CSV file to write (required)");
    addValue(*exporting, "db", "LOCATION", locationText);

    CLI::App* sync = cli.command(*results, "sync", "copy this workstation's results to the server", syncCommand);
    addValue(*sync, "db", "URL", "the server: postgresql://[user@]host[:port]/db (required)");
    addValue(*sync, "local", "FILE", "this workstation's results (default: the GUI's)");
    addFlag(*sync, "json", "print JSON");

    CLI::App* classes = cli.command(*results, "class", "a class's results, per trainee", classCommand);
    addValue(*classes, "db", "LOCATION", locationText);
    addValue(*classes, "class", "NAME", "only this class");
    addFlag(*classes, "json", "print JSON");
    addValue(*classes, "csv", "FILE", "also write them as CSV");

    CLI::App* grant = cli.command(
        *results, "grant", "make a login role a workstation of a class, or an instructor (run as the tables' owner)",
        grantCommand);
    addValue(*grant, "db", "URL", "the server (required)");
    addValue(*grant, "workstation", "ROLE", "the role of a workstation (with --class)");
    addValue(*grant, "class", "NAME", "the workstation's class");
    addValue(*grant, "instructor", "ROLE", "the role of an instructor");

    CLI::App* revoke = cli.command(*results, "revoke", "a role is neither a workstation nor an instructor now",
                                   revokeCommand);
    addValue(*revoke, "db", "URL", "the server (required)");
    addValue(*revoke, "role", "ROLE", "the role (required)");
}

}  // namespace palpate::cli

#endif  // PALPATE_HAVE_CHARTS
