#pragma once
// Local first, then the class's server (docs/results-store.md): every result is written to the
// workstation's own database when it is scored; this copies the ones the server has not
// acknowledged, oldest first, and marks each as sent once the server has it. A result carries a
// unique id and the server keeps one row per id, so a retry (the answer lost, the program killed
// between the two steps) never duplicates it. A server that is away stops the copy and leaves
// the rest waiting. A result the server refuses while it answers (a trainee of that name in
// another class, a policy) is named with why and what to do, stays waiting on the workstation,
// and does not hold back the results after it.

#include "results/ResultsDatabase.h"

#include <QDateTime>
#include <QString>

#include <vector>

namespace palpate {

/// A result the server would not take, and why (the server's words).
struct RefusedResult {
    QString uid;
    QString trainee;
    QString exercise;
    QDateTime startedUtc;
    QString why;
};

struct SyncReport {
    int sent = 0;          ///< new on the server
    int alreadyThere = 0;  ///< the server had them (an earlier copy whose mark was lost)
    int waiting = 0;       ///< still to send after this run
    QString error;         ///< "" or why the copy stopped (the server's words)
    QString connection;    ///< the server's connectionDescription() ("" when it did not answer)
    /// Refused by a server that answers: still waiting (counted in `waiting`), the rest went on.
    std::vector<RefusedResult> refused;
    /// One line per refused result: which, why, and what to do ("" when none).
    QString refusedText() const;
};

/// Copies `local`'s unsent results to `server`. Both must be open.
SyncReport syncResults(ResultsDatabase& local, ResultsDatabase& server);

}  // namespace palpate
