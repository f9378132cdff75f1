#include "results/ResultSync.h"

#include <QDateTime>

namespace palpate {

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
