#include "app/gui/GuiApplication.h"

#include <QMessageBox>
#include <QMetaObject>
#include <QPointer>
#include <QThread>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <utility>

namespace palpate {

GuiApplication::GuiApplication(int& argc, char** argv) : QApplication(argc, argv) {}

bool GuiApplication::notify(QObject* receiver, QEvent* event) {
    try {
        return QApplication::notify(receiver, event);
    } catch (const std::exception& e) {
        const QString where = receiver ? QString::fromLatin1(receiver->metaObject()->className()) : QString();
        report(tr("%1 (while %2 handled an event; the window goes on)").arg(QString::fromLocal8Bit(e.what()), where));
    } catch (...) {
        report(tr("an unknown error (the window goes on)"));
    }
    return false;
}

void GuiApplication::report(const QString& message) {
    if (mErrorHandler) {
        mErrorHandler(message);
        return;
    }
    std::fprintf(stderr, "palpate: %s\n", qPrintable(message));
    if (mShowingError) return;
    mShowingError = true;
    // Not from inside the event that failed (its widget may be half-way through painting).
    QMetaObject::invokeMethod(
        this,
        [this, message] {
            QMessageBox::warning(activeWindow(), tr("Palpate"), message);
            mShowingError = false;
        },
        Qt::QueuedConnection);
}

namespace {

std::function<void()> gBeforeExit;
QtMessageHandler gPreviousHandler = nullptr;

void threadFailureHandler(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (gPreviousHandler) gPreviousHandler(type, context, message);
    else std::fprintf(stderr, "%s\n", qPrintable(message));
    // QThread::start's warning: "QThread::start: Thread creation error (reason)".
    if (!message.contains(QLatin1String("Thread creation error"))) return;
    static std::once_flag once;
    std::call_once(once, [&message] {
        const bool guiThread = qApp && QThread::currentThread() == qApp->thread();
        if (guiThread && gBeforeExit) gBeforeExit();
        std::fprintf(stderr,
                     "palpate: cannot start a thread (%s): the system refused it (memory or process limits, e.g. "
                     "ulimit -v); the GUI cannot run without it and stops\n",
                     qPrintable(message));
        std::fflush(stderr);
        std::_Exit(1);  // nothing may wait for the thread that was never started
    });
}

}  // namespace

void exitOnThreadCreationFailure(std::function<void()> beforeExit) {
    gBeforeExit = std::move(beforeExit);
    QtMessageHandler previous = qInstallMessageHandler(threadFailureHandler);
    if (previous != threadFailureHandler) gPreviousHandler = previous;
}

void ignoreFileSizeSignal() { std::signal(SIGXFSZ, SIG_IGN); }

}  // namespace palpate
