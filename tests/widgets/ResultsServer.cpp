#include "tests/widgets/ResultsServer.h"

#include "results/ResultsDatabase.h"

#include <QSqlError>
#include <QSqlQuery>

#include <atomic>

namespace palpate::test {

QString serverUrl(const QString& user) {
    const QByteArray host = qgetenv("PGHOST"), port = qgetenv("PGPORT"), database = qgetenv("PGDATABASE");
    if (host.isEmpty() || database.isEmpty()) return {};
    return QStringLiteral("postgresql://%1@%2:%3/%4")
        .arg(user.isEmpty() ? qEnvironmentVariable("PGUSER") : user, QString::fromUtf8(host),
             QString::fromUtf8(port.isEmpty() ? "5432" : port), QString::fromUtf8(database));
}

QString runAsAdmin(const QStringList& statements) {
    static std::atomic<int> counter{0};
    const QString name = QStringLiteral("admin-%1").arg(counter.fetch_add(1));
    QString why;
    {
        QSqlDatabase raw = QSqlDatabase::addDatabase(QStringLiteral("QPSQL"), name);
        raw.setHostName(qEnvironmentVariable("PGHOST"));
        raw.setPort(qEnvironmentVariableIntValue("PGPORT"));
        raw.setDatabaseName(qEnvironmentVariable("PGDATABASE"));
        raw.setUserName(qEnvironmentVariable("PGUSER"));
        if (!raw.open()) {
            why = raw.lastError().text();
        } else {
            QSqlQuery q(raw);
            for (const QString& s : statements)
                if (!q.exec(s)) {
                    why = s + QStringLiteral(": ") + q.lastError().text();
                    break;
                }
        }
    }
    QSqlDatabase::removeDatabase(name);
    return why;
}

ScoreReport completedReport(double score) {
    ScoreReport r;
    r.exerciseName = "Press two targets";
    r.score = score;
    r.guidance.completed = true;
    return r;
}

QString workstationFile(const QTemporaryDir& dir, const QString& name, const QString& trainee, int count, double firstScore) {
    const QString path = dir.filePath(name + QStringLiteral(".sqlite"));
    ResultsDatabase db;
    QString error;
    EXPECT_TRUE(db.open(path, &error)) << error.toStdString();
    const qint64 id = db.addTrainee(trainee, &error);
    for (int i = 0; i < count; ++i)
        EXPECT_GE(db.addResult(id, completedReport(firstScore + i), QStringLiteral("Press two targets"), QStringLiteral("/e.json"),
                               QDateTime::currentDateTimeUtc(), 10.0, QString(), &error),
                  0)
            << error.toStdString();
    return path;
}

void clearServer() {
    ResultsDatabase db;
    QString error;
    ASSERT_TRUE(db.open(serverUrl(), &error)) << error.toStdString();
    db.close();
    const QString why =
        runAsAdmin({QStringLiteral("TRUNCATE results, staircases, trainees, class_workstations RESTART IDENTITY")});
    ASSERT_TRUE(why.isEmpty()) << why.toStdString();
}

}  // namespace palpate::test
