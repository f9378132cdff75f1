#pragma once
// The GUI's QApplication, and what the GUI process does when the system refuses it something.
// A file error must never abort the window (docs/reliability.md): an exception that escapes a slot or
// an event handler is caught where Qt delivers events (notify), reported and the window goes on.
// A thread that cannot be created is another matter: Qt then waits for it forever (a worker of its
// image thread pool, the device opener), so the process says so and exits instead of hanging.

#include <QApplication>
#include <QString>

#include <functional>

namespace palpate {

class GuiApplication final : public QApplication {
    Q_OBJECT
public:
    GuiApplication(int& argc, char** argv);

    /// What an escaped exception is shown with. The default prints it to stderr and shows it in a
    /// message box once the event in which it was thrown has returned; tests capture it instead.
    using ErrorHandler = std::function<void(const QString& message)>;
    void setErrorHandler(ErrorHandler handler) { mErrorHandler = std::move(handler); }

    /// Delivers the event; an exception thrown while handling it is reported (naming the object it
    /// was sent to) and swallowed, so that the event loop runs on.
    bool notify(QObject* receiver, QEvent* event) override;

private:
    void report(const QString& message);
    ErrorHandler mErrorHandler;
    bool mShowingError = false;  ///< one message box at a time: the next ones go to stderr only
};

/// Qt's "QThread::start: Thread creation error" (no memory for a stack, a process limit) ends the
/// process with exit code 1 and a message on stderr, after `beforeExit` (on the GUI thread only: it
/// stops the haptic thread, so that a device is left without force). Qt would otherwise wait for
/// the thread's work forever.
void exitOnThreadCreationFailure(std::function<void()> beforeExit = {});

/// A file-size limit (ulimit -f) becomes a write error (EFBIG) that the writer reports with the
/// file's path, instead of SIGXFSZ killing the process without a word.
void ignoreFileSizeSignal();

}  // namespace palpate
