#include "results/ResultsDatabase.h"

#include "results/ServerCallDeadline.h"
#include "results/ServerConnectOptions.h"

#include "results/ServerLocation.h"

#include <QDir>
#include <QFileInfo>
#include <QSysInfo>
#include <QUrl>
#include <QUrlQuery>
#include <QUuid>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlDriver>
#include <QSqlError>
#include <QSqlField>
#include <QSqlQuery>
#include <QSqlRecord>
#include <QVariant>

#include <libpq-fe.h>

#include <atomic>
#include <vector>

namespace palpate {

namespace {

std::atomic<int> gConnectionCounter{0};

// Version 1: the first release (no recording path). Kept verbatim for createVersion1().
const char* const kSchemaV1[] = {
    "CREATE TABLE trainees (id INTEGER PRIMARY KEY AUTOINCREMENT, name TEXT NOT NULL UNIQUE,"
    " created TEXT NOT NULL)",
    "CREATE TABLE results (id INTEGER PRIMARY KEY AUTOINCREMENT,"
    " trainee_id INTEGER NOT NULL REFERENCES trainees(id),"
    " exercise_name TEXT NOT NULL, exercise_path TEXT NOT NULL, started_utc TEXT NOT NULL,"
    " duration_s REAL NOT NULL, score REAL NOT NULL, metrics_json TEXT NOT NULL,"
    " rubric_json TEXT NOT NULL)",
    "CREATE INDEX results_by_trainee ON results(trainee_id, started_utc)",
    "PRAGMA user_version = 1",
};

// Version 2: the recording a result was scored from.
const char* const kMigrateV1ToV2[] = {
    "ALTER TABLE results ADD COLUMN recording_path TEXT NOT NULL DEFAULT ''",
    "PRAGMA user_version = 2",
};

// Version 3: how the session ended (ResultOutcome); '' for the rows stored before.
const char* const kMigrateV2ToV3[] = {
    "ALTER TABLE results ADD COLUMN outcome TEXT NOT NULL DEFAULT ''",
};

// Version 4: expert (reference) sessions, the guidance aids shown, and each trainee's staircase per
// exercise (docs/scoring.md, "Staircase" and "Proficiency").
const char* const kMigrateV3ToV4[] = {
    "ALTER TABLE results ADD COLUMN expert INTEGER NOT NULL DEFAULT 0",
    "ALTER TABLE results ADD COLUMN aids_json TEXT NOT NULL DEFAULT '[]'",
    "CREATE TABLE staircases (trainee_id INTEGER NOT NULL REFERENCES trainees(id),"
    " exercise_key TEXT NOT NULL, state_json TEXT NOT NULL, updated_utc TEXT NOT NULL,"
    " PRIMARY KEY (trainee_id, exercise_key))",
    "PRAGMA user_version = 4",
};

// Version 5 (the shared store, docs/results-store.md): a unique id per result so that copying it
// to the server is idempotent, the workstation that scored it, when it reached the server, and the
// class a trainee belongs to. The uids of older rows are filled in by migrateV4ToV5.
const char* const kMigrateV4ToV5[] = {
    "ALTER TABLE results ADD COLUMN uid TEXT NOT NULL DEFAULT ''",
    "ALTER TABLE results ADD COLUMN workstation TEXT NOT NULL DEFAULT ''",
    "ALTER TABLE results ADD COLUMN synced_utc TEXT NOT NULL DEFAULT ''",
    "ALTER TABLE trainees ADD COLUMN class_name TEXT NOT NULL DEFAULT ''",
};

// Version 6 (docs/results-store.md, "Roles"): the database role that put a result on the server
// (a workstation may insert only its own), and which class each workstation role belongs to (a
// workstation reads its class only). Both are empty on a workstation's own SQLite file.
const char* const kMigrateV5ToV6[] = {
    "ALTER TABLE results ADD COLUMN submitted_by TEXT NOT NULL DEFAULT ''",
    "CREATE TABLE class_workstations (role_name TEXT PRIMARY KEY, class_name TEXT NOT NULL)",
    "PRAGMA user_version = 6",
};

// The server keeps its version in a table (PostgreSQL has no user_version); made with version 1.
const char* const kServerVersionTable[] = {
    "CREATE TABLE palpate_schema (version INTEGER NOT NULL)",
    "INSERT INTO palpate_schema VALUES (0)",
};

/// Every migration of a fresh or older server runs under this advisory lock: two workstations that
/// open a new server at once must not both create the tables.
constexpr int kMigrationLock = 0x50414c50;  // "PALP"

/// The socket of the server connection `db` holds (QPSQL's handle is libpq's PGconn); -1 if none.
int serverSocket(const QSqlDatabase& db) {
    const QVariant handle = db.isValid() && db.driver() ? db.driver()->handle() : QVariant();
    // (Qt names the type by libpq's struct: "pg_conn*"; older builds "PGconn*".)
    if (!handle.isValid() ||
        (qstrcmp(handle.typeName(), "pg_conn*") != 0 && qstrcmp(handle.typeName(), "PGconn*") != 0))
        return -1;
    PGconn* connection = *static_cast<PGconn* const*>(handle.constData());
    return connection ? PQsocket(connection) : -1;
}

/// Runs a prepared statement, unless preparing it failed (a statement the server cancelled while it
/// waited on a lock): Qt's PostgreSQL driver would then run an empty EXECUTE and report a syntax
/// error in place of the real problem, which stays in lastError().
bool execPrepared(QSqlQuery& q) { return !q.lastError().isValid() && q.exec(); }

QString newUid() { return QUuid::createUuid().toString(QUuid::WithoutBraces); }

QString isoUtc(const QDateTime& t) { return t.toUTC().toString(Qt::ISODateWithMs); }
QDateTime fromIsoUtc(const QString& s) {
    QDateTime t = QDateTime::fromString(s, Qt::ISODateWithMs);
    return t.toUTC();
}

/// Begins a transaction that writes. On SQLite it takes the write lock at once (BEGIN IMMEDIATE,
/// waiting up to the busy timeout for another writer): a deferred BEGIN that reads first and
/// writes later fails at once with "database is locked" when another process wrote meanwhile.
constexpr int kBusyTimeoutMs = 15000;

bool beginWrite(QSqlDatabase& db) {
    if (db.driverName() != QLatin1String("QSQLITE")) return db.transaction();
    QSqlQuery q(db);
    return q.exec(QStringLiteral("BEGIN IMMEDIATE"));
}

/// Runs statements in one transaction; the first failure rolls back and is returned.
QString runInTransaction(QSqlDatabase& db, const QStringList& statements) {
    if (!beginWrite(db)) return db.lastError().text();
    QSqlQuery q(db);
    for (const QString& statement : statements)
        if (!q.exec(statement)) {
            const QString message = q.lastError().text();
            q.finish();
            db.rollback();
            return message;
        }
    q.finish();
    if (!db.commit()) {
        const QString message = db.lastError().text();
        db.rollback();
        return message;
    }
    return {};
}

QString runInTransaction(QSqlDatabase& db, const char* const* begin, const char* const* end) {
    QStringList statements;
    for (auto it = begin; it != end; ++it) statements << QString::fromLatin1(*it);
    return runInTransaction(db, statements);
}

}  // namespace

bool isServerLocation(const QString& location) { return isServerLocationText(location.toStdString()); }

QString ResultsDatabase::adapt(const char* statement) const {
    QString s = QString::fromLatin1(statement);
    if (!mServer) return s;
    // The schema is written in SQLite's words; PostgreSQL's types and version keeping differ.
    s.replace(QLatin1String("INTEGER PRIMARY KEY AUTOINCREMENT"), QLatin1String("BIGSERIAL PRIMARY KEY"));
    s.replace(QLatin1String("trainee_id INTEGER NOT NULL"), QLatin1String("trainee_id BIGINT NOT NULL"));
    s.replace(QLatin1String("REAL NOT NULL"), QLatin1String("DOUBLE PRECISION NOT NULL"));
    if (s.startsWith(QLatin1String("PRAGMA user_version = ")))
        s = QStringLiteral("UPDATE palpate_schema SET version = %1").arg(s.mid(22));
    return s;
}

QString ResultsDatabase::setVersionStatement(int version) const {
    return mServer ? QStringLiteral("UPDATE palpate_schema SET version = %1").arg(version)
                   : QStringLiteral("PRAGMA user_version = %1").arg(version);
}

ResultOutcome outcomeOf(const ScoreReport& report) {
    if (report.guidance.completed) return ResultOutcome::Completed;
    if (report.guidance.timeUp) return ResultOutcome::TimeUp;
    return ResultOutcome::Stopped;
}

QString outcomeKey(ResultOutcome outcome) {
    switch (outcome) {
        case ResultOutcome::Completed: return QStringLiteral("completed");
        case ResultOutcome::TimeUp: return QStringLiteral("time_up");
        case ResultOutcome::Stopped: return QStringLiteral("stopped");
        case ResultOutcome::Unknown: break;
    }
    return {};
}

ResultOutcome outcomeFromKey(const QString& key) {
    for (ResultOutcome o : {ResultOutcome::Completed, ResultOutcome::TimeUp, ResultOutcome::Stopped})
        if (key == outcomeKey(o)) return o;
    return ResultOutcome::Unknown;
}

ResultsDatabase::ResultsDatabase()
    : mConnection(QStringLiteral("palpate-results-%1").arg(gConnectionCounter.fetch_add(1))) {}

ResultsDatabase::~ResultsDatabase() { close(); }

class ResultsDatabase::ServerCall {
public:
    ServerCall(ServerCallDeadline* deadline, int socket) : mCall(deadline, socket) {}

private:
    ServerCallDeadline::Call mCall;
};

ResultsDatabase::ServerCall ResultsDatabase::serverCall() const {
    return ServerCall(mDeadline.get(), mDeadline ? serverSocket(mDb) : -1);
}

bool ResultsDatabase::fail(const QString& problem, QString* error) const {
    // A call the deadline cut short fails as "server closed the connection": say what happened.
    const QString why = mDeadline && mDeadline->expired()
                            ? tr("the server did not answer within %1 s (the URL's statement_timeout sets the wait, "
                                 "docs/results-store.md)")
                                  .arg(double(mDeadline->limit().count()) / 1000.0)
                            : problem;
    mLastError = tr("%1: %2").arg(QDir::toNativeSeparators(mPath), why);
    if (error) *error = mLastError;
    return false;
}

void ResultsDatabase::close() {
    mRole.clear();
    mClassName.clear();
    mEncrypted = false;
    if (!mDb.isValid()) return;
    mDb.close();
    mDb = QSqlDatabase();
    QSqlDatabase::removeDatabase(mConnection);
}

bool ResultsDatabase::isOpen() const { return mDb.isValid() && mDb.isOpen(); }

bool ResultsDatabase::open(const QString& path, QString* error) {
    close();
    mDeadline.reset();
    mReadOnly = false;
    mPath = path;
    mServer = isServerLocation(path);
    if (mServer) return openServer(path, error);
    const QFileInfo info(path);
    if (info.exists()) {
        if (info.isDir()) return fail(tr("is a folder, not a results database"), error);
        // A device or a FIFO is never opened: SQLite would block on a FIFO, and beside a device it
        // writes its journal (as root, /dev/null-journal).
        if (!info.isFile())
            return fail(tr("is not a regular file (a device, a FIFO or a socket): not a results database"), error);
        if (!info.isReadable()) return fail(tr("cannot be read (permission denied)"), error);
        // A store this user may not write (a colleague's, a copy on read-only media) is opened to
        // be read: listed and exported, never changed.
        mReadOnly = !info.isWritable();
    } else {
        const QFileInfo folder(info.absolutePath());
        if (!folder.isDir())
            return fail(tr("cannot be created: folder %1 does not exist")
                            .arg(QDir::toNativeSeparators(folder.absoluteFilePath())), error);
        if (!folder.isWritable())
            return fail(tr("cannot be created: folder %1 is not writable")
                            .arg(QDir::toNativeSeparators(folder.absoluteFilePath())), error);
    }
    if (!QSqlDatabase::isDriverAvailable(QStringLiteral("QSQLITE")))
        return fail(tr("the Qt SQLite driver (QSQLITE) is not installed"), error);

    mDb = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), mConnection);
    // The window's uploader and command-line runs share one store: a writer waits for another
    // (up to kBusyTimeoutMs) instead of failing with "database is locked".
    QString options = QStringLiteral("QSQLITE_BUSY_TIMEOUT=%1").arg(kBusyTimeoutMs);
    if (!mReadOnly) {
        mDb.setDatabaseName(path);
    } else if (QFileInfo(info.absolutePath()).isWritable()) {
        mDb.setDatabaseName(path);
        options += QStringLiteral(";QSQLITE_OPEN_READONLY");
    } else {
        // Nowhere to put the write-ahead log's index either (read-only media): read the file as
        // it is, assuming nobody changes it meanwhile.
        QUrl uri = QUrl::fromLocalFile(info.absoluteFilePath());
        uri.setScheme(QStringLiteral("file"));
        uri.setQuery(QStringLiteral("mode=ro&immutable=1"));
        mDb.setDatabaseName(uri.toString(QUrl::FullyEncoded));
        options += QStringLiteral(";QSQLITE_OPEN_READONLY;QSQLITE_OPEN_URI");
    }
    mDb.setConnectOptions(options);
    if (!mDb.open()) {
        const QString why = mDb.lastError().text();
        close();
        return fail(tr("cannot be opened: %1").arg(why), error);
    }
    // SQLite opens lazily: the first read is what finds a file that is not a database.
    int version = -1;
    {
        QSqlQuery q(mDb);
        if (!q.exec(QStringLiteral("PRAGMA user_version")) || !q.next()) {
            const QSqlError problem = q.lastError();
            q.finish();
            close();
            // SQLite's I/O error (10) or full disk (13), in their extended forms (the low byte):
            // the file may be fine, the disk is not.
            const int code = problem.nativeErrorCode().toInt() & 0xFF;
            if (code == 10 || code == 13)
                return fail(tr("cannot be read or written (%1): is the disk full?").arg(problem.text()), error);
            return fail(tr("not a results database (%1)").arg(problem.text()), error);
        }
        version = q.value(0).toInt();
        // Durable commits (a write that returned survives a crash) and the trainee references.
        // Write-ahead logging: readers never wait for a writer, and writers queue on the lock.
        if (!mReadOnly) q.exec(QStringLiteral("PRAGMA journal_mode = WAL"));
        q.exec(QStringLiteral("PRAGMA synchronous = FULL"));
        q.exec(QStringLiteral("PRAGMA foreign_keys = ON"));
    }
    if (version > kSchemaVersion) {
        close();
        return fail(tr("schema version %1 is newer than this build reads (%2): update Palpate")
                        .arg(version).arg(kSchemaVersion), error);
    }
    if (version < kSchemaVersion && mReadOnly) {
        close();
        return fail(tr("is read-only and of schema version %1 (this build reads %2): open it once where it can be "
                       "written, to update it")
                        .arg(version)
                        .arg(kSchemaVersion),
                    error);
    }
    if (version < kSchemaVersion && !migrate(version, error)) {
        close();
        return false;
    }
    // A file that says it is of this version but lacks a table or a column is damaged (or not
    // ours): reading it would show "no results" instead of saying so.
    if (const QString problem = schemaProblem(); !problem.isEmpty()) {
        close();
        return fail(tr("the results schema is damaged (%1): restore the file from a copy (Palpate does not repair it)")
                        .arg(problem),
                    error);
    }
    mLastError.clear();
    return true;
}

QString ResultsDatabase::schemaProblem() const {
    struct Table {
        const char* name;
        std::vector<const char*> columns;
    };
    static const Table kTables[] = {
        {"trainees", {"id", "name", "created", "class_name"}},
        {"results",
         {"id", "trainee_id", "exercise_name", "exercise_path", "started_utc", "duration_s", "score", "metrics_json",
          "rubric_json", "recording_path", "outcome", "expert", "aids_json", "uid", "workstation", "synced_utc",
          "submitted_by"}},
        {"staircases", {"trainee_id", "exercise_key", "state_json", "updated_utc"}},
        {"class_workstations", {"role_name", "class_name"}},
    };
    for (const Table& table : kTables) {
        const QSqlRecord record = mDb.record(QLatin1String(table.name));
        if (record.isEmpty()) return tr("table %1 is missing").arg(QLatin1String(table.name));
        for (const char* column : table.columns)
            if (record.indexOf(QLatin1String(column)) < 0)
                return tr("table %1 has no column %2").arg(QLatin1String(table.name), QLatin1String(column));
    }
    return {};
}

bool ResultsDatabase::openServer(const QString& location, QString* error) {
    const QUrl url(location);
    // The URL is shown in messages: never with a password, and its options only once they are
    // known to hold none.
    mPath = url.toString(QUrl::RemovePassword | QUrl::RemoveQuery);
    if (!url.isValid() || url.host().isEmpty())
        return fail(tr("is not a PostgreSQL URL (postgresql://[user@]host[:port]/database)"), error);
    if (!url.password().isEmpty())
        return fail(tr("a password in the URL is refused: put it in ~/.pgpass or the file PGPASSFILE names "
                       "(docs/results-store.md)"),
                    error);
    const QString database = url.path().mid(1);
    if (database.isEmpty() || database.contains(QLatin1Char('/')))
        return fail(tr("names no database (postgresql://host/database)"), error);
    if (!QSqlDatabase::isDriverAvailable(QStringLiteral("QPSQL")))
        return fail(tr("the Qt PostgreSQL driver (QPSQL, Debian package libqt6sql6-psql) is not installed"), error);
    // libpq's own options from the URL's query (sslmode, sslrootcert, ...), each quoted; TLS when
    // the server offers it and a short wait when it is away, unless the URL says otherwise.
    QString optionError;
    const std::optional<ServerConnectDef> options = serverConnectOptions(url, optionError);
    if (!options) return fail(optionError, error);
    mPath = url.toString(QUrl::RemovePassword);
    mDb = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), mConnection);
    mDb.setHostName(url.host());
    if (url.port() > 0) mDb.setPort(url.port());
    mDb.setDatabaseName(database);
    if (!url.userName().isEmpty()) mDb.setUserName(url.userName());
    mDb.setConnectOptions(options->connectOptions);
    if (!mDb.open()) {
        const QString why = mDb.lastError().text().trimmed();
        close();
        return fail(tr("cannot connect: %1").arg(why), error);
    }
    mDeadline = std::make_unique<ServerCallDeadline>(std::chrono::milliseconds(options->callDeadlineMs()));
    const ServerCall call = serverCall();
    QSqlQuery q(mDb);
    q.exec(QStringLiteral("SELECT pg_advisory_lock(%1)").arg(kMigrationLock));
    int version = -1;
    QString versionError;
    if (q.exec(QStringLiteral("SELECT version FROM palpate_schema")) && q.next()) {
        version = q.value(0).toInt();
    } else {
        versionError = q.lastError().databaseText();
        q.exec(QStringLiteral("SELECT count(*) FROM information_schema.tables WHERE table_schema = current_schema()"));
        if (q.next() && q.value(0).toInt() == 0) version = 0;
    }
    q.finish();
    const auto unlock = [&] {
        QSqlQuery u(mDb);
        u.exec(QStringLiteral("SELECT pg_advisory_unlock(%1)").arg(kMigrationLock));
    };
    // (information_schema lists only the tables a role may use: a role with no grants sees none.)
    if (versionError.contains(QLatin1String("permission denied"))) {
        unlock();
        close();
        return fail(tr("this role may not read the results (%1): the instructor grants it a workstation or instructor role "
                       "(palpate-cli results grant, docs/results-store.md)")
                        .arg(versionError.trimmed()),
                    error);
    }
    if (version < 0) {
        unlock();
        close();
        return fail(tr("the database holds other tables: not a Palpate results database"), error);
    }
    if (version > kSchemaVersion) {
        unlock();
        close();
        return fail(tr("schema version %1 is newer than this build reads (%2): update Palpate").arg(version).arg(kSchemaVersion),
                    error);
    }
    const bool migrated = version == kSchemaVersion || migrate(version, error);
    unlock();
    if (!migrated) {
        close();
        return false;
    }
    if (const QString problem = schemaProblem(); !problem.isEmpty()) {
        close();
        return fail(
            tr("the results schema is damaged (%1): the server's administrator restores it from a backup").arg(problem),
            error);
    }
    // Who this is on the server: a workstation role belongs to one class (ResultsRoles.h), and
    // its trainees are that class's.
    if (!q.exec(QStringLiteral("SELECT CAST(current_user AS TEXT),"
                               " COALESCE((SELECT class_name FROM class_workstations WHERE role_name = CAST(current_user AS TEXT)), ''),"
                               " COALESCE((SELECT ssl FROM pg_stat_ssl WHERE pid = pg_backend_pid()), false)")) ||
        !q.next()) {
        const QString why = q.lastError().text();
        close();
        return fail(tr("cannot read this connection's role: %1").arg(why), error);
    }
    mRole = q.value(0).toString();
    mClassName = q.value(1).toString();
    mEncrypted = q.value(2).toBool();
    q.finish();
    mLastError.clear();
    return true;
}

bool ResultsDatabase::answers() const {
    const ServerCall call = serverCall();
    if (!isOpen()) return false;
    QSqlQuery q(mDb);
    return q.exec(QStringLiteral("SELECT 1")) && q.next();
}

QString ResultsDatabase::connectionDescription() const {
    if (!mServer || !isOpen()) return {};
    QString out = mClassName.isEmpty() ? tr("role %1").arg(mRole) : tr("role %1, class %2").arg(mRole, mClassName);
    return out + (mEncrypted ? tr(", TLS") : tr(", no TLS"));
}

bool ResultsDatabase::runStatements(const QStringList& statements, QString* error) {
    const ServerCall call = serverCall();
    if (!isOpen()) return fail(tr("not open"), error);
    const QString why = runInTransaction(mDb, statements);
    if (!why.isEmpty()) return fail(why, error);
    return true;
}

QString ResultsDatabase::quotedIdentifier(const QString& name) const {
    return mDb.driver()->escapeIdentifier(name, QSqlDriver::FieldName);
}

QString ResultsDatabase::quotedText(const QString& text) const {
    QSqlField field(QStringLiteral("text"), QMetaType(QMetaType::QString));
    field.setValue(text);
    return mDb.driver()->formatValue(field);
}

bool ResultsDatabase::migrate(int from, QString* error) {
    const auto adapted = [this](const char* const* begin, const char* const* end) {
        QStringList statements;
        for (auto it = begin; it != end; ++it) statements << adapt(*it);
        return statements;
    };
    if (from == 0) {
        QStringList create;
        if (mServer) {
            create = adapted(std::begin(kServerVersionTable), std::end(kServerVersionTable));
        } else {
            QSqlQuery q(mDb);
            if (!q.exec(QStringLiteral("SELECT count(*) FROM sqlite_master")) || !q.next())
                return fail(tr("not a results database (%1)").arg(q.lastError().text()), error);
            if (q.value(0).toInt() > 0)
                return fail(tr("is an SQLite database but not a Palpate results database"), error);
        }
        create << adapted(std::begin(kSchemaV1), std::end(kSchemaV1));
        const QString why = runInTransaction(mDb, create);
        if (!why.isEmpty()) return fail(tr("cannot create the tables: %1").arg(why), error);
        from = 1;
    }
    if (from == 1) {
        const QString why = runInTransaction(mDb, adapted(std::begin(kMigrateV1ToV2), std::end(kMigrateV1ToV2)));
        if (!why.isEmpty()) return fail(tr("cannot migrate from schema version 1 to 2: %1").arg(why), error);
        from = 2;
    }
    if (from == 2) {
        const QString why = migrateV2ToV3();
        if (!why.isEmpty()) return fail(tr("cannot migrate from schema version 2 to 3: %1").arg(why), error);
        from = 3;
    }
    if (from == 3) {
        const QString why = runInTransaction(mDb, adapted(std::begin(kMigrateV3ToV4), std::end(kMigrateV3ToV4)));
        if (!why.isEmpty()) return fail(tr("cannot migrate from schema version 3 to 4: %1").arg(why), error);
        from = 4;
    }
    if (from == 4) {
        const QString why = migrateV4ToV5();
        if (!why.isEmpty()) return fail(tr("cannot migrate from schema version 4 to 5: %1").arg(why), error);
        from = 5;
    }
    if (from == 5) {
        const QString why = runInTransaction(mDb, adapted(std::begin(kMigrateV5ToV6), std::end(kMigrateV5ToV6)));
        if (!why.isEmpty()) return fail(tr("cannot migrate from schema version 5 to 6: %1").arg(why), error);
        from = 6;
    }
    return true;
}

QString ResultsDatabase::migrateV4ToV5() {
    if (!beginWrite(mDb)) return mDb.lastError().text();
    QString why;
    {
        QSqlQuery q(mDb);
        for (const char* statement : kMigrateV4ToV5)
            if (why.isEmpty() && !q.exec(adapt(statement))) why = q.lastError().text();
        // Every older row gets its own uid before the uids are made unique.
        std::vector<qint64> ids;
        if (why.isEmpty() && q.exec(QStringLiteral("SELECT id FROM results"))) {
            while (q.next()) ids.push_back(q.value(0).toLongLong());
        } else if (why.isEmpty()) {
            why = q.lastError().text();
        }
        q.finish();
        for (qint64 id : ids) {
            if (!why.isEmpty()) break;
            q.prepare(QStringLiteral("UPDATE results SET uid = ? WHERE id = ?"));
            q.addBindValue(newUid());
            q.addBindValue(id);
            if (!execPrepared(q)) why = q.lastError().text();
        }
        if (why.isEmpty() && !q.exec(QStringLiteral("CREATE UNIQUE INDEX results_by_uid ON results(uid)"))) why = q.lastError().text();
        if (why.isEmpty() && !q.exec(setVersionStatement(5))) why = q.lastError().text();
        q.finish();
    }
    if (why.isEmpty() && !mDb.commit()) why = mDb.lastError().text();
    if (!why.isEmpty()) mDb.rollback();
    return why;
}

QString ResultsDatabase::migrateV2ToV3() {
    if (!beginWrite(mDb)) return mDb.lastError().text();
    QString why;
    {
        QSqlQuery q(mDb);
        for (const char* statement : kMigrateV2ToV3)
            if (why.isEmpty() && !q.exec(adapt(statement))) why = q.lastError().text();
        // A completion of 1 means the task was done; any other old row may have been stopped or
        // timed out, which version 2 did not record.
        std::vector<qint64> completed;
        if (why.isEmpty() && q.exec(QStringLiteral("SELECT id, metrics_json FROM results"))) {
            while (q.next()) {
                const QJsonObject metrics = QJsonDocument::fromJson(q.value(1).toString().toUtf8()).object();
                if (metrics.value(QStringLiteral("completion")).toDouble(0.0) >= 1.0)
                    completed.push_back(q.value(0).toLongLong());
            }
        } else if (why.isEmpty()) {
            why = q.lastError().text();
        }
        q.finish();
        for (qint64 id : completed) {
            if (!why.isEmpty()) break;
            q.prepare(QStringLiteral("UPDATE results SET outcome = ? WHERE id = ?"));
            q.addBindValue(outcomeKey(ResultOutcome::Completed));
            q.addBindValue(id);
            if (!execPrepared(q)) why = q.lastError().text();
        }
        if (why.isEmpty() && !q.exec(setVersionStatement(3))) why = q.lastError().text();
        q.finish();
    }
    if (why.isEmpty() && !mDb.commit()) why = mDb.lastError().text();
    if (!why.isEmpty()) mDb.rollback();
    return why;
}

int ResultsDatabase::schemaVersion() const {
    const ServerCall call = serverCall();
    if (!isOpen()) return -1;
    QSqlQuery q(mDb);
    if (!q.exec(mServer ? QStringLiteral("SELECT version FROM palpate_schema") : QStringLiteral("PRAGMA user_version")) ||
        !q.next())
        return -1;
    return q.value(0).toInt();
}

bool ResultsDatabase::createVersion1(const QString& path, QString* error) {
    const QString connection =
        QStringLiteral("palpate-results-v1-%1").arg(gConnectionCounter.fetch_add(1));
    QString why;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connection);
        db.setDatabaseName(path);
        if (!db.open())
            why = db.lastError().text();
        else
            why = runInTransaction(db, std::begin(kSchemaV1), std::end(kSchemaV1));
        db.close();
    }
    QSqlDatabase::removeDatabase(connection);
    if (!why.isEmpty() && error) *error = tr("%1: %2").arg(QDir::toNativeSeparators(path), why);
    return why.isEmpty();
}

qint64 ResultsDatabase::addTrainee(const QString& name, QString* error) {
    const ServerCall call = serverCall();
    const QString trimmed = name.trimmed();
    if (!isOpen()) return fail(tr("not open"), error), -1;
    if (trimmed.isEmpty()) return fail(tr("a trainee needs a name"), error), -1;
    if (!beginWrite(mDb)) return fail(mDb.lastError().text(), error), -1;
    qint64 id = -1;
    QString why;
    {
        QSqlQuery q(mDb);
        q.prepare(QStringLiteral("SELECT id FROM trainees WHERE name = ?"));
        q.addBindValue(trimmed);
        if (!execPrepared(q)) why = q.lastError().text();
        else if (q.next())
            id = q.value(0).toLongLong();
        else {
            q.finish();
            // Two workstations adding the same trainee at once: the second insert does nothing and
            // the name is read again (the name is unique).
            // A workstation's new trainee is of its class (on a file, and for an unassigned role: none).
            q.prepare(QStringLiteral(
                "INSERT INTO trainees (name, created, class_name) VALUES (?, ?, ?) ON CONFLICT (name) DO NOTHING"));
            q.addBindValue(trimmed);
            q.addBindValue(isoUtc(QDateTime::currentDateTimeUtc()));
            q.addBindValue(mClassName.isNull() ? QString(QLatin1String("")) : mClassName);
            if (!execPrepared(q)) {
                why = q.lastError().text();
            } else {
                q.finish();
                q.prepare(QStringLiteral("SELECT id FROM trainees WHERE name = ?"));
                q.addBindValue(trimmed);
                if (!execPrepared(q)) why = q.lastError().text();
                else if (q.next()) id = q.value(0).toLongLong();
                // The name is taken, by a trainee this role may not see: one of another class.
                else why = tr("the server already has a trainee of that name in another class");
            }
        }
    }
    if (why.isEmpty() && !mDb.commit()) why = mDb.lastError().text();
    if (!why.isEmpty()) {
        mDb.rollback();
        return fail(tr("cannot add trainee \"%1\": %2").arg(trimmed, why), error), -1;
    }
    return id;
}

std::vector<TraineeRecord> ResultsDatabase::trainees() const {
    const ServerCall call = serverCall();
    std::vector<TraineeRecord> out;
    if (!isOpen()) return out;
    QSqlQuery q(mDb);
    if (!q.exec(QStringLiteral("SELECT id, name, created, class_name FROM trainees ORDER BY name, id"))) {
        fail(q.lastError().text(), nullptr);
        return out;
    }
    while (q.next())
        out.push_back({q.value(0).toLongLong(), q.value(1).toString(), fromIsoUtc(q.value(2).toString()),
                       q.value(3).toString()});
    return out;
}

qint64 ResultsDatabase::addResult(qint64 traineeId, const ScoreReport& report, const QString& exerciseName,
                                  const QString& exercisePath, const QDateTime& startedUtc, double durationS,
                                  const QString& recordingPath, QString* error) {
    return addResult(traineeId, report, exerciseName, exercisePath, startedUtc, durationS, recordingPath, false, error);
}

qint64 ResultsDatabase::addResult(qint64 traineeId, const ScoreReport& report, const QString& exerciseName,
                                  const QString& exercisePath, const QDateTime& startedUtc, double durationS,
                                  const QString& recordingPath, bool expert, QString* error) {
    const ServerCall call = serverCall();
    QJsonArray aidsArray;
    for (const GuidanceAid& aid : report.aids)
        aidsArray.append(QJsonObject{{QStringLiteral("name"), QString::fromStdString(aid.name)},
                                     {QStringLiteral("level"), aid.level}});
    const QString aids = QString::fromUtf8(QJsonDocument(aidsArray).toJson(QJsonDocument::Compact));
    if (!isOpen()) return fail(tr("not open"), error), -1;
    // The same metrics and rubric objects as `palpate-cli score --json`.
    const QJsonObject all =
        QJsonDocument::fromJson(QByteArray::fromStdString(scoreReportToJson(report, -1))).object();
    const QString metrics = QString::fromUtf8(QJsonDocument(all.value(QStringLiteral("metrics")).toObject())
                                                  .toJson(QJsonDocument::Compact));
    const QString rubric = QString::fromUtf8(QJsonDocument(all.value(QStringLiteral("rubric")).toObject())
                                                 .toJson(QJsonDocument::Compact));
    if (!beginWrite(mDb)) return fail(mDb.lastError().text(), error), -1;
    qint64 id = -1;
    QString why;
    {
        QSqlQuery q(mDb);
        q.prepare(QStringLiteral("SELECT 1 FROM trainees WHERE id = ?"));
        q.addBindValue(traineeId);
        if (!execPrepared(q)) why = q.lastError().text();
        else if (!q.next())
            why = tr("no trainee with id %1").arg(traineeId);
        else {
            q.finish();
            q.prepare(QStringLiteral(
                "INSERT INTO results (trainee_id, exercise_name, exercise_path, started_utc, duration_s,"
                 " score, metrics_json, rubric_json, recording_path, outcome, expert, aids_json, uid, workstation)"
                // A null QString binds as NULL: empty text instead.
                " VALUES (?, COALESCE(?, ''), COALESCE(?, ''), ?, ?, ?, ?, ?, COALESCE(?, ''), ?, ?, ?, ?, ?) RETURNING id"));
            q.addBindValue(traineeId);
            q.addBindValue(exerciseName);
            q.addBindValue(exercisePath);
            q.addBindValue(isoUtc(startedUtc));
            q.addBindValue(durationS);
            q.addBindValue(report.score);
            q.addBindValue(metrics);
            q.addBindValue(rubric);
            q.addBindValue(recordingPath);
            q.addBindValue(outcomeKey(outcomeOf(report)));
            q.addBindValue(expert ? 1 : 0);
            q.addBindValue(aids);
            q.addBindValue(newUid());
            q.addBindValue(QSysInfo::machineHostName());
            if (execPrepared(q) && q.next()) id = q.value(0).toLongLong();
            else
                why = q.lastError().text();
        }
    }
    if (why.isEmpty() && !mDb.commit()) why = mDb.lastError().text();
    if (!why.isEmpty()) {
        mDb.rollback();
        return fail(tr("cannot store the result: %1").arg(why), error), -1;
    }
    return id;
}

std::vector<ResultRecord> ResultsDatabase::results(qint64 traineeId) const {
    return selectResults(QStringLiteral("r.trainee_id = ?"), traineeId);
}

std::vector<ResultRecord> ResultsDatabase::allResults() const { return selectResults(QStringLiteral("? = 1"), 1); }

std::vector<ResultRecord> ResultsDatabase::unsyncedResults() const {
    return selectResults(QStringLiteral("r.synced_utc = ?"), QString(QLatin1String("")));
}

bool ResultsDatabase::markSynced(const QString& uid, const QDateTime& whenUtc, QString* error) {
    const ServerCall call = serverCall();
    if (!isOpen()) return fail(tr("not open"), error);
    QSqlQuery q(mDb);
    q.prepare(QStringLiteral("UPDATE results SET synced_utc = ? WHERE uid = ?"));
    q.addBindValue(isoUtc(whenUtc));
    q.addBindValue(uid);
    if (!execPrepared(q)) return fail(tr("cannot mark result %1 as sent: %2").arg(uid, q.lastError().text()), error);
    return true;
}

std::optional<bool> ResultsDatabase::importResult(const ResultRecord& r, const QString& traineeName, QString* error) {
    const ServerCall call = serverCall();
    if (r.uid.isEmpty()) return fail(tr("a result without a uid cannot be copied"), error), std::nullopt;
    const qint64 trainee = addTrainee(traineeName, error);
    if (trainee < 0) return std::nullopt;
    QSqlQuery q(mDb);
    // The uid is unique: a result sent twice (a retry after a lost answer) stays one row.
    q.prepare(QStringLiteral(
        "INSERT INTO results (trainee_id, exercise_name, exercise_path, started_utc, duration_s, score, metrics_json,"
        " rubric_json, recording_path, outcome, expert, aids_json, uid, workstation, submitted_by)"
        " VALUES (?, COALESCE(?, ''), COALESCE(?, ''), ?, ?, ?, COALESCE(?, ''), COALESCE(?, ''), COALESCE(?, ''),"
        " COALESCE(?, ''), ?, COALESCE(?, '[]'), ?, COALESCE(?, ''), %1) ON CONFLICT (uid) DO NOTHING RETURNING id")
                  // The server's row says which role sent it (a workstation may send only its own).
                  .arg(mServer ? QStringLiteral("CAST(current_user AS TEXT)") : QStringLiteral("''")));
    q.addBindValue(trainee);
    q.addBindValue(r.exerciseName);
    q.addBindValue(r.exercisePath);
    q.addBindValue(isoUtc(r.startedUtc));
    q.addBindValue(r.durationS);
    q.addBindValue(r.score);
    q.addBindValue(r.metricsJson);
    q.addBindValue(r.rubricJson);
    q.addBindValue(r.recordingPath);
    q.addBindValue(outcomeKey(r.outcome));
    q.addBindValue(r.expert ? 1 : 0);
    q.addBindValue(r.aidsJson);
    q.addBindValue(r.uid);
    q.addBindValue(r.workstation);
    if (!execPrepared(q))
        return fail(tr("cannot store result %1: %2").arg(r.uid, q.lastError().text()), error), std::nullopt;
    return q.next();
}

std::vector<ResultRecord> ResultsDatabase::expertResults(const QString& exercisePath, const QString& exerciseName) const {
    std::vector<ResultRecord> out;
    for (ResultRecord& r : selectResults(QStringLiteral("r.expert = ?"), 1))
        if (isSameExercise(r, exercisePath, exerciseName)) out.push_back(std::move(r));
    return out;
}

std::vector<ResultRecord> ResultsDatabase::selectResults(const QString& where, const QVariant& bind) const {
    const ServerCall call = serverCall();
    std::vector<ResultRecord> out;
    if (!isOpen()) return out;
    QSqlQuery q(mDb);
    q.prepare(QStringLiteral(
        "SELECT r.id, r.trainee_id, r.exercise_name, r.exercise_path, r.started_utc, r.duration_s, r.score,"
        " r.metrics_json, r.rubric_json, r.recording_path, r.outcome, r.expert, r.aids_json, r.uid, r.workstation,"
        " r.synced_utc, t.name, r.submitted_by, t.class_name FROM results r JOIN trainees t ON t.id = r.trainee_id WHERE %1"
        " ORDER BY r.started_utc, r.id")
                  .arg(where));
    q.addBindValue(bind);
    if (!execPrepared(q)) {
        fail(q.lastError().text(), nullptr);
        return out;
    }
    while (q.next()) {
        ResultRecord r;
        r.id = q.value(0).toLongLong();
        r.traineeId = q.value(1).toLongLong();
        r.exerciseName = q.value(2).toString();
        r.exercisePath = q.value(3).toString();
        r.startedUtc = fromIsoUtc(q.value(4).toString());
        r.durationS = q.value(5).toDouble();
        r.score = q.value(6).toDouble();
        r.metricsJson = q.value(7).toString();
        r.rubricJson = q.value(8).toString();
        r.recordingPath = q.value(9).toString();
        r.outcome = outcomeFromKey(q.value(10).toString());
        r.expert = q.value(11).toInt() != 0;
        r.aidsJson = q.value(12).toString();
        r.uid = q.value(13).toString();
        r.workstation = q.value(14).toString();
        r.syncedUtc = q.value(15).toString();
        r.traineeName = q.value(16).toString();
        r.submittedBy = q.value(17).toString();
        r.traineeClass = q.value(18).toString();
        out.push_back(std::move(r));
    }
    return out;
}

QString ResultsDatabase::staircase(qint64 traineeId, const QString& exerciseKey) const {
    const ServerCall call = serverCall();
    if (!isOpen()) return {};
    QSqlQuery q(mDb);
    q.prepare(QStringLiteral("SELECT state_json FROM staircases WHERE trainee_id = ? AND exercise_key = ?"));
    q.addBindValue(traineeId);
    q.addBindValue(exerciseKey);
    if (!execPrepared(q)) {
        fail(q.lastError().text(), nullptr);
        return {};
    }
    return q.next() ? q.value(0).toString() : QString();
}

bool ResultsDatabase::putStaircase(qint64 traineeId, const QString& exerciseKey, const QString& stateJson,
                                   QString* error) {
    const ServerCall call = serverCall();
    if (!isOpen()) return fail(tr("not open"), error);
    if (!beginWrite(mDb)) return fail(mDb.lastError().text(), error);
    QString why;
    {
        QSqlQuery q(mDb);
        q.prepare(QStringLiteral("INSERT INTO staircases (trainee_id, exercise_key, state_json, updated_utc)"
                                 " VALUES (?, ?, ?, ?) ON CONFLICT (trainee_id, exercise_key) DO UPDATE"
                                 " SET state_json = excluded.state_json, updated_utc = excluded.updated_utc"));
        q.addBindValue(traineeId);
        q.addBindValue(exerciseKey);
        q.addBindValue(stateJson);
        q.addBindValue(isoUtc(QDateTime::currentDateTimeUtc()));
        if (!execPrepared(q)) why = q.lastError().text();
    }
    if (why.isEmpty() && !mDb.commit()) why = mDb.lastError().text();
    if (!why.isEmpty()) {
        mDb.rollback();
        return fail(tr("cannot store the staircase of %1: %2").arg(exerciseKey, why), error);
    }
    return true;
}

QString exerciseKey(const QString& exercisePath, const QString& exerciseName) {
    if (exercisePath.isEmpty()) return exerciseName;
    const QFileInfo info(exercisePath);
    const QString canonical = info.canonicalFilePath();
    return canonical.isEmpty() ? QDir::cleanPath(info.absoluteFilePath()) : canonical;
}

bool isSameExercise(const ResultRecord& result, const QString& exercisePath, const QString& exerciseName) {
    if (result.exercisePath.isEmpty() || exercisePath.isEmpty()) return result.exerciseName == exerciseName;
    return exerciseKey(result.exercisePath, QString()) == exerciseKey(exercisePath, QString());
}

}  // namespace palpate
