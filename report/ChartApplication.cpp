#include "report/ChartApplication.h"

#include <cstdio>

namespace palpate {

ChartApplication::ChartApplication() {
    if (QCoreApplication::instance()) {
        if (!qobject_cast<QApplication*>(QCoreApplication::instance()))
            mProblem = "the chart needs a QApplication (widgets); this process runs a non-widget Qt application";
        return;
    }
    sPrevious = qInstallMessageHandler(&ChartApplication::quietHandler);
    mQuiet = true;
    static int argc = 1;
    static char name[] = "palpate-cli";
    static char platformFlag[] = "-platform";
    static char offscreen[] = "offscreen";
    static char* argv[] = {name, platformFlag, offscreen, nullptr};
    argc = qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") ? 3 : 1;
    mOwn = std::make_unique<QApplication>(argc, argv);
}

ChartApplication::~ChartApplication() {
    mOwn.reset();  // before the handler goes: the application's last notices are dropped too
    if (mQuiet) qInstallMessageHandler(sPrevious);
}

void ChartApplication::quietHandler(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    // No XDG_RUNTIME_DIR, no window size hints: the offscreen platform's, nothing about the PNG.
    if (type != QtCriticalMsg && type != QtFatalMsg &&
        (message.contains(QLatin1String("XDG_RUNTIME_DIR")) || message.contains(QLatin1String("propagateSizeHints"))))
        return;
    if (sPrevious) sPrevious(type, context, message);
    else std::fprintf(stderr, "%s\n", qPrintable(message));
}

}  // namespace palpate
