#pragma once
// Trainees and their scored sessions, so that the GUI can show a trainee's history: one SQLite file
// per workstation (Qt SQL, QSQLITE), or a shared PostgreSQL server for a class (QPSQL; a
// postgresql:// URL, docs/results-store.md). Both back-ends have the same schema and the same
// versioned migrations (SQLite keeps the version in PRAGMA user_version, PostgreSQL in the table
// palpate_schema). Every write is one transaction: once addResult returns, the row is committed.
// Each result carries a unique id (uid), so that copying it to the server is idempotent.

#include "engine/exercise/ScoreReport.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QSqlDatabase>
#include <QString>
#include <QVariant>

#include <memory>
#include <optional>
#include <vector>

namespace palpate {

class ServerCallDeadline;

struct TraineeRecord {
    qint64 id = -1;
    QString name;
    QDateTime created;  ///< UTC
    QString className;  ///< the class on the server ("" on a workstation's own file, or unassigned)
};

/// How a stored session ended. A stopped one (Stop, or the recording stopped) is kept and listed,
/// but its partial score is not a score: it counts in neither the best nor the mean.
enum class ResultOutcome {
    Unknown,    ///< stored before schema version 3, which did not record it (counted as before)
    Completed,  ///< the task was done
    TimeUp,     ///< the time limit passed first: a scored attempt
    Stopped,    ///< ended before completion or the time limit
};

/// The outcome `report` describes (its guidance's completed / time_up).
ResultOutcome outcomeOf(const ScoreReport& report);
/// "completed", "time_up", "stopped"; "" for Unknown: the `outcome` column's text.
QString outcomeKey(ResultOutcome outcome);
ResultOutcome outcomeFromKey(const QString& key);
/// Whether a result with this outcome is a score (best, mean, the chart's lines): all but Stopped.
inline bool isScored(ResultOutcome outcome) { return outcome != ResultOutcome::Stopped; }

struct ResultRecord {
    qint64 id = -1;
    qint64 traineeId = -1;
    QString exerciseName;
    QString exercisePath;
    QDateTime startedUtc;
    double durationS = 0.0;
    double score = 0.0;
    QString metricsJson;    ///< `{name: value|null}`, as in `palpate-cli score --json`
    QString rubricJson;     ///< `{name: {value, sub_score, weight, contribution, full, zero}}`
    QString recordingPath;  ///< empty when the session was not recorded
    ResultOutcome outcome = ResultOutcome::Unknown;
    bool expert = false;    ///< an instructor's reference session: sets the proficiency standard
    QString aidsJson;       ///< `[{name, level}]`: the guidance aids shown (ScoreReport::aids)
    QString uid;            ///< unique across workstations (a UUID): the same result has the same uid everywhere
    QString workstation;    ///< the host that scored it
    QString syncedUtc;      ///< when it reached the shared server ("" while waiting); local databases only
    QString submittedBy;    ///< the database role that put it on the server ("" elsewhere)
    QString traineeName;    ///< filled by allResults()
    QString traineeClass;   ///< the trainee's class (TraineeRecord::className)
};

/// Whether `location` names a PostgreSQL server (postgresql:// or postgres://) rather than an
/// SQLite file.
bool isServerLocation(const QString& location);

/// How an exercise is told apart across sessions: by its file, the path made absolute (and
/// canonical when the file exists); a session stored without a path (an exercise carried by a
/// recording) is matched by the exercise's name. The same key names a trainee's staircase.
QString exerciseKey(const QString& exercisePath, const QString& exerciseName);
/// Whether the stored result is of that exercise (by exerciseKey).
bool isSameExercise(const ResultRecord& result, const QString& exercisePath, const QString& exerciseName);

class ResultsDatabase {
    Q_DECLARE_TR_FUNCTIONS(palpate::ResultsDatabase)
public:
    /// The version this build writes; files with a newer one are refused, older ones migrated.
    static constexpr int kSchemaVersion = 6;

    ResultsDatabase();
    ~ResultsDatabase();
    ResultsDatabase(const ResultsDatabase&) = delete;
    ResultsDatabase& operator=(const ResultsDatabase&) = delete;

    /// Opens (creating if missing) and migrates; on failure the message names the file and why.
    /// A postgresql://[user@]host[:port]/database[?sslmode=...] location opens the server: the
    /// password is never in the URL or the settings but found by libpq (PGPASSFILE or ~/.pgpass);
    /// TLS is used when the server offers it (sslmode=prefer unless the URL says otherwise).
    bool open(const QString& location, QString* error = nullptr);
    bool isServer() const { return mServer; }
    /// A store file this user may not write: opened to be read (listed, exported); every write
    /// fails, naming it read-only.
    bool isReadOnly() const { return mReadOnly; }
    void close();
    bool isOpen() const;
    /// Open, and a trivial query is answered now (a server that went away: false).
    bool answers() const;
    QString path() const { return mPath; }
    /// The version of the open file (kSchemaVersion after a successful open).
    int schemaVersion() const;

    /// The trainee's id; an existing name gives its id. -1 on error (empty name, database error).
    qint64 addTrainee(const QString& name, QString* error = nullptr);
    /// By name.
    std::vector<TraineeRecord> trainees() const;
    /// Stores a scored session with its outcome (outcomeOf(report)), committed before returning.
    /// -1 on error (unknown trainee, ...).
    qint64 addResult(qint64 traineeId, const ScoreReport& report, const QString& exerciseName,
                     const QString& exercisePath, const QDateTime& startedUtc, double durationS,
                     const QString& recordingPath, QString* error = nullptr);
    /// The same, marking the session as an expert's (instructor's reference) when `expert`.
    qint64 addResult(qint64 traineeId, const ScoreReport& report, const QString& exerciseName,
                     const QString& exercisePath, const QDateTime& startedUtc, double durationS,
                     const QString& recordingPath, bool expert, QString* error = nullptr);
    /// The trainee's results, oldest first (the History chart's order).
    std::vector<ResultRecord> results(qint64 traineeId) const;
    /// Every result with its trainee's name, oldest first.
    std::vector<ResultRecord> allResults() const;
    /// The results not yet on the shared server (syncedUtc empty), oldest first.
    std::vector<ResultRecord> unsyncedResults() const;
    /// Marks a result as on the server, committed before returning.
    bool markSynced(const QString& uid, const QDateTime& whenUtc, QString* error = nullptr);
    /// Copies a result from another database under `traineeName` (added if new), keeping its uid:
    /// a result already there (same uid) is left as it is. Returns whether it was new; nullopt on
    /// error. One transaction.
    std::optional<bool> importResult(const ResultRecord& result, const QString& traineeName, QString* error = nullptr);
    /// Every trainee's expert results of the exercise (isSameExercise), oldest first.
    std::vector<ResultRecord> expertResults(const QString& exercisePath, const QString& exerciseName) const;
    /// The trainee's staircase state (Staircase::toJson) for exerciseKey(...); "" when none yet.
    QString staircase(qint64 traineeId, const QString& exerciseKey) const;
    /// Stores (replaces) it, committed before returning.
    bool putStaircase(qint64 traineeId, const QString& exerciseKey, const QString& stateJson, QString* error = nullptr);
    QString lastError() const { return mLastError; }

    /// On a server: the role this connection logged in as, its class (docs/results-store.md,
    /// "Roles"; "" when the role is in none), and whether the connection is encrypted (TLS).
    QString serverRole() const { return mRole; }
    QString className() const { return mClassName; }
    bool isEncrypted() const { return mEncrypted; }
    /// "role alice, class 3B, TLS" (or "no TLS"): for tooltips and `results list`; "" for a file.
    QString connectionDescription() const;

    /// Runs `statements` in one transaction (the server's roles and grants, ResultsRoles.h); the
    /// first failure rolls back and names the statement's problem.
    bool runStatements(const QStringList& statements, QString* error = nullptr);
    /// `name` quoted as an SQL identifier, and `text` as a string literal, in this back-end's words.
    QString quotedIdentifier(const QString& name) const;
    QString quotedText(const QString& text) const;

    /// Writes an empty version-1 file (no recording_path): kept so that the migration is tested
    /// against the real old schema, not a guess at it.
    static bool createVersion1(const QString& path, QString* error = nullptr);

private:
    bool fail(const QString& problem, QString* error) const;
    /// On a server, every public call runs under a deadline (ServerCallDeadline.h); on a file, none.
    class ServerCall;
    ServerCall serverCall() const;
    bool migrate(int from, QString* error);
    /// "" when every table and column this build reads is there; else which one is missing.
    QString schemaProblem() const;
    /// Version 2 to 3: the outcome column, and `completed` for the old rows whose completion is 1
    /// (the rest cannot be told apart from a time-up and stay Unknown).
    QString migrateV2ToV3();
    std::vector<ResultRecord> selectResults(const QString& where, const QVariant& bind) const;

    /// The statement in this back-end's dialect (the schema is written for SQLite).
    QString adapt(const char* statement) const;
    QString setVersionStatement(int version) const;
    bool openServer(const QString& location, QString* error);
    QString migrateV4ToV5();

    QString mConnection;
    QString mPath;
    bool mServer = false;
    bool mReadOnly = false;
    QString mRole;
    QString mClassName;
    bool mEncrypted = false;
    QSqlDatabase mDb;
    std::unique_ptr<ServerCallDeadline> mDeadline;  ///< on a server only
    mutable QString mLastError;
};

}  // namespace palpate
