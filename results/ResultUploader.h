#pragma once
// The workstation's side of the class's server (docs/results-store.md): after each stored result,
// and every minute while some wait, the results the server has not acknowledged are copied to it
// on a worker thread (syncResults), so the window never waits for the network. statusText() says
// what is waiting, for the status bar.

#include "results/ResultSync.h"

#include <QObject>
#include <QString>
#include <QTimer>

class QThread;

namespace palpate {

class ResultUploader final : public QObject {
    Q_OBJECT
public:
    explicit ResultUploader(QObject* parent = nullptr);
    /// Waits for a copy in flight (at most the connect timeout and one result).
    ~ResultUploader() override;

    /// The workstation's database file and the server (a postgresql:// URL; "" = none: nothing is sent).
    void setLocations(const QString& localPath, const QString& serverUrl);
    QString serverUrl() const { return mServer; }
    /// Starts a copy now (or right after the one running).
    void syncNow();
    bool busy() const { return mThread != nullptr; }
    /// The last copy's outcome.
    const SyncReport& lastReport() const { return mLast; }
    bool hasReport() const { return mHaveReport; }
    /// "" without a server; else what is on the server and what waits.
    QString statusText() const;

signals:
    /// A copy ended: statusText() changed.
    void changed();

private:
    void onFinished(const SyncReport& report);

    QString mLocal, mServer;
    QThread* mThread = nullptr;
    bool mAgain = false;
    SyncReport mLast;
    bool mHaveReport = false;
    QTimer mRetry;
};

}  // namespace palpate
