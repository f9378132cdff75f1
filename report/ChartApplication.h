#pragma once
// What a chart image needs to be drawn in a process that may have no QApplication (palpate-cli
// sweep --png, bench feel --png): the process's own QApplication, or one made for the drawing on the
// offscreen platform (unless QT_QPA_PLATFORM chooses one), so that a PNG is the same with or without
// a display and never opens a connection to one; while it lives, the offscreen platform's notices
// that say nothing about the image are dropped.

#include <QApplication>
#include <QtGlobal>

#include <memory>
#include <string>

namespace palpate {

class ChartApplication {
public:
    ChartApplication();
    ~ChartApplication();
    ChartApplication(const ChartApplication&) = delete;
    ChartApplication& operator=(const ChartApplication&) = delete;

    /// "" when widgets can be drawn; else why not (a non-widget Qt application runs).
    const std::string& problem() const { return mProblem; }

private:
    static void quietHandler(QtMsgType type, const QMessageLogContext& context, const QString& message);
    static inline QtMessageHandler sPrevious = nullptr;

    bool mQuiet = false;
    std::unique_ptr<QApplication> mOwn;
    std::string mProblem;
};

}  // namespace palpate
