#pragma once
// Local first, then the class's server (docs/results-store.md): every result is written to the
// workstation's own database when it is scored; this copies the ones the server has not
// acknowledged, oldest first, and marks each as sent once the server has it. A result carries a
// unique id and the server keeps one row per id, so a retry (the answer lost, the program killed
// between the two steps) never duplicates it. A server that is away stops the copy and leaves
// the rest waiting.

#include "results/ResultsDatabase.h"

#include <QString>

namespace palpate {

struct SyncReport {
    int sent = 0;          ///< new on the server
    int alreadyThere = 0;  ///< the server had them (an earlier copy whose mark was lost)
    int waiting = 0;       ///< still to send after this run
    QString error;         ///< "" or why the copy stopped (the server's words)
    QString connection;    ///< the server's connectionDescription() ("" when it did not answer)
};

/// Copies `local`'s unsent results to `server`. Both must be open.
SyncReport syncResults(ResultsDatabase& local, ResultsDatabase& server);

}  // namespace palpate
