#pragma once
// The part of QProcess these tests use, on the suite's own fork-and-exec runner
// (tests/support/ChildProcess.h). Qt starts a child with clone(CLONE_VM | CLONE_VFORK), which
// ThreadSanitizer does not see as a fork: the child ran in the test's own memory, and the
// sanitizer then refused the test's next thread ("starting new threads after multi-threaded
// fork") and reported races between locked accesses. A child-process modifier does not make Qt 6.4
// fork; this does.

#include "tests/support/ChildProcess.h"

#include <QByteArray>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>
#include <QString>
#include <QStringList>

#include <optional>

namespace palpate::test {

class ForkedProcess {
public:
    void setProcessEnvironment(const QProcessEnvironment& env) { mEnv = env; }
    void setProcessChannelMode(QProcess::ProcessChannelMode mode) { mMerged = mode == QProcess::MergedChannels; }

    /// Remembers what to run: the child starts in waitForFinished, which knows how long to wait
    /// (these tests start a program and wait for it at once).
    void start(const QString& program, const QStringList& arguments) {
        mSpec = ChildSpec{};
        const QString path = program.contains(QLatin1Char('/')) ? program : QStandardPaths::findExecutable(program);
        mSpec.argv.push_back(path.toStdString());
        for (const QString& a : arguments) mSpec.argv.push_back(a.toStdString());
        if (mEnv)
            for (const QString& key : mEnv->keys()) mSpec.env[key.toStdString()] = mEnv->value(key).toStdString();
        mResult.reset();
    }
    /// Runs it for up to `ms` (then kills its process group); whether it exited in that time.
    bool waitForFinished(int ms) {
        mSpec.timeoutS = double(ms) / 1000.0;
        mResult = runChild(mSpec);
        return mResult->exited && !mResult->timedOut;
    }
    void kill() {}  // a child past its wait was killed already
    int exitCode() const { return mResult && mResult->exited ? mResult->exitCode : -1; }
    QByteArray readAllStandardOutput() const {
        if (!mResult) return {};
        return QByteArray::fromStdString(mMerged ? mResult->out + mResult->err : mResult->out);
    }
    QByteArray readAllStandardError() const {
        return mResult && !mMerged ? QByteArray::fromStdString(mResult->err) : QByteArray();
    }
    QByteArray readAll() const { return readAllStandardOutput(); }

private:
    ChildSpec mSpec;
    std::optional<QProcessEnvironment> mEnv;
    bool mMerged = false;
    std::optional<ChildResult> mResult;
};

}  // namespace palpate::test
