// palpate: the GUI. Exit codes: 0 success, 1 failure (bad mesh, screenshot not written), 2 bad usage.
#include "app/cli/DefaultScene.h"
#include "app/gui/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QTimer>

#include <cstdio>
#include <cstring>

namespace {

constexpr int kDefaultScreenshotTicks = 800;  // the scripted tool is pressing by then
constexpr int kScreenshotWidthPx = 1024;
constexpr int kScreenshotHeightPx = 768;

/// Qt aborts when the default platform (xcb, wayland) has no display; offscreen always works.
bool displayAvailable() {
    return !qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
           !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
}

bool hasArgument(int argc, char** argv, const char* name) {
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], name) == 0) return true;
    return false;
}

void printLoaded(const palpate::SceneSimulation& simulation) {
    const auto& mesh = simulation.mesh();
    const auto lo = mesh.boundsMinMm(), hi = mesh.boundsMaxMm();
    std::printf("mesh %s: %zu vertices, %zu triangles, bounds (%.1f %.1f %.1f)..(%.1f %.1f %.1f) mm\n",
                simulation.path().c_str(), mesh.vertexCount(), mesh.triangleCount(), lo.x, lo.y, lo.z, hi.x, hi.y,
                hi.z);
    for (const auto& warning : mesh.report().warnings) std::printf("warning: %s\n", warning.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    // Must happen before QApplication exists: the platform plugin is chosen in its constructor.
    const bool noDisplay = !displayAvailable();
    const bool headlessFlag = hasArgument(argc, argv, "--headless");
    if (noDisplay || (headlessFlag && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")))
        qputenv("QT_QPA_PLATFORM", "offscreen");

    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("palpate"));
    QApplication::setApplicationVersion(QStringLiteral(PALPATE_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Palpate: haptic soft-tissue deformation"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption meshOption(QStringLiteral("mesh"), QStringLiteral("Mesh to open (OBJ, OFF, PLY, STL, OM)."),
                                        QStringLiteral("FILE"));
    const QCommandLineOption softwareOption(QStringLiteral("software-render"),
                                            QStringLiteral("Draw with QPainter instead of OpenGL."));
    const QCommandLineOption screenshotOption(QStringLiteral("screenshot"),
                                              QStringLiteral("Render the scene after --ticks ticks, save a PNG, exit."),
                                              QStringLiteral("FILE"));
    const QCommandLineOption ticksOption(QStringLiteral("ticks"),
                                         QStringLiteral("Simulation ticks (1 ms) before the screenshot (default %1).")
                                             .arg(kDefaultScreenshotTicks),
                                         QStringLiteral("N"), QString::number(kDefaultScreenshotTicks));
    const QCommandLineOption headlessOption(QStringLiteral("headless"),
                                            QStringLiteral("No window: load the mesh, print what was loaded, exit."));
    parser.addOptions({meshOption, softwareOption, screenshotOption, ticksOption, headlessOption});
    parser.process(app);  // exits with 0 on --help/--version and with 1 on unknown options

    bool ticksOk = false;
    const int ticks = parser.value(ticksOption).toInt(&ticksOk);
    if (!ticksOk || ticks < 0) {
        std::fprintf(stderr, "palpate: --ticks needs a whole number >= 0, not '%s'\n", qPrintable(parser.value(ticksOption)));
        return 2;
    }
    const bool screenshot = parser.isSet(screenshotOption);
    // Without a display and without a task there is nothing to show: report the scene and stop
    // rather than run an invisible window forever.
    const bool headless = parser.isSet(headlessOption) || (noDisplay && !screenshot);
    if (noDisplay)
        std::printf("palpate: no display (DISPLAY, WAYLAND_DISPLAY and QT_QPA_PLATFORM unset): running headless "
                    "(QT_QPA_PLATFORM=offscreen) with the software renderer\n");

    QString meshPath = parser.value(meshOption);
    if (meshPath.isEmpty()) {
        meshPath = QString::fromStdString(palpate::cli::findResource(palpate::cli::kDefaultMesh));
        if (meshPath.isEmpty()) {
            const QString error = QStringLiteral("the default mesh %1 was not found (set PALPATE_RESOURCES)")
                                      .arg(QLatin1String(palpate::cli::kDefaultMesh));
            std::fprintf(stderr, "palpate: %s\n", qPrintable(error));
            if (!headless && !screenshot) QMessageBox::critical(nullptr, QStringLiteral("Palpate"), error);
            return 1;
        }
    }

    if (headless) {
        const auto outcome = palpate::SceneSimulation::load(meshPath.toStdString());
        if (!outcome.simulation) {
            std::fprintf(stderr, "palpate: %s\n", outcome.error.c_str());
            return 1;
        }
        printLoaded(*outcome.simulation);
        return 0;
    }

    const auto renderer = parser.isSet(softwareOption) ? palpate::RendererChoice::Software : palpate::RendererChoice::Auto;
    palpate::MainWindow window(renderer);
    if (const QString error = window.loadMesh(meshPath); !error.isEmpty()) {
        std::fprintf(stderr, "palpate: %s\n", qPrintable(error));
        return 1;
    }
    std::printf("palpate: %s renderer (%s)\n", qPrintable(palpate::rendererName(window.viewport()->kind())),
                qPrintable(window.rendererReason()));
    std::fflush(stdout);  // before the event loop: a session may end by signal

    if (screenshot) {
        window.resize(kScreenshotWidthPx, kScreenshotHeightPx);
        window.advanceTicks(ticks);
        window.show();
        const QString file = parser.value(screenshotOption);
        int exitCode = 1;
        // Grab once the window is shown and laid out, from inside the event loop.
        QTimer::singleShot(200, &window, [&] {
            const QImage image = window.viewport()->grabImage();
            if (image.isNull() || !image.save(file, "PNG")) {
                std::fprintf(stderr, "palpate: the screenshot could not be written to %s\n", qPrintable(file));
            } else {
                std::printf("palpate: wrote %s (%dx%d) after %d ticks; %s\n", qPrintable(file), image.width(),
                            image.height(), ticks, qPrintable(window.statusText()));
                exitCode = 0;
            }
            QApplication::exit(exitCode);
        });
        QApplication::exec();
        return exitCode;
    }

    window.resize(1280, 860);
    window.show();
    window.setPlaying(true);
    return QApplication::exec();
}
