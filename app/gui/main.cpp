// palpate: the GUI. Exit codes: 0 success, 1 failure (bad mesh or device, screenshot not written),
// 2 bad usage.
#include "base/resources/ShippedResources.h"
#include "app/gui/FirstRun.h"
#include "results/SettingsFileGuard.h"
#include "app/gui/GuiApplication.h"
#include "app/gui/MainWindow.h"
#include "app/gui/ViewportBenchmark.h"
#include "device/open/DeviceUri.h"
#include "engine/record/RecordedToolDevice.h"
#include "widgets/RecorderPanel.h"

#include <QApplication>
#include <QDockWidget>
#include <QCommandLineParser>
#include <QIcon>
#include <QMessageBox>
#include <QPointer>
#include <QTabWidget>
#include <QScreen>
#include <QStatusBar>
#include <QTimer>

#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <new>
#include <optional>
#include <string>

namespace {

constexpr int kDefaultScreenshotTicks = 800;  // the scripted tool is pressing by then
constexpr int kScreenshotWidthPx = 1024;
constexpr int kScreenshotHeightPx = 768;
constexpr int kWindowWidthPx = 1280;
constexpr int kWindowHeightPx = 860;
/// The address space the window needs: it peaks at about 330 MiB offscreen and reserves more with
/// OpenGL. Below this, Qt's own code would meet failed allocations it does not survive (it
/// dereferences them), so the limit is refused up front (docs/reliability.md).
constexpr rlim_t kMinAddressSpaceBytes = rlim_t(512) << 20;

/// "" when the address-space limit (ulimit -v) leaves the window room, else the message.
std::string addressSpaceProblem() {
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur >= kMinAddressSpaceBytes)
        return {};
    return "palpate: not enough memory to run: the address-space limit (ulimit -v) is " +
           std::to_string(limit.rlim_cur >> 20) + " MiB, and the window needs at least " +
           std::to_string(kMinAddressSpaceBytes >> 20) + " MiB\n";
}

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

void printLoaded(const std::string& path, const palpate::TissueMesh& mesh) {
    const auto lo = mesh.boundsMinMm(), hi = mesh.boundsMaxMm();
    std::printf("mesh %s: %zu vertices, %zu triangles, bounds (%.1f %.1f %.1f)..(%.1f %.1f %.1f) mm\n", path.c_str(),
                mesh.vertexCount(), mesh.triangleCount(), lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    for (const auto& warning : mesh.report().warnings) std::printf("warning: %s\n", warning.c_str());
}

QString deviceHelp() {
    QStringList forms;
    for (const auto& scheme : palpate::listDeviceSchemes()) forms << QString::fromStdString(scheme.uri);
    return QStringLiteral("Haptic device: %1 (default %2 in the interactive window, where the mouse steers the "
                          "tool; %3 for screenshots).")
        .arg(forms.join(QStringLiteral(", ")), QLatin1String(palpate::HapticSession::kInteractiveDeviceUri),
             QLatin1String(palpate::HapticSession::kDefaultDeviceUri));
}

/// The command line of palpate, in the order --help lists it.
struct GuiCommandLine {
    QCommandLineOption mesh{QStringLiteral("mesh"), QStringLiteral("Mesh to open (OBJ, OFF, PLY, STL, OM)."),
                            QStringLiteral("FILE")};
    // No default here: it depends on the mode (runWindow).
    QCommandLineOption device{QStringLiteral("device"), deviceHelp(), QStringLiteral("URI")};
    QCommandLineOption software{QStringLiteral("software-render"),
                                QStringLiteral("Draw on the CPU instead of with OpenGL.")};
    // Where OpenGL is a CPU rasteriser (llvmpipe) the window draws on the CPU unless asked (ViewportFactory.h).
    QCommandLineOption openGl{QStringLiteral("opengl-render"),
                              QStringLiteral("Draw with OpenGL even where it is a CPU rasteriser (llvmpipe).")};
    QCommandLineOption screenshot{
        QStringLiteral("screenshot"),
        QStringLiteral("Run the loop with the device for --after-ms, save a PNG of the main window, exit. With "
                       "--ticks: run that many ticks stepped (no thread: deterministic) and save the viewport."),
        QStringLiteral("FILE")};
    QCommandLineOption afterMs{QStringLiteral("after-ms"),
                               QStringLiteral("Milliseconds the loop runs before --screenshot (default 1500)."),
                               QStringLiteral("N"), QStringLiteral("1500")};
    QCommandLineOption preset{QStringLiteral("preset"), QStringLiteral("Tissue preset (JSON) to load and apply."),
                              QStringLiteral("FILE")};
    QCommandLineOption ticks{
        QStringLiteral("ticks"),
        QStringLiteral("Haptic ticks (1 ms) before the screenshot (default %1).").arg(kDefaultScreenshotTicks),
        QStringLiteral("N"), QString::number(kDefaultScreenshotTicks)};
    QCommandLineOption noFifo{
        QStringLiteral("no-fifo"),
        QStringLiteral(
            "Run the haptic thread with normal scheduling, as a desktop user without real-time rights does.")};
    QCommandLineOption headless{QStringLiteral("headless"),
                                QStringLiteral("No window: load the mesh, print what was loaded, exit.")};
    // Hidden, for documentation and checks: `--grab-after-ms MS FILE` runs the interactive window
    // (with the haptic thread), grabs the whole window after MS milliseconds into FILE, and exits.
    QCommandLineOption grab{QStringLiteral("grab-after-ms"),
                            QStringLiteral("Run interactively, save the whole window to FILE after MS ms, exit."),
                            QStringLiteral("MS")};
    QCommandLineOption exercise{QStringLiteral("exercise"),
                                QStringLiteral("Start this exercise (JSON) at once: for --trainee, else as a preview."),
                                QStringLiteral("FILE")};
    QCommandLineOption trainee{QStringLiteral("trainee"),
                               QStringLiteral("The trainee --exercise runs for (added if new); the result is stored."),
                               QStringLiteral("NAME")};
    QCommandLineOption mode{QStringLiteral("mode"), QStringLiteral("instructor or trainee (the window's docks)."),
                            QStringLiteral("MODE")};
    QCommandLineOption wholeWindow{QStringLiteral("whole-window"),
                                   QStringLiteral("--screenshot saves the whole window, not only the viewport.")};
    // --benchmark-viewport [--mesh FILE] [--seconds S] [--software-render]: the window's frame rate
    // while a device keeps pressing (ViewportBenchmark.h).
    QCommandLineOption benchmark{
        QStringLiteral("benchmark-viewport"),
        QStringLiteral("Show --mesh (default: a generated 100 000-vertex sphere) in the window while sim:sine keeps "
                       "pressing, count the frames painted for --seconds, print fps= and frame times, exit.")};
    QCommandLineOption seconds{QStringLiteral("seconds"), QStringLiteral("Length of --benchmark-viewport (default 5)."),
                               QStringLiteral("S"), QStringLiteral("5")};
    QCommandLineOption heatMap{QStringLiteral("heat-map"),
                               QStringLiteral("With --benchmark-viewport: draw a coverage heat map over every vertex, "
                                              "as after a whole surface was examined.")};
    // Hidden, for screenshots of the Recorder dock: opens FILE in the dock and plays it at 1x.
    QCommandLineOption openRecording{QStringLiteral("open-recording"),
                                     QStringLiteral("Open a session recording in the Recorder dock and play it."),
                                     QStringLiteral("FILE")};
    // Hidden, for the user guide's pictures: shows the welcome page, the preferences or the guide
    // over the window; --screenshot FILE (timed) then saves that window instead of the main one.
    QCommandLineOption showDialog{QStringLiteral("show-dialog"),
                                  QStringLiteral("Show welcome, preferences or guide (for screenshots)."),
                                  QStringLiteral("NAME")};
    // Hidden, for screenshots of a dock tabbed behind another: brings the dock whose object name is
    // NAME + "Dock" to the front, and with NAME:TAB the tab of its tab widget whose page's object name
    // starts with TAB (charts:feel: the feel chart).
    QCommandLineOption showDock{QStringLiteral("show-dock"),
                                QStringLiteral("Bring a dock (and a tab in it) to the front: parameters, device, "
                                               "charts, charts:feel, ... (for screenshots)."),
                                QStringLiteral("NAME[:TAB]")};

    /// Adds every option to `parser`, the hidden ones hidden from --help.
    void addTo(QCommandLineParser& parser) {
        for (QCommandLineOption* hidden : {&grab, &openRecording, &showDialog, &showDock})
            hidden->setFlags(QCommandLineOption::HiddenFromHelp);
        parser.setApplicationDescription(QStringLiteral("Palpate: haptic soft-tissue deformation"));
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addOption(noFifo);
        parser.addOptions({mesh, device, preset, software, openGl, screenshot, afterMs, ticks, headless, grab});
        parser.addOptions({exercise, trainee, mode, wholeWindow});
        parser.addOptions({benchmark, seconds, heatMap});
        parser.addOption(openRecording);
        parser.addOption(showDialog);
        parser.addOption(showDock);
    }
};

/// What this run does, decided from the command line.
struct RunPlan {
    int ticks = 0;            ///< --ticks: the stepped screenshot's haptic ticks
    bool screenshot = false;  ///< --screenshot with --ticks: stepped, the viewport (or --whole-window)
    bool timedShot = false;   ///< --screenshot without --ticks: timed, threaded, the whole window
    bool grab = false;        ///< --grab-after-ms MS FILE
    int grabAfterMs = 0;      ///< how long the timed shot or the grab waits
    QString grabFile;
    bool headless = false;  ///< no window: print the mesh and exit
    bool interactive = false;
};

/// The run the options ask for; 2 (bad usage, said on stderr) in `exitCode` when they do not fit.
std::optional<RunPlan> planRun(const QCommandLineParser& parser, const GuiCommandLine& options, bool noDisplay,
                               int& exitCode) {
    exitCode = 2;
    RunPlan plan;
    bool ticksOk = false;
    plan.ticks = parser.value(options.ticks).toInt(&ticksOk);
    if (!ticksOk || plan.ticks < 0) {
        std::fprintf(stderr, "palpate: --ticks needs a whole number >= 0, not '%s'\n",
                     qPrintable(parser.value(options.ticks)));
        return std::nullopt;
    }
    plan.grab = parser.isSet(options.grab);
    if (plan.grab) {
        bool msOk = false;
        plan.grabAfterMs = parser.value(options.grab).toInt(&msOk);
        const QStringList rest = parser.positionalArguments();
        if (!msOk || plan.grabAfterMs < 0 || rest.size() != 1) {
            std::fprintf(stderr, "palpate: usage: --grab-after-ms MS FILE (MS a whole number >= 0)\n");
            return std::nullopt;
        }
        plan.grabFile = rest.front();
    }
    // --screenshot FILE: timed, threaded, the whole window (as --grab-after-ms), unless --ticks asks
    // for the deterministic stepped viewport image.
    plan.screenshot = parser.isSet(options.screenshot) && parser.isSet(options.ticks);
    if (parser.isSet(options.screenshot) && !plan.screenshot) {
        bool msOk = false;
        plan.grabAfterMs = parser.value(options.afterMs).toInt(&msOk);
        if (!msOk || plan.grabAfterMs < 0) {
            std::fprintf(stderr, "palpate: --after-ms needs a whole number >= 0, not '%s'\n",
                         qPrintable(parser.value(options.afterMs)));
            return std::nullopt;
        }
        plan.grabFile = parser.value(options.screenshot);
    }
    plan.timedShot = parser.isSet(options.screenshot) && !plan.screenshot;
    // Without a display and without a task there is nothing to show: report the scene and stop
    // rather than run an invisible window forever.
    plan.headless = parser.isSet(options.headless) || (noDisplay && !plan.screenshot && !plan.grab && !plan.timedShot);
    plan.interactive = !plan.headless && !plan.screenshot && !plan.grab && !plan.timedShot;
    exitCode = 0;
    return plan;
}

/// Prints the error (and shows it, in an interactive run); the exit code 1.
int failed(const QString& error, bool interactive) {
    std::fprintf(stderr, "palpate: %s\n", qPrintable(error));
    if (interactive) QMessageBox::critical(nullptr, QStringLiteral("Palpate"), error);
    return 1;
}

/// --headless: loads the mesh, prints what was loaded. The exit code.
int printMesh(const QString& meshPath) {
    std::string error;
    const auto mesh = palpate::HapticSession::loadTissueMesh(meshPath.toStdString(), error);
    if (!mesh) {
        std::fprintf(stderr, "palpate: %s\n", error.c_str());
        return 1;
    }
    printLoaded(meshPath.toStdString(), *mesh);
    return 0;
}

/// --preset, --mode and --exercise, once the session runs. "" or the error (naming the file).
QString applyStartOptions(palpate::MainWindow& window, const QCommandLineParser& parser,
                          const GuiCommandLine& options) {
    if (parser.isSet(options.preset))
        if (const QString error = window.loadPresetFile(parser.value(options.preset)); !error.isEmpty()) return error;
    if (parser.isSet(options.mode)) {
        const QString modeName = parser.value(options.mode);
        if (modeName != QLatin1String("instructor") && modeName != QLatin1String("trainee"))
            return QStringLiteral("--mode: '%1' is neither instructor nor trainee").arg(modeName);
        window.setMode(modeName == QLatin1String("trainee") ? palpate::MainWindow::Mode::Trainee
                                                            : palpate::MainWindow::Mode::Instructor);
    }
    if (parser.isSet(options.exercise))
        if (const QString error = window.runExercise(parser.value(options.exercise), parser.value(options.trainee));
            !error.isEmpty())
            return error;  // naming the exercise or the results database
    return {};
}

/// --screenshot with --ticks: runs the ticks stepped, saves the viewport (or the whole window) to
/// `file` from inside the event loop. The exit code.
int saveSteppedScreenshot(palpate::MainWindow& window, int ticks, const QString& file, bool wholeWindow) {
    window.resize(kScreenshotWidthPx, kScreenshotHeightPx);
    window.advanceTicks(ticks);
    window.show();
    int exitCode = 1;
    // Grab once the window is shown and laid out, from inside the event loop.
    QTimer::singleShot(200, &window, [&] {
        const QImage image = wholeWindow ? window.grab().toImage() : window.viewport()->grabImage();
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

/// --show-dock NAME[:TAB]: brings the dock (and the tab) to the front. False (said on stderr) when
/// there is no such dock or tab.
bool showDock(palpate::MainWindow& window, const QString& name) {
    const QStringList parts = name.split(QLatin1Char(':'));
    auto* dock = window.findChild<QDockWidget*>(parts.front() + QStringLiteral("Dock"));
    if (!dock) {
        std::fprintf(stderr, "palpate: --show-dock: no dock named '%s'\n", qPrintable(parts.front()));
        return false;
    }
    dock->show();
    dock->raise();
    if (parts.size() > 1) {
        auto* tabs = dock->findChild<QTabWidget*>();
        int page = -1;
        for (int i = 0; tabs && i < tabs->count(); ++i)
            if (tabs->widget(i)->objectName().startsWith(parts[1])) page = i;
        if (page < 0) {
            std::fprintf(stderr, "palpate: --show-dock: the %s dock has no tab '%s'\n", qPrintable(parts.front()),
                         qPrintable(parts[1]));
            return false;
        }
        tabs->setCurrentIndex(page);
    }
    return true;
}

/// --grab-after-ms or a timed --screenshot: after `afterMs` saves the whole window (or `shownDialog`)
/// to `file` and closes. The exit code.
int saveTimedGrab(palpate::MainWindow& window, const QPointer<QWidget>& shownDialog, int afterMs, const QString& file) {
    int exitCode = 1;
    QTimer::singleShot(afterMs, &window, [&] {
        // The whole window (menus, viewport, status bar), or the dialog --show-dialog opened.
        const QImage image = shownDialog ? shownDialog->grab().toImage() : window.grab().toImage();
        if (image.isNull() || !image.save(file, "PNG")) {
            std::fprintf(stderr, "palpate: the window could not be saved to %s\n", qPrintable(file));
        } else {
            std::printf("palpate: wrote %s (%dx%d) after %d ms; %s\n", qPrintable(file), image.width(), image.height(),
                        afterMs, qPrintable(window.statusText()));
            exitCode = 0;
        }
        window.close();  // stops the haptic thread
        QApplication::exit(exitCode);
    });
    QApplication::exec();
    return exitCode;
}

/// The window shown: the device problem or the welcome page, --show-dock, --show-dialog,
/// --open-recording, then the timed shot or the event loop. The exit code.
int runShownWindow(palpate::MainWindow& window, const QCommandLineParser& parser, const GuiCommandLine& options,
                   const RunPlan& plan, const QString& deviceProblem) {
    // The usual size, but never more than the screen offers (a 1280x800 laptop).
    QSize size(kWindowWidthPx, kWindowHeightPx);
    if (const QScreen* screen = window.screen()) size = size.boundedTo(screen->availableGeometry().size());
    window.resize(size);
    window.show();
    if (plan.interactive && !deviceProblem.isEmpty()) {
        // Once the window is up, so that Preferences (behind this box) can be reached at once.
        QTimer::singleShot(0, &window, [&window, deviceProblem] {
            QMessageBox::warning(&window, palpate::MainWindow::tr("Device not opened"), deviceProblem);
        });
    } else if (plan.interactive) {
        palpate::maybeShowWelcome(window, parser.optionNames());  // not over --exercise etc.
    }
    if (parser.isSet(options.showDock) && !showDock(window, parser.value(options.showDock))) return 2;
    const QPointer<QWidget> shownDialog = parser.isSet(options.showDialog)
                                              ? palpate::showFirstRunDialog(window, parser.value(options.showDialog))
                                              : nullptr;
    if (parser.isSet(options.openRecording)) {
        palpate::RecorderPanel* panel = window.recorderPanel();
        QObject::connect(panel, &palpate::RecorderPanel::playbackStarted, panel, [panel] { panel->setPlaying(true); });
        window.openRecording(parser.value(options.openRecording));
    }
    if (plan.grab || plan.timedShot) return saveTimedGrab(window, shownDialog, plan.grabAfterMs, plan.grabFile);
    return QApplication::exec();
}

/// The window on `meshPath` with the device the options ask for, run as `plan` says. The exit code.
int runWindow(const QCommandLineParser& parser, const GuiCommandLine& options, const RunPlan& plan,
              palpate::RendererChoice renderer, const QString& meshPath) {
    // Without --device: the interactive window has no hardware to find yet, so the mouse steers the
    // tool; screenshots, grabs and scripted runs keep the scripted stroke (deterministic pictures).
    const QString fallbackUri = QLatin1String(plan.interactive ? palpate::HapticSession::kInteractiveDeviceUri
                                                               : palpate::HapticSession::kDefaultDeviceUri);
    QString deviceUri = parser.isSet(options.device) ? parser.value(options.device) : fallbackUri;
    if (!parser.isSet(options.device) && plan.interactive && !palpate::preferredDeviceUri().isEmpty())
        deviceUri = palpate::preferredDeviceUri();  // Preferences: the device at start

    // Screenshots step the loop on this thread (deterministic); everything else runs its thread.
    const auto mode = plan.screenshot ? palpate::LoopMode::Stepped : palpate::LoopMode::Threaded;
    palpate::HapticLoopDef loopDef;
    loopDef.trySchedFifo = !parser.isSet(options.noFifo);
    palpate::MainWindow window(renderer, mode, loopDef);
    palpate::applyPreferences(window);  // data folder, haptic rate; --preset below still wins
    if (const QString problem = palpate::settingsFileProblem(); !problem.isEmpty())
        window.statusBar()->showMessage(problem, 60000);
    QString deviceProblem;
    if (const QString error = window.startSession(meshPath, deviceUri, fallbackUri, deviceProblem); !error.isEmpty())
        return failed(error, plan.interactive);
    if (!deviceProblem.isEmpty()) {
        std::fprintf(stderr, "palpate: %s\n", qPrintable(deviceProblem));
        deviceUri = QString::fromStdString(window.session().deviceUri());
    }
    if (const QString error = applyStartOptions(window, parser, options); !error.isEmpty())
        return failed(error, plan.interactive);
    std::printf("palpate: %s renderer (%s), device %s, haptic loop %s\n",
                qPrintable(palpate::rendererName(window.viewport()->kind())), qPrintable(window.rendererReason()),
                qPrintable(deviceUri), mode == palpate::LoopMode::Stepped ? "stepped" : "threaded");
    std::fflush(stdout);  // before the event loop: a session may end by signal

    if (plan.screenshot)
        return saveSteppedScreenshot(window, plan.ticks, parser.value(options.screenshot),
                                     parser.isSet(options.wholeWindow));
    return runShownWindow(window, parser, options, plan, deviceProblem);
}

}  // namespace

int runGui(int argc, char** argv);

int main(int argc, char** argv) {
    if (const std::string problem = addressSpaceProblem(); !problem.empty()) {
        std::fputs(problem.c_str(), stderr);
        return 1;
    }
    palpate::ignoreFileSizeSignal();  // a file-size limit: the recorder reports the write error
    palpate::exitOnThreadCreationFailure([] {
        for (QWidget* widget : QApplication::topLevelWidgets())
            if (auto* window = qobject_cast<palpate::MainWindow*>(widget)) window->session().stop();
    });
    try {
        return runGui(argc, argv);
    } catch (const std::bad_alloc&) {
        // Outside the event loop (start-up, shut-down): GuiApplication::notify catches the rest.
        std::fprintf(stderr, "palpate: not enough memory to run (is a memory limit set, e.g. ulimit -v?)\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "palpate: %s\n", e.what());
        return 1;
    }
}

int runGui(int argc, char** argv) {
    // Must happen before QApplication exists: the platform plugin is chosen in its constructor.
    const bool noDisplay = !displayAvailable();
    const bool headlessFlag = hasArgument(argc, argv, "--headless");
    if (noDisplay || (headlessFlag && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")))
        qputenv("QT_QPA_PLATFORM", "offscreen");

    palpate::GuiApplication app(argc, argv);
    palpate::setApplicationNames();  // before the first QSettings (FirstRun.h)
    if (const QString problem = palpate::guardSettingsFile(); !problem.isEmpty())
        std::fprintf(stderr, "palpate: %s\n", qPrintable(problem));
    palpate::migrateOldSettings();
    QApplication::setApplicationVersion(QStringLiteral(PALPATE_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/palpate-256.png")));
    QGuiApplication::setDesktopFileName(QStringLiteral("org.palpate.Palpate"));  // packaging/*.desktop
    palpate::installTranslator(app);  // QSettings "language", else the system locale (FirstRun.h)

    QCommandLineParser parser;
    GuiCommandLine options;
    options.addTo(parser);
    parser.process(app);  // exits with 0 on --help/--version and with 1 on unknown options
    const auto renderer = parser.isSet(options.software) ? palpate::RendererChoice::Software
                          : parser.isSet(options.openGl) ? palpate::RendererChoice::OpenGL
                                                         : palpate::RendererChoice::Auto;
    if (parser.isSet(options.benchmark))
        return palpate::runViewportBenchmark(parser.value(options.seconds), parser.value(options.mesh), renderer,
                                             parser.isSet(options.heatMap));

    int usageExit = 0;
    const std::optional<RunPlan> plan = planRun(parser, options, noDisplay, usageExit);
    if (!plan) return usageExit;
    if (noDisplay)
        std::printf(
            "palpate: no display (DISPLAY, WAYLAND_DISPLAY and QT_QPA_PLATFORM unset): running headless "
            "(QT_QPA_PLATFORM=offscreen) with the software renderer\n");

    // A device that cannot be opened does not stop the window (MainWindow::startSession); the
    // replay: scheme is registered first, so that replay:FILE is checked like every other URI.
    palpate::registerReplayDeviceScheme();

    QString meshPath = parser.value(options.mesh);
    if (meshPath.isEmpty()) {
        meshPath = QString::fromStdString(palpate::findResource(palpate::kDefaultMesh));
        if (meshPath.isEmpty())
            return failed(QStringLiteral("the default mesh %1 was not found (set PALPATE_RESOURCES)")
                              .arg(QLatin1String(palpate::kDefaultMesh)),
                          plan->interactive);
    }
    if (plan->headless) return printMesh(meshPath);
    return runWindow(parser, options, *plan, renderer, meshPath);
}
