#include "results/ResultUploader.h"

#include "results/HandOff.h"

#include <QThread>

namespace palpate {

ResultUploader::ResultUploader(QObject* parent) : QObject(parent) {
    mRetry.setInterval(60 * 1000);
    connect(&mRetry, &QTimer::timeout, this, &ResultUploader::syncNow);
}

ResultUploader::~ResultUploader() {
    if (mThread) {
        mThread->wait();  // its queued call to this object is dropped with it
        delete mThread;
    }
}

void ResultUploader::setLocations(const QString& localPath, const QString& serverUrl) {
    const bool changedServer = serverUrl != mServer;
    mLocal = localPath;
    mServer = serverUrl;
    if (changedServer) {
        mHaveReport = false;
        mLast = {};
        mRetry.stop();
        emit changed();
    }
    if (!mServer.isEmpty()) syncNow();
}

void ResultUploader::syncNow() {
    if (mServer.isEmpty() || mLocal.isEmpty()) return;
    if (mThread) {
        mAgain = true;
        return;
    }
    const QString local = mLocal, server = mServer;
    mThread = QThread::create([this, local, server] {
        SyncReport report;
        {
            // Connections of this thread's own (Qt SQL connections belong to the thread that made them).
            ResultsDatabase localDb, serverDb;
            QString error;
            if (!localDb.open(local, &error)) {
                report.error = error;
            } else if (!serverDb.open(server, &error)) {
                report.waiting = int(localDb.unsyncedResults().size());
                report.error = error;
            } else {
                report = syncResults(localDb, serverDb);
            }
        }
        handOffTo(this, [this, report] { onFinished(report); });
    });
    mThread->setObjectName(QStringLiteral("results upload"));
    mThread->start(QThread::LowPriority);
}

void ResultUploader::onFinished(const SyncReport& report) {
    if (mThread) {
        mThread->wait();
        delete mThread;
        mThread = nullptr;
    }
    mLast = report;
    mHaveReport = true;
    if (report.waiting > 0) mRetry.start();
    else mRetry.stop();
    emit changed();
    if (mAgain) {
        mAgain = false;
        syncNow();
    }
}

QString ResultUploader::statusText() const {
    if (mServer.isEmpty()) return {};
    // Short: the status bar has many fields (the tooltip says which server and why).
    if (!mHaveReport) return tr("Results: sending…");
    if (mLast.waiting == 0) return mLast.error.isEmpty() ? tr("Results: all sent") : tr("Results: server does not answer");
    if (!mLast.refused.empty() && mLast.error.isEmpty())
        return tr("Results: %1 waiting, %2 refused (see the tooltip)").arg(mLast.waiting).arg(mLast.refused.size());
    return mLast.waiting == 1 ? tr("Results: 1 waiting") : tr("Results: %1 waiting").arg(mLast.waiting);
}

}  // namespace palpate
