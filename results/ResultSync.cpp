#include "results/ResultSync.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QStringList>

namespace palpate {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(palpate::ResultsDatabase)
};

}  // namespace

QString SyncReport::refusedText() const {
    QStringList lines;
    for (const RefusedResult& r : refused)
        lines << Tr::tr(
                     "The server refused %1's result of \"%2\" (%3, %4): %5. It stays on this workstation; "
                     "rename the trainee here or ask the instructor (results grant, docs/results-store.md), then "
                     "send again.")
                     .arg(r.trainee, r.exercise, r.startedUtc.toString(Qt::ISODate), r.uid, r.why);
    return lines.join(QLatin1Char('\n'));
}

SyncReport syncResults(ResultsDatabase& local, ResultsDatabase& server) {
    SyncReport report;
    const std::vector<ResultRecord> pending = local.unsyncedResults();
    report.waiting = int(pending.size());
    if (!local.isOpen() || !server.isOpen()) {
        report.error = QStringLiteral("both databases must be open");
        return report;
    }
    report.connection = server.connectionDescription();
    for (const ResultRecord& r : pending) {
        QString error;
        const std::optional<bool> inserted = server.importResult(r, r.traineeName, &error);
        if (!inserted) {
            // The server still answers: it refused this result, not the connection. Say which and
            // why, keep it waiting, and send the others.
            if (server.answers()) {
                report.refused.push_back({r.uid, r.traineeName, r.exerciseName, r.startedUtc, error});
                continue;
            }
            report.error = error;
            return report;
        }
        // On the server now: a crash before this mark only means the next run finds it there.
        if (!local.markSynced(r.uid, QDateTime::currentDateTimeUtc(), &error)) {
            report.error = error;
            return report;
        }
        ++(*inserted ? report.sent : report.alreadyThere);
        --report.waiting;
    }
    return report;
}

}  // namespace palpate
