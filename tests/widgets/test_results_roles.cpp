// Who may do what on a class's server (docs/results-store.md, "Roles" and "TLS"): a workstation
// role adds its class's trainees, sends only results it submits itself and reads only its class;
// an instructor reads every class and writes nothing; a role with neither reads nothing. The
// passwords come from a pgpass file, as on a workstation. And the connection is encrypted when the
// server offers TLS, and verify-full refuses a server whose certificate the workstation does not
// trust. These need the server pg_virtualenv starts (they are skipped without one).
#include "results/ClassSummary.h"
#include "results/ResultSync.h"
#include "results/ResultsDatabase.h"
#include "results/ResultsRoles.h"
#include "tests/widgets/ResultsServer.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include "tests/widgets/ForkedProcess.h"

#include <QProcess>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>

#include <gtest/gtest.h>

#include <set>

#include <unistd.h>

using namespace palpate;
using palpate::test::clearServer;
using palpate::test::runAsAdmin;
using palpate::test::serverUrl;

namespace {

/// Sets an environment variable for a scope (or unsets it), then puts back what was there.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const QByteArray& value) : mName(name), mHad(qEnvironmentVariableIsSet(name)), mOld(qgetenv(name)) {
        if (value.isNull()) qunsetenv(name);
        else qputenv(name, value);
    }
    ~ScopedEnv() {
        if (mHad) qputenv(mName, mOld);
        else qunsetenv(mName);
    }

private:
    const char* mName;
    bool mHad;
    QByteArray mOld;
};

QString workstationFile(const QTemporaryDir& dir, const QString& name, const QString& trainee, int count) {
    return palpate::test::workstationFile(dir, name, trainee, count, 60.0);
}

SyncReport syncAs(const QString& localPath, const QString& role) {
    ResultsDatabase local, server;
    QString error;
    SyncReport report;
    EXPECT_TRUE(local.open(localPath, &error)) << error.toStdString();
    if (!server.open(serverUrl(role), &error)) {
        report.error = error;
        return report;
    }
    return syncResults(local, server);
}

/// A statement run as `role` on a connection of its own: its error text, or "".
QString runAs(const QString& role, const QString& statement) {
    const QString name = QStringLiteral("as-") + role;
    QString why;
    {
        QSqlDatabase raw = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), name);
        raw.setHostName(qEnvironmentVariable("PGHOST"));
        raw.setPort(qEnvironmentVariableIntValue("PGPORT"));
        raw.setDatabaseName(qEnvironmentVariable("PGDATABASE"));
        raw.setUserName(role);
        if (!raw.open()) why = raw.lastError().text();
        else if (QSqlQuery q(raw); !q.exec(statement)) why = q.lastError().text();
        if (why.isEmpty() && statement.startsWith(QLatin1String("UPDATE"))) {
            // An UPDATE that the policies filter to no rows succeeds: say how many it changed.
            QSqlQuery q(raw);
            q.exec(statement + QStringLiteral(" RETURNING 1"));
            if (q.numRowsAffected() > 0) why = QStringLiteral("changed %1 rows").arg(q.numRowsAffected());
        }
    }
    QSqlDatabase::removeDatabase(name);
    return why;
}

class ServerRoles : public ::testing::Test {
protected:
    void SetUp() override {
        REQUIRE_SERVER();
        clearServer();
        ASSERT_TRUE(dir.isValid());
        // Login roles are the administrator's to make (Palpate only grants them a kind).
        QStringList make;
        for (const char* role : {"ws_a", "ws_b", "teacher", "stranger"})
            make << QStringLiteral("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = '%1') THEN"
                                   " CREATE ROLE %1 LOGIN; END IF; END $$")
                        .arg(QLatin1String(role))
                 << QStringLiteral("ALTER ROLE %1 PASSWORD 'pw-%1'").arg(QLatin1String(role));
        const QString why = runAsAdmin(make);
        ASSERT_TRUE(why.isEmpty()) << why.toStdString();
        // Every password from a pgpass file, as a workstation keeps it; none in the environment.
        const QString pgpass = dir.filePath(QStringLiteral("pgpass"));
        QFile file(pgpass);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write("*:*:*:" + qgetenv("PGUSER") + ":" + qgetenv("PGPASSWORD") + "\n");
        for (const char* role : {"ws_a", "ws_b", "teacher", "stranger"})
            file.write(QByteArray("*:*:*:") + role + ":pw-" + role + "\n");
        file.close();
        file.setPermissions(QFile::ReadOwner | QFile::WriteOwner);  // libpq ignores a looser one
        passFile.emplace("PGPASSFILE", QFile::encodeName(pgpass));
        password.emplace("PGPASSWORD", QByteArray());
    }
    QTemporaryDir dir;
    std::optional<ScopedEnv> passFile, password;
};

// A result the server refuses while it answers (its trainee's name belongs to another class) is
// named with why and what to do, stays waiting, and does not hold back the results after it.
TEST_F(ServerRoles, ARefusedResultIsNamedAndTheOthersStillGo) {
    ResultsDatabase admin;
    QString error;
    ASSERT_TRUE(admin.open(serverUrl(), &error)) << error.toStdString();
    ASSERT_TRUE(grantWorkstation(admin, QStringLiteral("ws_a"), QStringLiteral("3A"), &error)) << error.toStdString();
    ASSERT_TRUE(grantWorkstation(admin, QStringLiteral("ws_b"), QStringLiteral("3B"), &error)) << error.toStdString();
    ASSERT_EQ(syncAs(workstationFile(dir, QStringLiteral("b"), QStringLiteral("Kim"), 1), QStringLiteral("ws_b")).sent,
              1);
    // Workstation a: Kim (of 3B on the server) first, then its own Ann.
    const QString aFile = workstationFile(dir, QStringLiteral("a"), QStringLiteral("Kim"), 2);
    {
        ResultsDatabase a;
        ASSERT_TRUE(a.open(aFile, &error)) << error.toStdString();
        const qint64 ann = a.addTrainee(QStringLiteral("Ann"), &error);
        ASSERT_GE(a.addResult(ann, palpate::test::completedReport(80.0), QStringLiteral("Press two targets"),
                              QStringLiteral("/e.json"), QDateTime::currentDateTimeUtc().addSecs(60), 10.0, QString(),
                              &error),
                  0)
            << error.toStdString();
    }
    const SyncReport report = syncAs(aFile, QStringLiteral("ws_a"));
    EXPECT_TRUE(report.error.isEmpty()) << report.error.toStdString();
    EXPECT_EQ(report.sent, 1) << "Ann's result went, after Kim's were refused";
    EXPECT_EQ(report.waiting, 2);
    ASSERT_EQ(report.refused.size(), 2u);
    EXPECT_EQ(report.refused[0].trainee, QStringLiteral("Kim"));
    EXPECT_TRUE(report.refused[0].why.contains(QStringLiteral("another class"))) << report.refused[0].why.toStdString();
    const QString text = report.refusedText();
    EXPECT_TRUE(text.contains(QStringLiteral("Kim"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("rename the trainee"))) << text.toStdString();
    ResultsDatabase a;
    ASSERT_TRUE(a.open(aFile, &error)) << error.toStdString();
    EXPECT_EQ(a.unsyncedResults().size(), 2u) << "Kim's stay on the workstation";
}

TEST_F(ServerRoles, WorkstationsSendTheirOwnAndReadTheirClassInstructorsReadAll) {
    ResultsDatabase admin;
    QString error;
    ASSERT_TRUE(admin.open(serverUrl(), &error)) << error.toStdString();
    ASSERT_TRUE(grantWorkstation(admin, QStringLiteral("ws_a"), QStringLiteral("3A"), &error)) << error.toStdString();
    ASSERT_TRUE(grantWorkstation(admin, QStringLiteral("ws_b"), QStringLiteral("3B"), &error)) << error.toStdString();
    ASSERT_TRUE(grantInstructor(admin, QStringLiteral("teacher"), &error)) << error.toStdString();
    ASSERT_TRUE(grantInstructor(admin, QStringLiteral("teacher"), &error)) << error.toStdString();  // again: the same

    // Each workstation sends its own trainee's results; the server gives the trainee its class.
    EXPECT_EQ(syncAs(workstationFile(dir, QStringLiteral("a"), QStringLiteral("Ann"), 3), QStringLiteral("ws_a")).sent, 3);
    const QString bFile = workstationFile(dir, QStringLiteral("b"), QStringLiteral("Bo"), 2);
    const SyncReport b = syncAs(bFile, QStringLiteral("ws_b"));
    EXPECT_EQ(b.sent, 2) << b.error.toStdString();

    ResultsDatabase a;
    ASSERT_TRUE(a.open(serverUrl(QStringLiteral("ws_a")), &error)) << error.toStdString();
    EXPECT_EQ(a.serverRole(), QStringLiteral("ws_a"));
    EXPECT_EQ(a.className(), QStringLiteral("3A"));
    EXPECT_TRUE(a.connectionDescription().contains(QStringLiteral("class 3A")));
    // It reads its class only.
    const auto seenByA = a.allResults();
    ASSERT_EQ(seenByA.size(), 3u);
    for (const ResultRecord& r : seenByA) {
        EXPECT_EQ(r.traineeName, QStringLiteral("Ann"));
        EXPECT_EQ(r.traineeClass, QStringLiteral("3A"));
        EXPECT_EQ(r.submittedBy, QStringLiteral("ws_a"));
    }
    ASSERT_EQ(a.trainees().size(), 1u);
    // A trainee of another class cannot be sent from here, nor taken over by name.
    ResultsDatabase bLocal;
    ASSERT_TRUE(bLocal.open(bFile, &error));
    ResultRecord bos = bLocal.allResults().front();
    bos.uid = QStringLiteral("00000000-0000-0000-0000-00000000000b");
    EXPECT_FALSE(a.importResult(bos, QStringLiteral("Bo"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("another class"))) << error.toStdString();
    // Nor a result in another role's name, nor a change or a removal of what is there.
    const QString forged = runAs(
        QStringLiteral("ws_a"),
        QStringLiteral("INSERT INTO results (trainee_id, exercise_name, exercise_path, started_utc, duration_s, score,"
                       " metrics_json, rubric_json, uid, submitted_by) SELECT id, 'x', '', '2026-12-01', 1, 100, '{}', '{}',"
                       " 'forged', 'ws_b' FROM trainees WHERE name = 'Ann'"));
    EXPECT_TRUE(forged.contains(QStringLiteral("row-level security"))) << forged.toStdString();
    EXPECT_TRUE(runAs(QStringLiteral("ws_a"), QStringLiteral("UPDATE results SET score = 100"))
                    .contains(QStringLiteral("permission denied")));
    EXPECT_TRUE(runAs(QStringLiteral("ws_a"), QStringLiteral("DELETE FROM results")).contains(QStringLiteral("permission denied")));
    EXPECT_TRUE(runAs(QStringLiteral("ws_a"), QStringLiteral("INSERT INTO trainees (name, created, class_name)"
                                                            " VALUES ('Cy', '2026-12-01', '3B')"))
                    .contains(QStringLiteral("row-level security")));
    EXPECT_TRUE(runAs(QStringLiteral("ws_a"), QStringLiteral("INSERT INTO class_workstations VALUES ('ws_a', '3B')"))
                    .contains(QStringLiteral("permission denied")));

    // The instructor reads both classes and writes nothing.
    ResultsDatabase teacher;
    ASSERT_TRUE(teacher.open(serverUrl(QStringLiteral("teacher")), &error)) << error.toStdString();
    EXPECT_TRUE(teacher.className().isEmpty());
    const auto all = teacher.allResults();
    EXPECT_EQ(all.size(), 5u);
    std::set<QString> classes;
    for (const ClassRow& row : classSummary(all, [](const QString&, const QString&) { return std::optional<Exercise>(); }))
        classes.insert(row.className);
    EXPECT_EQ(classes, (std::set<QString>{QStringLiteral("3A"), QStringLiteral("3B")}));
    EXPECT_LT(teacher.addTrainee(QStringLiteral("Di"), &error), 0);
    EXPECT_TRUE(error.contains(QStringLiteral("permission denied"))) << error.toStdString();

    // A role that is neither is told so, and reads nothing.
    ResultsDatabase stranger;
    EXPECT_FALSE(stranger.open(serverUrl(QStringLiteral("stranger")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("may not read the results"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("results grant"))) << error.toStdString();

    // Refused: a role the server does not have, a name that is not a plain one, no class, a file.
    EXPECT_FALSE(grantWorkstation(admin, QStringLiteral("nobody"), QStringLiteral("3A"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no role nobody"))) << error.toStdString();
    EXPECT_FALSE(grantWorkstation(admin, QStringLiteral("x\"; DROP TABLE results; --"), QStringLiteral("3A"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("refused"))) << error.toStdString();
    EXPECT_FALSE(grantWorkstation(admin, QStringLiteral("ws_a"), QStringLiteral(" "), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("class"))) << error.toStdString();
    // Refused: roles that are not a plain login of their own: built-in, group, administering the
    // server (the administrator's own, a superuser), or unable to log in.
    ASSERT_TRUE(runAsAdmin({QStringLiteral("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = "
                                           "'nologin_group') THEN CREATE ROLE nologin_group NOLOGIN; END IF; END $$"),
                            QStringLiteral("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = "
                                           "'maker') THEN CREATE ROLE maker LOGIN CREATEROLE; END IF; END $$")})
                    .isEmpty());
    const QString administrator = qEnvironmentVariable("PGUSER");
    for (const QString& role : {QStringLiteral("pg_read_all_data"), QStringLiteral("pg_write_all_data"),
                                QStringLiteral("palpate_workstation"), QStringLiteral("palpate_instructor"),
                                administrator, QStringLiteral("nologin_group"), QStringLiteral("maker")}) {
        EXPECT_FALSE(grantWorkstation(admin, role, QStringLiteral("3A"), &error)) << role.toStdString();
        EXPECT_TRUE(error.contains(QStringLiteral("is refused"))) << role.toStdString() << ": " << error.toStdString();
        EXPECT_FALSE(grantInstructor(admin, role, &error)) << role.toStdString();
        EXPECT_TRUE(error.contains(QStringLiteral("is refused"))) << role.toStdString() << ": " << error.toStdString();
    }
    ResultsDatabase file;
    ASSERT_TRUE(file.open(dir.filePath(QStringLiteral("f.sqlite")), &error));
    EXPECT_FALSE(grantInstructor(file, QStringLiteral("teacher"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("PostgreSQL server only"))) << error.toStdString();
    EXPECT_EQ(teacher.allResults().size(), 5u);  // the refused grants changed nothing

    // A workstation moved to another class reads that class from its next connection.
    ASSERT_TRUE(grantWorkstation(admin, QStringLiteral("ws_a"), QStringLiteral("3B"), &error)) << error.toStdString();
    ResultsDatabase moved;
    ASSERT_TRUE(moved.open(serverUrl(QStringLiteral("ws_a")), &error)) << error.toStdString();
    EXPECT_EQ(moved.className(), QStringLiteral("3B"));
    ASSERT_EQ(moved.allResults().size(), 2u);
    EXPECT_EQ(moved.allResults().front().traineeName, QStringLiteral("Bo"));

    // Revoked (a machine retired): it reads and sends nothing more; what it sent stays.
    ASSERT_TRUE(revokeRole(admin, QStringLiteral("ws_b"), &error)) << error.toStdString();
    ResultsDatabase retired;
    EXPECT_FALSE(retired.open(serverUrl(QStringLiteral("ws_b")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("may not read the results"))) << error.toStdString();
    const SyncReport late = syncAs(bFile, QStringLiteral("ws_b"));
    EXPECT_FALSE(late.error.isEmpty());
    EXPECT_EQ(teacher.allResults().size(), 5u);
    EXPECT_FALSE(revokeRole(admin, QStringLiteral("nobody"), &error));
}

/// Runs a program; its exit code and what it wrote.
std::pair<int, QString> run(const QString& program, const QStringList& arguments) {
    test::ForkedProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(program, arguments);
    if (!p.waitForFinished(60000)) return {-1, QStringLiteral("did not finish")};
    return {p.exitCode(), QString::fromLocal8Bit(p.readAll())};
}

/// A self-signed certificate for localhost: `name`.crt and `name`.key in `folder`.
bool makeCertificate(const QString& folder, const QString& name) {
    const auto [code, output] = run(QStringLiteral("openssl"),
                                    {QStringLiteral("req"), QStringLiteral("-new"), QStringLiteral("-x509"), QStringLiteral("-days"),
                                     QStringLiteral("2"), QStringLiteral("-nodes"), QStringLiteral("-subj"),
                                     QStringLiteral("/CN=localhost"), QStringLiteral("-addext"),
                                     QStringLiteral("subjectAltName=DNS:localhost,IP:127.0.0.1,IP:::1"),
                                     QStringLiteral("-keyout"), folder + QLatin1Char('/') + name + QStringLiteral(".key"),
                                     QStringLiteral("-out"), folder + QLatin1Char('/') + name + QStringLiteral(".crt")});
    EXPECT_EQ(code, 0) << output.toStdString();
    return code == 0;
}

/// The server offers TLS with `certificate` until the end of the scope.
class ServerTls {
public:
    explicit ServerTls(const QString& folder) {
        // The server reads its key as the user it runs as, from a file only that user may read.
        const QString dataDir = dataDirectory();
        if (dataDir.isEmpty()) return;
        const QFileInfo owner(dataDir);
        mCert = dataDir + QStringLiteral("/palpate-test.crt");
        mKey = dataDir + QStringLiteral("/palpate-test.key");
        QFile::remove(mCert);
        QFile::remove(mKey);
        if (!QFile::copy(folder + QStringLiteral("/server.crt"), mCert) || !QFile::copy(folder + QStringLiteral("/server.key"), mKey))
            return;
        QFile::setPermissions(mKey, QFile::ReadOwner | QFile::WriteOwner);
        if (::chown(QFile::encodeName(mCert).constData(), owner.ownerId(), owner.groupId()) != 0 ||
            ::chown(QFile::encodeName(mKey).constData(), owner.ownerId(), owner.groupId()) != 0)
            return;
        mError = runAsAdmin({QStringLiteral("ALTER SYSTEM SET ssl_cert_file = '%1'").arg(mCert),
                             QStringLiteral("ALTER SYSTEM SET ssl_key_file = '%1'").arg(mKey),
                             QStringLiteral("ALTER SYSTEM SET ssl = on"), QStringLiteral("SELECT pg_reload_conf()")});
        mOn = mError.isEmpty();
        QThread::msleep(500);  // the postmaster rereads its files on the signal
    }
    ~ServerTls() {
        runAsAdmin({QStringLiteral("ALTER SYSTEM RESET ssl"), QStringLiteral("ALTER SYSTEM RESET ssl_cert_file"),
                    QStringLiteral("ALTER SYSTEM RESET ssl_key_file"), QStringLiteral("SELECT pg_reload_conf()")});
        QThread::msleep(500);
        QFile::remove(mCert);
        QFile::remove(mKey);
    }
    bool on() const { return mOn; }
    QString error() const { return mError; }

private:
    static QString dataDirectory() {
        QString dir;
        const QString name = QStringLiteral("data-dir");
        {
            QSqlDatabase raw = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), name);
            raw.setHostName(qEnvironmentVariable("PGHOST"));
            raw.setPort(qEnvironmentVariableIntValue("PGPORT"));
            raw.setDatabaseName(qEnvironmentVariable("PGDATABASE"));
            raw.setUserName(qEnvironmentVariable("PGUSER"));
            if (raw.open())
                if (QSqlQuery q(raw); q.exec(QStringLiteral("SHOW data_directory")) && q.next()) dir = q.value(0).toString();
        }
        QSqlDatabase::removeDatabase(name);
        return dir;
    }
    QString mCert, mKey, mError;
    bool mOn = false;
};

TEST(ServerTlsTest, EncryptedWhenOfferedAndVerifyFullRefusesAStranger) {
    REQUIRE_SERVER();
    clearServer();
    QTemporaryDir dir;
    ASSERT_TRUE(makeCertificate(dir.path(), QStringLiteral("server")));
    ASSERT_TRUE(makeCertificate(dir.path(), QStringLiteral("other")));
    QString error;
    {
        ResultsDatabase plain;  // the cluster pg_virtualenv makes offers no TLS
        ASSERT_TRUE(plain.open(serverUrl(), &error)) << error.toStdString();
        EXPECT_FALSE(plain.isEncrypted());
        EXPECT_TRUE(plain.connectionDescription().contains(QStringLiteral("no TLS")));
    }
    const ServerTls tls(dir.path());
    ASSERT_TRUE(tls.on()) << tls.error().toStdString();
    // The default (sslmode=prefer) takes the TLS the server offers.
    ResultsDatabase preferred;
    ASSERT_TRUE(preferred.open(serverUrl(), &error)) << error.toStdString();
    EXPECT_TRUE(preferred.isEncrypted());
    EXPECT_TRUE(preferred.connectionDescription().endsWith(QStringLiteral(", TLS")));
    // verify-full with the server's certificate as the root: encrypted and the server checked.
    ResultsDatabase verified;
    ASSERT_TRUE(verified.open(serverUrl() + QStringLiteral("?sslmode=verify-full&sslrootcert=") + dir.filePath(QStringLiteral("server.crt")),
                              &error))
        << error.toStdString();
    EXPECT_TRUE(verified.isEncrypted());
    // verify-full against a root the server's certificate is not from: refused, and said why.
    ResultsDatabase stranger;
    EXPECT_FALSE(stranger.open(serverUrl() + QStringLiteral("?sslmode=verify-full&sslrootcert=") + dir.filePath(QStringLiteral("other.crt")),
                               &error));
    EXPECT_TRUE(error.contains(QStringLiteral("cannot connect"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("certificate"))) << error.toStdString();
}

/// palpate-cli with `arguments`: exit code, stdout, stderr.
struct CliRun {
    int code = -1;
    QByteArray out, err;
};
CliRun cli(const QStringList& arguments) {
    test::ForkedProcess p;
    p.start(QStringLiteral(PALPATE_CLI_PATH), arguments);
    p.waitForFinished(120000);
    return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
}

// score --trainee --db URL: stored on the workstation first, then sent; with the server away it
// waits (exit 0, said on stderr) and goes with the next sync. results grant as the owner runs it.
TEST_F(ServerRoles, ScoreStoresAndSendsAndGrantNamesWhatIsWrong) {
    const QString recording = dir.filePath(QStringLiteral("press.palprec"));
    const QString source = QStringLiteral(PALPATE_SOURCE_DIR);
    const CliRun recorded = cli({QStringLiteral("run"), QStringLiteral("--exercise"), source + QStringLiteral("/resources/exercises/press_targets.json"),
                                 QStringLiteral("--device"), QStringLiteral("sim:path:") + source + QStringLiteral("/resources/exercises/press_targets.good.path"),
                                 QStringLiteral("--seconds"), QStringLiteral("0.5"), QStringLiteral("--record"), recording,
                                 QStringLiteral("--no-fifo")});
    ASSERT_EQ(recorded.code, 0) << recorded.err.toStdString();
    const QString local = dir.filePath(QStringLiteral("local.sqlite"));
    // The server away: stored here, waiting.
    CliRun r = cli({QStringLiteral("score"), QStringLiteral("--recording"), recording, QStringLiteral("--trainee"), QStringLiteral("Eve"),
                    QStringLiteral("--db"), QStringLiteral("postgresql://localhost:1/class"), QStringLiteral("--local"), local,
                    QStringLiteral("--json")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    QJsonObject stored = QJsonDocument::fromJson(r.out).object().value(QStringLiteral("stored")).toObject();
    EXPECT_EQ(stored.value(QStringLiteral("waiting")).toInt(), 1);
    EXPECT_TRUE(r.err.contains("wait for the server")) << r.err.toStdString();
    // The server back (as a workstation of class 3A): this one and the waiting one go, once each.
    ResultsDatabase admin;
    QString error;
    ASSERT_TRUE(admin.open(serverUrl(), &error)) << error.toStdString();
    const QString url = serverUrl();
    EXPECT_EQ(cli({QStringLiteral("results"), QStringLiteral("grant"), QStringLiteral("--db"), url, QStringLiteral("--workstation"),
                   QStringLiteral("ws_a"), QStringLiteral("--class"), QStringLiteral("3A")})
                  .code,
              0);
    r = cli({QStringLiteral("score"), QStringLiteral("--recording"), recording, QStringLiteral("--trainee"), QStringLiteral("Eve"),
             QStringLiteral("--db"), serverUrl(QStringLiteral("ws_a")), QStringLiteral("--local"), local, QStringLiteral("--json")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    stored = QJsonDocument::fromJson(r.out).object().value(QStringLiteral("stored")).toObject();
    EXPECT_EQ(stored.value(QStringLiteral("sent")).toInt(), 2);
    EXPECT_EQ(stored.value(QStringLiteral("waiting")).toInt(), 0);
    r = cli({QStringLiteral("results"), QStringLiteral("list"), QStringLiteral("--db"), serverUrl(QStringLiteral("ws_a")),
             QStringLiteral("--json")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QJsonObject listed = QJsonDocument::fromJson(r.out).object();
    const QJsonArray rows = listed.value(QStringLiteral("results")).toArray();
    ASSERT_EQ(rows.size(), 2);
    for (const auto& row : rows) {
        EXPECT_EQ(row.toObject().value(QStringLiteral("trainee")).toString(), QStringLiteral("Eve"));
        EXPECT_EQ(row.toObject().value(QStringLiteral("class")).toString(), QStringLiteral("3A"));
        EXPECT_EQ(row.toObject().value(QStringLiteral("submitted_by")).toString(), QStringLiteral("ws_a"));
    }
    EXPECT_EQ(listed.value(QStringLiteral("connection")).toObject().value(QStringLiteral("class")).toString(), QStringLiteral("3A"));
    // results class --class filters; grant names what is wrong.
    r = cli({QStringLiteral("results"), QStringLiteral("class"), QStringLiteral("--db"), url, QStringLiteral("--class"), QStringLiteral("3B"),
             QStringLiteral("--json")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(QJsonDocument::fromJson(r.out).object().value(QStringLiteral("rows")).toArray().isEmpty());
    r = cli({QStringLiteral("results"), QStringLiteral("grant"), QStringLiteral("--db"), url, QStringLiteral("--workstation"),
             QStringLiteral("nobody"), QStringLiteral("--class"), QStringLiteral("3A")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains("no role nobody")) << r.err.toStdString();
    EXPECT_EQ(cli({QStringLiteral("results"), QStringLiteral("grant"), QStringLiteral("--db"), url, QStringLiteral("--workstation"),
                   QStringLiteral("ws_a")})
                  .code,
              2);  // no class
    EXPECT_EQ(cli({QStringLiteral("results"), QStringLiteral("grant"), QStringLiteral("--db"), local, QStringLiteral("--instructor"),
                   QStringLiteral("teacher")})
                  .code,
              2);  // not a server
    // Revoked, the workstation's login reads nothing more.
    r = cli({QStringLiteral("results"), QStringLiteral("revoke"), QStringLiteral("--db"), url, QStringLiteral("--role"), QStringLiteral("ws_a")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    r = cli({QStringLiteral("results"), QStringLiteral("list"), QStringLiteral("--db"), serverUrl(QStringLiteral("ws_a"))});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains("may not read the results")) << r.err.toStdString();
    EXPECT_EQ(cli({QStringLiteral("results"), QStringLiteral("revoke"), QStringLiteral("--db"), url}).code, 2);  // no role
}

}  // namespace
