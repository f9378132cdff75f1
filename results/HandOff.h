#pragma once
// Hands a worker thread's result to the thread of a QObject (the GUI's), as a queued
// QMetaObject::invokeMethod would, in a way ThreadSanitizer can follow: the function is stored
// before handOffRelease() and run after handOffAcquire() (base/concurrency/HandOff.h), so the
// sanitizer sees what Qt's event-queue lock really orders, and still reports a worker that touches
// the data after handing it off (docs/reliability.md, "Sanitizers"). Like the queued call, nothing
// runs when the receiver is gone by then. Header-only, Qt Core: the lowest Qt layer (results/) so
// that the results uploader, the widgets and the window all use it.

#include "base/concurrency/HandOff.h"

#include <QCoreApplication>
#include <QEvent>
#include <QObject>
#include <QPointer>

#include <functional>

namespace palpate {

namespace detail {

inline QEvent::Type handOffEventType() {
    static const QEvent::Type type = QEvent::Type(QEvent::registerEventType());
    return type;
}

/// Made in the worker, moved to the receiver's thread, and gone once it has run.
class HandOffTarget : public QObject {
public:
    HandOffTarget(QObject* receiver, std::function<void()> run) : mReceiver(receiver), mRun(std::move(run)) {}

protected:
    bool event(QEvent* e) override {
        handOffAcquire();  // before the event itself is read: the worker made it
        if (e->type() != handOffEventType()) return QObject::event(e);
        if (mReceiver) mRun();
        mRun = nullptr;
        deleteLater();
        return true;
    }

private:
    QPointer<QObject> mReceiver;
    std::function<void()> mRun;
};

}  // namespace detail

/// Runs `run` in `receiver`'s thread, from its event loop, unless `receiver` is deleted first.
inline void handOffTo(QObject* receiver, std::function<void()> run) {
    auto* target = new detail::HandOffTarget(receiver, std::move(run));
    target->moveToThread(receiver->thread());
    // A receiver deleted before the delivery takes the undelivered hand-off with it (its event too).
    QObject::connect(receiver, &QObject::destroyed, target, [target] { delete target; });
    auto* event = new QEvent(detail::handOffEventType());
    handOffRelease();  // after everything the receiver will read, the event included
    QCoreApplication::postEvent(target, event);
}

}  // namespace palpate
