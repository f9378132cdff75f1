// The results database and the score report PDF under QT_QPA_PLATFORM=offscreen: a database closed
// and reopened gives back what was stored; a version-1 file is migrated to version 2 with its rows
// kept; a newer schema, a file that is not a database and a folder that does not exist are refused
// with a message naming the file; the PDF is written and pdftotext reads the score and the trainee.
#include "results/ResultsDatabase.h"
#include "report/ScoreReportPdf.h"

#include <QApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using namespace palpate;

namespace {

ScoreReport sampleReport(double score) {
    ScoreReport r;
    r.exerciseName = "Press two targets";
    r.type = ExerciseType::PressTargets;
    r.score = score;
    auto add = [&](Metric m, double value, double sub, double weight, double contribution) {
        MetricResult line;
        line.metric = m;
        line.value = value;
        line.subScore = sub;
        line.weight = weight;
        line.contribution = contribution;
        r.metrics.push_back(line);
    };
    add(Metric::Completion, 1.0, 1.0, 3.0, 50.0);
    add(Metric::TimeS, 12.5, 0.6, 1.0, 10.0);
    add(Metric::PeakForceN, 2.4, 0.4, 2.0, 12.5);
    r.guidance.completed = true;
    r.guidance.forceMinN = 1.0;
    r.guidance.forceMaxN = 2.0;
    return r;
}

/// Runs SQL on a file with a connection of the test's own (to build or damage files by hand).
void execOn(const QString& path, const QStringList& statements) {
    const QString name = QStringLiteral("test-%1").arg(qHash(path));
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
        db.setDatabaseName(path);
        ASSERT_TRUE(db.open());
        QSqlQuery q(db);
        for (const QString& s : statements) ASSERT_TRUE(q.exec(s)) << s.toStdString();
        q.finish();
        db.close();
    }
    QSqlDatabase::removeDatabase(name);
}

}  // namespace

TEST(ResultsDatabase, SurvivesCloseAndReopen) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("results.sqlite"));
    const QDateTime t1 = QDateTime(QDate(2026, 3, 1), QTime(10, 0, 0, 250), Qt::UTC);
    const QDateTime t2 = t1.addSecs(3600);
    qint64 alice = -1, bob = -1;
    std::vector<ResultRecord> before;
    {
        ResultsDatabase db;
        QString error;
        ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
        EXPECT_EQ(db.schemaVersion(), ResultsDatabase::kSchemaVersion);
        alice = db.addTrainee(QStringLiteral("Alice"), &error);
        bob = db.addTrainee(QStringLiteral("Bob"), &error);
        ASSERT_GE(alice, 0) << error.toStdString();
        ASSERT_GE(bob, 0);
        EXPECT_NE(alice, bob);
        EXPECT_EQ(db.addTrainee(QStringLiteral("Alice")), alice);  // an existing name gives its id
        // Stored out of order: results() gives them oldest first.
        ASSERT_GE(db.addResult(alice, sampleReport(81.5), QStringLiteral("Press"), QStringLiteral("/ex/press.json"),
                               t2, 14.0, QStringLiteral("/rec/b.palprec"), &error), 0)
            << error.toStdString();
        ASSERT_GE(db.addResult(alice, sampleReport(64.25), QStringLiteral("Press"), QStringLiteral("/ex/press.json"),
                               t1, 20.5, QString(), &error), 0)
            << error.toStdString();
        ASSERT_GE(db.addResult(bob, sampleReport(40.0), QStringLiteral("Trace"), QStringLiteral("/ex/trace.json"),
                               t1, 30.0, QString(), &error), 0);
        EXPECT_LT(db.addResult(9999, sampleReport(1.0), QStringLiteral("X"), QString(), t1, 1.0, QString(), &error), 0);
        EXPECT_TRUE(error.contains(QStringLiteral("9999"))) << error.toStdString();
        before = db.results(alice);
        ASSERT_EQ(before.size(), 2u);
        EXPECT_EQ(before[0].startedUtc, t1);
        EXPECT_EQ(before[1].startedUtc, t2);
        EXPECT_DOUBLE_EQ(before[0].score, 64.25);
        EXPECT_EQ(before[1].recordingPath, QStringLiteral("/rec/b.palprec"));
        const QJsonObject metrics = QJsonDocument::fromJson(before[1].metricsJson.toUtf8()).object();
        EXPECT_DOUBLE_EQ(metrics.value(QStringLiteral("peak_force_n")).toDouble(), 2.4);
        const QJsonObject rubric = QJsonDocument::fromJson(before[1].rubricJson.toUtf8()).object();
        EXPECT_DOUBLE_EQ(rubric.value(QStringLiteral("completion")).toObject().value(QStringLiteral("contribution")).toDouble(),
                         50.0);
    }
    ResultsDatabase db;
    QString error;
    ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
    const std::vector<TraineeRecord> trainees = db.trainees();
    ASSERT_EQ(trainees.size(), 2u);
    EXPECT_EQ(trainees[0].name, QStringLiteral("Alice"));
    EXPECT_EQ(trainees[0].id, alice);
    EXPECT_EQ(trainees[1].name, QStringLiteral("Bob"));
    EXPECT_TRUE(trainees[0].created.isValid());
    const std::vector<ResultRecord> after = db.results(alice);
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t i = 0; i < after.size(); ++i) {
        EXPECT_EQ(after[i].id, before[i].id);
        EXPECT_EQ(after[i].traineeId, alice);
        EXPECT_EQ(after[i].exerciseName, before[i].exerciseName);
        EXPECT_EQ(after[i].exercisePath, before[i].exercisePath);
        EXPECT_EQ(after[i].startedUtc, before[i].startedUtc);
        EXPECT_EQ(after[i].durationS, before[i].durationS);
        EXPECT_EQ(after[i].score, before[i].score);
        EXPECT_EQ(after[i].metricsJson, before[i].metricsJson);
        EXPECT_EQ(after[i].rubricJson, before[i].rubricJson);
        EXPECT_EQ(after[i].recordingPath, before[i].recordingPath);
    }
    EXPECT_EQ(db.results(bob).size(), 1u);
}

TEST(ResultsDatabase, TwoInstancesAtOnce) {
    QTemporaryDir dir;
    ResultsDatabase a, b;
    QString error;
    ASSERT_TRUE(a.open(dir.filePath(QStringLiteral("a.sqlite")), &error)) << error.toStdString();
    ASSERT_TRUE(b.open(dir.filePath(QStringLiteral("b.sqlite")), &error)) << error.toStdString();
    EXPECT_GE(a.addTrainee(QStringLiteral("Only in a")), 0);
    EXPECT_EQ(a.trainees().size(), 1u);
    EXPECT_EQ(b.trainees().size(), 0u);
}

TEST(ResultsDatabase, MigratesVersion1KeepingRows) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("v1.sqlite"));
    QString error;
    ASSERT_TRUE(ResultsDatabase::createVersion1(path, &error)) << error.toStdString();
    execOn(path, {QStringLiteral("INSERT INTO trainees (name, created) VALUES ('Carol', '2025-01-02T03:04:05.000Z')"),
                  QStringLiteral("INSERT INTO results (trainee_id, exercise_name, exercise_path, started_utc,"
                                 " duration_s, score, metrics_json, rubric_json) VALUES (1, 'Lump', '/ex/lump.json',"
                                 " '2025-01-02T04:00:00.000Z', 42.5, 77.5, '{\"completion\":1}', '{}')")});
    ResultsDatabase db;
    ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
    EXPECT_EQ(db.schemaVersion(), ResultsDatabase::kSchemaVersion);
    const std::vector<TraineeRecord> trainees = db.trainees();
    ASSERT_EQ(trainees.size(), 1u);
    EXPECT_EQ(trainees[0].name, QStringLiteral("Carol"));
    std::vector<ResultRecord> rows = db.results(trainees[0].id);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].exerciseName, QStringLiteral("Lump"));
    EXPECT_DOUBLE_EQ(rows[0].score, 77.5);
    EXPECT_DOUBLE_EQ(rows[0].durationS, 42.5);
    EXPECT_EQ(rows[0].metricsJson, QStringLiteral("{\"completion\":1}"));
    EXPECT_EQ(rows[0].recordingPath, QString());
    EXPECT_EQ(rows[0].startedUtc, QDateTime(QDate(2025, 1, 2), QTime(4, 0), Qt::UTC));
    // The new column is usable.
    ASSERT_GE(db.addResult(trainees[0].id, sampleReport(90.0), QStringLiteral("Lump"), QStringLiteral("/ex/lump.json"),
                           QDateTime(QDate(2025, 2, 1), QTime(9, 0), Qt::UTC), 10.0, QStringLiteral("/r.palprec"),
                           &error), 0)
        << error.toStdString();
    db.close();
    ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
    rows = db.results(trainees[0].id);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1].recordingPath, QStringLiteral("/r.palprec"));
}

// A session the trainee stopped is stored as stopped, not as a score of its own.
TEST(ResultsDatabase, StoresHowEachSessionEnded) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("outcomes.sqlite"));
    const QDateTime t = QDateTime(QDate(2026, 3, 1), QTime(10, 0), Qt::UTC);
    {
        ResultsDatabase db;
        QString error;
        ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
        const qint64 eve = db.addTrainee(QStringLiteral("Eve"));
        ScoreReport stopped = sampleReport(12.0);
        stopped.guidance.completed = false;
        ScoreReport timeUp = sampleReport(40.0);
        timeUp.guidance.completed = false;
        timeUp.guidance.timeUp = true;
        ASSERT_GE(db.addResult(eve, sampleReport(80.0), QStringLiteral("Press"), QString(), t, 10.0, QString()), 0);
        ASSERT_GE(db.addResult(eve, stopped, QStringLiteral("Press"), QString(), t.addSecs(60), 3.0, QString()), 0);
        ASSERT_GE(db.addResult(eve, timeUp, QStringLiteral("Press"), QString(), t.addSecs(120), 60.0, QString()), 0);
    }
    ResultsDatabase db;
    ASSERT_TRUE(db.open(path));
    const std::vector<ResultRecord> rows = db.results(db.trainees().at(0).id);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0].outcome, ResultOutcome::Completed);
    EXPECT_EQ(rows[1].outcome, ResultOutcome::Stopped);
    EXPECT_EQ(rows[2].outcome, ResultOutcome::TimeUp);
    EXPECT_TRUE(isScored(rows[0].outcome));
    EXPECT_FALSE(isScored(rows[1].outcome));
    EXPECT_TRUE(isScored(rows[2].outcome));
    EXPECT_DOUBLE_EQ(rows[1].score, 12.0);  // the partial score is kept, for the report
}

// A version-2 file gains the outcome column: rows whose completion is 1 are completed, the others
// cannot be told apart (stopped or timed out) and stay unknown, counted as before.
TEST(ResultsDatabase, MigratesVersion2AddingTheOutcome) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("v2.sqlite"));
    QString error;
    ASSERT_TRUE(ResultsDatabase::createVersion1(path, &error)) << error.toStdString();
    // Version 2 as it shipped: version 1 and the recording path.
    execOn(path, {QStringLiteral("ALTER TABLE results ADD COLUMN recording_path TEXT NOT NULL DEFAULT ''"),
                  QStringLiteral("PRAGMA user_version = 2"),
                  QStringLiteral("INSERT INTO trainees (name, created) VALUES ('Finn', '2025-01-02T03:04:05.000Z')"),
                  QStringLiteral("INSERT INTO results (trainee_id, exercise_name, exercise_path, started_utc, duration_s,"
                                 " score, metrics_json, rubric_json, recording_path) VALUES (1, 'Press', '/p.json',"
                                 " '2025-01-02T04:00:00.000Z', 20, 85, '{\"completion\":1,\"time_s\":20}', '{}', '/a')"),
                  QStringLiteral("INSERT INTO results (trainee_id, exercise_name, exercise_path, started_utc, duration_s,"
                                 " score, metrics_json, rubric_json, recording_path) VALUES (1, 'Press', '/p.json',"
                                 " '2025-01-02T04:01:00.000Z', 4, 0, '{\"completion\":0}', '{}', '')")});
    ResultsDatabase db;
    ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
    EXPECT_EQ(db.schemaVersion(), ResultsDatabase::kSchemaVersion);
    const std::vector<ResultRecord> rows = db.results(db.trainees().at(0).id);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].outcome, ResultOutcome::Completed);
    EXPECT_EQ(rows[0].recordingPath, QStringLiteral("/a"));
    EXPECT_DOUBLE_EQ(rows[0].score, 85.0);
    EXPECT_EQ(rows[1].outcome, ResultOutcome::Unknown);
    EXPECT_TRUE(isScored(rows[1].outcome));
}

// A version-3 file gains the expert flag (old rows are trainees' sessions), the aids column (none
// shown) and the staircase table; expert sessions are found by exercise across trainees.
TEST(ResultsDatabase, MigratesVersion3AddingExpertsAidsAndStaircases) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("v3.sqlite"));
    QString error;
    ASSERT_TRUE(ResultsDatabase::createVersion1(path, &error)) << error.toStdString();
    // Version 3 as it shipped: version 1, the recording path, the outcome.
    execOn(path, {QStringLiteral("ALTER TABLE results ADD COLUMN recording_path TEXT NOT NULL DEFAULT ''"),
                  QStringLiteral("ALTER TABLE results ADD COLUMN outcome TEXT NOT NULL DEFAULT ''"),
                  QStringLiteral("PRAGMA user_version = 3"),
                  QStringLiteral("INSERT INTO trainees (name, created) VALUES ('Gus', '2025-01-02T03:04:05.000Z')"),
                  QStringLiteral("INSERT INTO results (trainee_id, exercise_name, exercise_path, started_utc, duration_s,"
                                 " score, metrics_json, rubric_json, recording_path, outcome) VALUES (1, 'Press',"
                                 " '/p.json', '2025-01-02T04:00:00.000Z', 20, 85, '{\"completion\":1}', '{}', '/a',"
                                 " 'completed')")});
    ResultsDatabase db;
    ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
    EXPECT_EQ(db.schemaVersion(), ResultsDatabase::kSchemaVersion);  // through 4 to the current one
    const qint64 gus = db.trainees().at(0).id;
    std::vector<ResultRecord> rows = db.results(gus);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].uid.size(), 36);  // version 5 gave the old row its own uid
    EXPECT_FALSE(rows[0].expert);
    EXPECT_EQ(rows[0].aidsJson, QStringLiteral("[]"));
    EXPECT_EQ(rows[0].outcome, ResultOutcome::Completed);
    EXPECT_DOUBLE_EQ(rows[0].score, 85.0);
    EXPECT_TRUE(db.expertResults(QStringLiteral("/p.json"), QStringLiteral("Press")).empty());

    // Expert sessions of another trainee (the instructor), with the aids shown.
    const qint64 ida = db.addTrainee(QStringLiteral("Ida (instructor)"));
    ScoreReport withAids = sampleReport(95.0);
    withAids.aids = {{"force_gauge", 0.5}};
    const QDateTime t(QDate(2026, 1, 1), QTime(9, 0), Qt::UTC);
    ASSERT_GE(db.addResult(ida, withAids, QStringLiteral("Press"), QStringLiteral("/p.json"), t, 9.0, QString(), true,
                           &error), 0)
        << error.toStdString();
    ASSERT_GE(db.addResult(ida, sampleReport(90.0), QStringLiteral("Other"), QStringLiteral("/o.json"), t, 9.0,
                           QString(), true), 0);
    ASSERT_GE(db.addResult(gus, sampleReport(50.0), QStringLiteral("Press"), QStringLiteral("/p.json"), t, 9.0,
                           QString()), 0);  // the old call: not an expert's
    const std::vector<ResultRecord> experts = db.expertResults(QStringLiteral("/p.json"), QStringLiteral("Press"));
    ASSERT_EQ(experts.size(), 1u);
    EXPECT_TRUE(experts[0].expert);
    EXPECT_EQ(experts[0].traineeId, ida);
    EXPECT_DOUBLE_EQ(experts[0].score, 95.0);
    const QJsonDocument aids = QJsonDocument::fromJson(experts[0].aidsJson.toUtf8());
    ASSERT_TRUE(aids.isArray());
    ASSERT_EQ(aids.array().size(), 1);
    EXPECT_EQ(aids.array()[0].toObject().value(QStringLiteral("name")).toString(), QStringLiteral("force_gauge"));
    EXPECT_DOUBLE_EQ(aids.array()[0].toObject().value(QStringLiteral("level")).toDouble(), 0.5);
    rows = db.results(gus);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_FALSE(rows[1].expert);
    // A session stored without a path (the exercise a recording carried) matches by name.
    ASSERT_GE(db.addResult(ida, sampleReport(91.0), QStringLiteral("Press"), QString(), t, 9.0, QString(), true), 0);
    EXPECT_EQ(db.expertResults(QStringLiteral("/p.json"), QStringLiteral("Press")).size(), 2u);

    // Staircases per trainee and exercise, kept across a reopen, replaced by a put.
    EXPECT_EQ(db.staircase(gus, QStringLiteral("/p.json")), QString());
    ASSERT_TRUE(db.putStaircase(gus, QStringLiteral("/p.json"), QStringLiteral("{\"level\":3}"), &error))
        << error.toStdString();
    ASSERT_TRUE(db.putStaircase(gus, QStringLiteral("/p.json"), QStringLiteral("{\"level\":2.5}"), &error));
    ASSERT_TRUE(db.putStaircase(ida, QStringLiteral("/p.json"), QStringLiteral("{\"level\":1}"), &error));
    EXPECT_FALSE(db.putStaircase(9999, QStringLiteral("/p.json"), QStringLiteral("{}"), &error));
    db.close();
    ASSERT_TRUE(db.open(path, &error)) << error.toStdString();
    EXPECT_EQ(db.staircase(gus, QStringLiteral("/p.json")), QStringLiteral("{\"level\":2.5}"));
    EXPECT_EQ(db.staircase(ida, QStringLiteral("/p.json")), QStringLiteral("{\"level\":1}"));
    EXPECT_EQ(db.staircase(gus, QStringLiteral("/o.json")), QString());
}

TEST(ResultsDatabase, RefusesNewerSchema) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("future.sqlite"));
    {
        ResultsDatabase db;
        ASSERT_TRUE(db.open(path));
        ASSERT_GE(db.addTrainee(QStringLiteral("Dan")), 0);
    }
    const int newer = ResultsDatabase::kSchemaVersion + 1;
    execOn(path, {QStringLiteral("PRAGMA user_version = %1").arg(newer)});
    ResultsDatabase db;
    QString error;
    EXPECT_FALSE(db.open(path, &error));
    EXPECT_FALSE(db.isOpen());
    EXPECT_TRUE(error.contains(path)) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("newer"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QString::number(newer))) << error.toStdString();
    EXPECT_EQ(db.lastError(), error);
}

TEST(ResultsDatabase, RefusesGarbageAndForeignFiles) {
    QTemporaryDir dir;
    const QString garbage = dir.filePath(QStringLiteral("garbage.sqlite"));
    {
        QFile f(garbage);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(4096, 'x'));
    }
    ResultsDatabase db;
    QString error;
    EXPECT_FALSE(db.open(garbage, &error));
    EXPECT_TRUE(error.contains(garbage)) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("not a"))) << error.toStdString();
    // The garbage is left as it was.
    EXPECT_EQ(QFileInfo(garbage).size(), 4096);

    const QString foreign = dir.filePath(QStringLiteral("other.sqlite"));
    execOn(foreign, {QStringLiteral("CREATE TABLE something (x INTEGER)")});
    EXPECT_FALSE(db.open(foreign, &error));
    EXPECT_TRUE(error.contains(foreign)) << error.toStdString();

    const QString nowhere = dir.filePath(QStringLiteral("no/such/folder/results.sqlite"));
    EXPECT_FALSE(db.open(nowhere, &error));
    EXPECT_TRUE(error.contains(nowhere)) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("does not exist"))) << error.toStdString();
    EXPECT_FALSE(QFileInfo::exists(nowhere));

    // Still usable after the failures.
    EXPECT_TRUE(db.open(dir.filePath(QStringLiteral("good.sqlite")), &error)) << error.toStdString();
}

TEST(ScoreReportPdf, WritesReadableText) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("report.pdf"));
    ScoreReportContent content;
    for (int i = 0; i <= 400; ++i) {
        const double t = i * 0.05;
        content.force.push_back({t, 1.5 + std::sin(t) * 0.8});
    }
    content.windows.push_back({0.0, 20.0, 1.0, 2.0, 0});
    content.report = sampleReport(72.5);
    content.traineeName = QStringLiteral("Erika Mustermann");
    content.exerciseName = QStringLiteral("Press two targets");
    QString error;
    ASSERT_TRUE(writeScoreReportPdf(path, content, &error)) << error.toStdString();
    ASSERT_TRUE(QFileInfo::exists(path));
    EXPECT_GT(QFileInfo(path).size(), 1000);
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_TRUE(f.read(5).startsWith("%PDF-"));

    // Without a series the plot is left out; still a valid file.
    const QString noPlot = dir.filePath(QStringLiteral("noplot.pdf"));
    ASSERT_TRUE(writeScoreReportPdf(noPlot, ScoreReportContent{}, &error)) << error.toStdString();
    EXPECT_GT(QFileInfo(noPlot).size(), 0);

    const QString nowhere = dir.filePath(QStringLiteral("no/such/report.pdf"));
    EXPECT_FALSE(writeScoreReportPdf(nowhere, content, &error));
    EXPECT_TRUE(error.contains(nowhere)) << error.toStdString();

    const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    if (pdftotext.isEmpty()) GTEST_SKIP() << "pdftotext not installed (poppler-utils): the PDF's text is not checked";
    QProcess proc;
    proc.start(pdftotext, {path, QStringLiteral("-")});
    ASSERT_TRUE(proc.waitForFinished(30000));
    ASSERT_EQ(proc.exitCode(), 0) << proc.readAllStandardError().toStdString();
    // pdftotext guesses lines and columns: compare with runs of white space collapsed, and the
    // exercise name word by word (its reading order beside the date line is pdftotext's choice).
    const QString text = QString::fromUtf8(proc.readAllStandardOutput()).simplified();
    EXPECT_TRUE(text.contains(QStringLiteral("Erika Mustermann"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Score: %1 / 100").arg(QLocale().toString(72.5, 'f', 1))))
        << text.toStdString();
    for (const char* word : {"Press", "two", "targets"}) EXPECT_TRUE(text.contains(QLatin1String(word))) << word;
    // Metrics by their names for people, values in the metric's display.
    EXPECT_TRUE(text.contains(QStringLiteral("Peak force"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Completion 100 %"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Contribution"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Time (s)"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("force window"))) << text.toStdString();
}

int main(int argc, char** argv) {
    // Before QApplication: the platform is chosen in its constructor. No GPU, no display needed.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
