// The viewport and the main window under QT_QPA_PLATFORM=offscreen: the factory falls back to the
// software renderer, which draws the mesh and the touched-vertex highlight; the window runs the
// haptic loop stepped (deterministic) or on its thread (interactive), observes its snapshots, and
// reports contact, force and the loop's health; bad meshes and devices give errors naming them.
#include "base/resources/ShippedResources.h"
#include "app/gui/HapticSession.h"
#include "app/gui/MainWindow.h"
#include "app/gui/SnapshotObserver.h"
#include "app/gui/ViewportBenchmark.h"
#include "widgets/SceneOverlay.h"
#include "widgets/SceneStyle.h"
#include "widgets/SoftwareViewport.h"
#include "widgets/ViewportFactory.h"

#include <QAction>
#include <QApplication>
#include <QStandardPaths>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <memory>

using namespace palpate;

namespace {

constexpr int kTicksIntoContact = 800;  // the scripted stroke is pressing by then

QString defaultMeshPath() { return QString::fromStdString(findResource(kDefaultMesh)); }

bool near(QRgb pixel, const QColor& colour, int tolerance) {
    return std::abs(qRed(pixel) - colour.red()) <= tolerance && std::abs(qGreen(pixel) - colour.green()) <= tolerance &&
           std::abs(qBlue(pixel) - colour.blue()) <= tolerance;
}

int countNear(const QImage& image, const QRect& region, const QColor& colour, int tolerance) {
    int count = 0;
    for (int y = region.top(); y <= region.bottom(); ++y)
        for (int x = region.left(); x <= region.right(); ++x)
            if (near(image.pixel(x, y), colour, tolerance)) ++count;
    return count;
}

/// Processes events until `done` or `timeoutMs` passed; returns done().
bool waitUntil(const std::function<bool()>& done, int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    while (!done() && clock.elapsed() < timeoutMs) QTest::qWait(10);
    return done();
}

/// The number in a status field such as "haptic 998 Hz"; -1 if there is none.
double statusNumber(const MainWindow& window, const char* objectName) {
    const auto* label = window.findChild<QLabel*>(QLatin1String(objectName));
    if (!label) return -1.0;
    const auto match = QRegularExpression(QStringLiteral("(\\d+(\\.\\d+)?)")).match(label->text());
    return match.hasMatch() ? match.captured(1).toDouble() : -1.0;
}

QAction* findAction(QWidget& window, const QString& text) {
    for (QAction* action : window.findChildren<QAction*>())
        if (action->text().remove(QLatin1Char('&')) == text) return action;
    return nullptr;
}

}  // namespace

TEST(ViewportFactory, PicksSoftwareUnderOffscreen) {
    ASSERT_EQ(QGuiApplication::platformName(), QStringLiteral("offscreen"));
    QString whyNot;
    EXPECT_FALSE(openGl33Available(&whyNot));
    EXPECT_TRUE(whyNot.contains(QStringLiteral("offscreen"))) << whyNot.toStdString();
    for (const auto choice : {RendererChoice::Auto, RendererChoice::Software}) {
        std::unique_ptr<QWidget> parent(new QWidget);
        Viewport* viewport = createViewport(choice, parent.get());
        ASSERT_NE(viewport, nullptr);
        EXPECT_EQ(viewport->kind(), RendererKind::Software);
        EXPECT_NE(dynamic_cast<SoftwareViewport*>(viewport), nullptr);
        EXPECT_EQ(viewport->widget()->parent(), parent.get());
    }
}

TEST(SoftwareViewport, DrawsTheMeshAndTheTouchedVertexInContact) {
    const QString path = defaultMeshPath();
    ASSERT_FALSE(path.isEmpty()) << "resources/" << kDefaultMesh << " not found";
    HapticSession session(LoopMode::Stepped);
    ASSERT_EQ(session.loadMesh(path.toStdString()), "");
    ASSERT_TRUE(session.drawnMesh());

    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(*session.drawnMesh());
    const QImage atRest = viewport.grabImage();
    ASSERT_EQ(atRest.size(), QSize(640, 480));

    // The mesh is framed: the centre of the picture is tissue, not background.
    const QRect centre(atRest.width() * 2 / 5, atRest.height() * 2 / 5, atRest.width() / 5, atRest.height() / 5);
    const QColor background = toQColor(style::kBackground);
    EXPECT_LT(countNear(atRest, centre, background, 2), centre.width() * centre.height() / 20);
    // The corners are background: the mesh is not blown up past the frame.
    EXPECT_TRUE(near(atRest.pixel(2, 2), background, 2));

    const QColor highlight = toQColor(style::kTouchedHighlight);
    const QRect all = atRest.rect();
    EXPECT_EQ(countNear(atRest, all, highlight, 10), 0) << "highlight drawn before any contact";

    session.step(kTicksIntoContact);
    ASSERT_EQ(session.observe(), HapticSession::Observation::Updated);
    ASSERT_TRUE(session.observed().contact) << "the scripted stroke should be pressing after " << kTicksIntoContact;
    EXPECT_GT(session.observed().displacedCount, 0u);
    viewport.setSnapshot(session.view());
    const QImage pressed = viewport.grabImage();
    EXPECT_GT(countNear(pressed, all, highlight, 10), 20) << "no touched-vertex highlight in contact";
    // The pressed tissue is drawn deformed: the picture changed beyond the markers.
    EXPECT_NE(pressed, atRest);
}

TEST(SnapshotObserver, TouchesOnlyWhatChanged) {
    const std::vector<glm::vec3> rest = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
    SnapshotObserver observer;
    observer.setRestPositions(rest);
    auto snapshot = std::make_unique<HapticSnapshot>();  // ~80 kB: not on the stack
    snapshot->displacedCount = 2;
    snapshot->displacedIds[0] = 1;
    snapshot->displacedPositionsMm[0] = {1, 0, -1};
    snapshot->displacedIds[1] = 2;
    snapshot->displacedPositionsMm[1] = {2, 0, -2};
    EXPECT_EQ(observer.apply(*snapshot), 2u);
    EXPECT_EQ(observer.view().positionsMm[1], glm::vec3(1, 0, -1));
    EXPECT_EQ(observer.view().positionsMm[2], glm::vec3(2, 0, -2));

    // Next frame: 2 moved, 3 is new, 1 is back at rest; an id outside the mesh is ignored.
    snapshot->displacedCount = 3;
    snapshot->displacedIds[0] = 2;
    snapshot->displacedPositionsMm[0] = {2, 0, -1.5f};
    snapshot->displacedIds[1] = 3;
    snapshot->displacedPositionsMm[1] = {3, 0, -0.5f};
    snapshot->displacedIds[2] = 99;
    EXPECT_EQ(observer.apply(*snapshot), 3u);  // 2 set, 3 set, 1 reset; 0 and 4 untouched
    EXPECT_EQ(observer.view().positionsMm[1], rest[1]);
    EXPECT_EQ(observer.view().positionsMm[2], glm::vec3(2, 0, -1.5f));
    EXPECT_EQ(observer.view().positionsMm[3], glm::vec3(3, 0, -0.5f));
    EXPECT_EQ(observer.view().positionsMm[0], rest[0]);
    EXPECT_EQ(observer.view().positionsMm[4], rest[4]);
    EXPECT_EQ(observer.displacedIds(), (std::vector<VertexId>{2, 3}));

    snapshot->displacedCount = 0;
    EXPECT_EQ(observer.apply(*snapshot), 2u);
    EXPECT_EQ(observer.view().positionsMm, rest);
}

TEST(MainWindow, OpensStepsAndShowsContactInTheStatusBar) {
    MainWindow window(RendererChoice::Auto, LoopMode::Stepped);
    EXPECT_EQ(window.viewport()->kind(), RendererKind::Software);
    const QString path = defaultMeshPath();
    ASSERT_EQ(window.loadMesh(path), QString());
    window.resize(800, 600);
    window.show();
    EXPECT_FALSE(window.session().threadRunning()) << "stepped mode must not start the haptic thread";
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("stomach_3970.off")));
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("3970 vertices")));
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("software")));
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("contact: no"))) << window.statusText().toStdString();

    window.advanceTicks(kTicksIntoContact);
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("contact: yes"))) << window.statusText().toStdString();
    EXPECT_FALSE(window.statusText().contains(QStringLiteral("force 0.00 N"))) << window.statusText().toStdString();
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("sim:stroke: Ready"))) << window.statusText().toStdString();
    EXPECT_EQ(window.session().observed().tick, std::uint64_t(kTicksIntoContact));
    EXPECT_FALSE(window.viewport()->grabImage().isNull());

    window.setPlaying(true);
    EXPECT_TRUE(window.isPlaying());
    window.setPlaying(false);
    EXPECT_FALSE(window.isPlaying());
}

TEST(MainWindow, SteppedRunsAreDeterministic) {
    std::uint64_t hashes[2] = {};
    for (auto& hash : hashes) {
        MainWindow window(RendererChoice::Software, LoopMode::Stepped);
        ASSERT_EQ(window.loadMesh(defaultMeshPath()), QString());
        window.advanceTicks(1500);
        // The snapshot's state is what is drawn; equal runs draw equal pictures.
        hash = qHash(QByteArray(reinterpret_cast<const char*>(window.session().view().positionsMm.data()),
                                qsizetype(window.session().view().positionsMm.size() * sizeof(glm::vec3))));
        EXPECT_TRUE(window.session().observed().contact);
    }
    EXPECT_EQ(hashes[0], hashes[1]);
}

TEST(MainWindow, TheScriptedStrokeRepeatsAfterARest) {
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window.loadMesh(defaultMeshPath()), QString());
    window.advanceTicks(6500);  // the 6 s stroke is over: the tool rests above the tissue
    EXPECT_FALSE(window.session().observed().contact);
    EXPECT_EQ(window.session().observer().displacedIds().size(), 0u) << "the tissue has relaxed";
    window.advanceTicks(1300);  // 7 s period: 0.8 s into the next stroke
    EXPECT_TRUE(window.session().observed().contact);
}

TEST(MainWindow, PauseGivesAPausedSnapshotWithZeroForce) {
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window.loadMesh(defaultMeshPath()), QString());
    window.advanceTicks(kTicksIntoContact);
    ASSERT_TRUE(window.session().observed().contact);
    ASSERT_GT(glm::length(window.session().observed().forceN), 0.0f);
    EXPECT_FALSE(window.session().observed().paused);

    // Through the menu, as Space does.
    QAction* pause = findAction(window, QStringLiteral("Pause"));
    ASSERT_NE(pause, nullptr);
    pause->trigger();
    EXPECT_FALSE(window.isPlaying());
    window.advanceTicks(1);
    EXPECT_TRUE(window.session().observed().paused);
    EXPECT_EQ(window.session().observed().forceN, glm::vec3(0.0f));
    EXPECT_FALSE(window.session().observed().contact);
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("force 0.00 N"))) << window.statusText().toStdString();

    window.setPlaying(true);
    window.advanceTicks(1);
    EXPECT_FALSE(window.session().observed().paused);
}

TEST(MainWindow, PauseActionsTickMeansPausedAndItsTextSaysWhatAClickDoes) {
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window.loadMesh(defaultMeshPath()), QString());
    auto* pause = window.findChild<QAction*>(QStringLiteral("pauseAction"));
    ASSERT_NE(pause, nullptr);
    ASSERT_TRUE(pause->isCheckable());
    const QString text = pause->text();
    EXPECT_EQ(text, MainWindow::tr("&Pause"));
    // Running: no tick (a click pauses).
    EXPECT_TRUE(window.isPlaying());
    EXPECT_FALSE(pause->isChecked());
    pause->trigger();
    EXPECT_FALSE(window.isPlaying());
    EXPECT_TRUE(pause->isChecked());
    EXPECT_EQ(pause->text(), text);
    pause->trigger();
    EXPECT_TRUE(window.isPlaying());
    EXPECT_FALSE(pause->isChecked());
    // Paused from elsewhere (a recording played back, the welcome page): the tick follows.
    window.setPlaying(false);
    EXPECT_TRUE(pause->isChecked());
    window.setPlaying(true);
    EXPECT_FALSE(pause->isChecked());
    EXPECT_EQ(pause->text(), text);
}

TEST(MainWindow, RestartAndDeviceSwitchSwapTheLoopsSceneAndDevice) {
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window.loadMesh(defaultMeshPath()), QString());
    window.advanceTicks(7000);  // the stroke has ended and is resting before it repeats
    const std::uint64_t firstScene = window.session().drawnSceneId();
    EXPECT_EQ(window.session().observed().sceneId, firstScene);

    ASSERT_EQ(window.restartSimulation(), QString());
    EXPECT_TRUE(window.session().sceneSwitchPending());
    EXPECT_EQ(window.session().drawnSceneId(), firstScene) << "drawn switches only once the loop runs the new scene";
    window.advanceTicks(1);
    EXPECT_FALSE(window.session().sceneSwitchPending());
    EXPECT_NE(window.session().drawnSceneId(), firstScene);
    EXPECT_EQ(window.session().observed().sceneId, window.session().drawnSceneId());
    EXPECT_EQ(window.viewport()->scene().vertexCount(), 3970u);
    EXPECT_FALSE(window.session().observed().contact);
    // The fresh device plays its script from the start: pressing again 800 ticks later.
    window.advanceTicks(kTicksIntoContact - 1);
    EXPECT_TRUE(window.session().observed().contact) << window.statusText().toStdString();

    // The Device menu lists the four scripted devices and the mouse; choosing one swaps it in.
    QMenu* devices = nullptr;
    for (QMenu* menu : window.findChildren<QMenu*>())
        if (menu->title().remove(QLatin1Char('&')) == QStringLiteral("Device")) devices = menu;
    ASSERT_NE(devices, nullptr);
    QStringList listed;
    for (QAction* action : devices->actions()) {
        listed << action->text();
        EXPECT_TRUE(action->isCheckable());
        EXPECT_EQ(action->isChecked(), action->text() == QStringLiteral("sim:stroke")) << action->text().toStdString();
    }
    EXPECT_EQ(listed, (QStringList{"sim:press", "sim:stroke", "sim:scan", "sim:sine", "mouse:"}));
    devices->actions().at(3)->trigger();
    EXPECT_EQ(window.session().deviceUri(), "sim:sine");
    EXPECT_TRUE(devices->actions().at(3)->isChecked());
    EXPECT_FALSE(devices->actions().at(1)->isChecked());
    window.advanceTicks(kTicksIntoContact);
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("sim:sine: Ready"))) << window.statusText().toStdString();
    EXPECT_TRUE(window.session().observed().contact);

    // A bad URI is refused with a message naming it; the device stays.
    const QString error = window.setDeviceUri(QStringLiteral("nosuch:thing"));
    EXPECT_TRUE(error.contains(QStringLiteral("nosuch:thing"))) << error.toStdString();
    EXPECT_EQ(window.session().deviceUri(), "sim:sine");

    // Another mesh: drawn once the loop runs it.
    const QString other = QString::fromStdString(findResource("meshes/sphere_1442.off"));
    ASSERT_FALSE(other.isEmpty());
    ASSERT_EQ(window.loadMesh(other), QString());
    EXPECT_EQ(window.viewport()->scene().vertexCount(), 3970u);
    window.advanceTicks(1);
    EXPECT_EQ(window.viewport()->scene().vertexCount(), 1442u);
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("sphere_1442.off"))) << window.statusText().toStdString();
    window.advanceTicks(kTicksIntoContact);
    EXPECT_TRUE(window.session().observed().contact) << "the new device is aimed at the new mesh";
}

TEST(MainWindow, BadMeshGivesAnErrorNamingTheFileAndKeepsTheScene) {
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window.loadMesh(defaultMeshPath()), QString());

    const QString missing = QStringLiteral("/nonexistent/dir/missing_mesh.off");
    const QString missingError = window.loadMesh(missing);
    EXPECT_TRUE(missingError.contains(missing)) << missingError.toStdString();

    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString garbage = dir.filePath(QStringLiteral("garbage.off"));
    QFile file(garbage);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n");
    file.close();
    const QString garbageError = window.loadMesh(garbage);
    EXPECT_FALSE(garbageError.isEmpty());
    EXPECT_TRUE(garbageError.contains(garbage)) << garbageError.toStdString();

    // The failed loads left the previous scene in place, in the loop too.
    window.advanceTicks(10);
    EXPECT_FALSE(window.session().sceneSwitchPending());
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("stomach_3970.off")));
    EXPECT_EQ(window.viewport()->scene().vertexCount(), 3970u);
}

TEST(MainWindow, InteractiveRunsTheLoopThreadAndOnlyObservesIt) {
    auto window = std::make_unique<MainWindow>(RendererChoice::Auto, LoopMode::Threaded);
    ASSERT_EQ(window->loadMesh(defaultMeshPath()), QString());
    window->resize(800, 600);
    window->show();
    EXPECT_TRUE(window->session().threadRunning());

    QTest::qWait(300);
    // A loaded (or sanitized) machine may observe later: wait for the observer to see 100 ticks.
    waitUntil([&] { return window->session().observed().counters.ticks > 100u; }, 5000);
    // The status bar updates at ~4 Hz; give a loaded machine a little longer to paint it.
    waitUntil([&] { return statusNumber(*window, "hapticRateStatus") > 0.0; }, 2000);
    const double rateHz = statusNumber(*window, "hapticRateStatus");
    EXPECT_GT(rateHz, 500.0) << window->statusText().toStdString();
    EXPECT_GT(window->session().snapshotsObserved(), 0u);
    EXPECT_GT(window->session().observed().publishCount, 0u);
    EXPECT_GT(window->session().observed().counters.ticks, 100u);
    EXPECT_GE(statusNumber(*window, "overrunStatus"), 0.0);
    EXPECT_NE(window->findChild<QLabel*>(QStringLiteral("schedFifoStatus")), nullptr);
    EXPECT_NE(window->findChild<QLabel*>(QStringLiteral("frameRateStatus")), nullptr);

    // Pause reaches the thread: the next snapshots say paused, with zero force.
    window->setPlaying(false);
    EXPECT_TRUE(waitUntil([&] { return window->session().observed().paused; }, 2000));
    EXPECT_EQ(window->session().observed().forceN, glm::vec3(0.0f));
    window->setPlaying(true);
    EXPECT_TRUE(waitUntil([&] { return !window->session().observed().paused; }, 2000));

    // Restart while the thread runs: the drawn scene follows the snapshot's scene id.
    const std::uint64_t firstScene = window->session().drawnSceneId();
    ASSERT_EQ(window->restartSimulation(), QString());
    EXPECT_TRUE(waitUntil([&] { return window->session().drawnSceneId() != firstScene; }, 2000));
    EXPECT_EQ(window->viewport()->scene().vertexCount(), 3970u);

    // Closing stops the thread before anything is destroyed.
    window->close();
    EXPECT_FALSE(window->session().threadRunning());
    window.reset();
}

// --- the renderer for the GL_RENDERER found (a pure function: strings in, decision out) ---

TEST(ViewportFactory, NoMultisamplingAndTheSoftwareRendererOnACpuRasteriser) {
    const QString llvmpipe = QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)");
    const QString gpu = QStringLiteral("Mesa Intel(R) UHD Graphics 620 (KBL GT2)");
    for (const char* cpu : {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Software Rasterizer", "swrast"})
        EXPECT_TRUE(isSoftwareGlRenderer(QLatin1String(cpu))) << cpu;
    for (const char* hardware : {"Mesa Intel(R) UHD Graphics 620 (KBL GT2)", "NVIDIA GeForce RTX 3060/PCIe/SSE2",
                                 "AMD Radeon RX 6600 (navi23, LLVM 15.0.6, DRM 3.49)", "Apple M1"})
        EXPECT_FALSE(isSoftwareGlRenderer(QLatin1String(hardware))) << hardware;

    EXPECT_EQ(viewportSamplesFor(llvmpipe), 0) << "4x costs a CPU rasteriser up to four times the fragments";
    EXPECT_EQ(viewportSamplesFor(QStringLiteral("softpipe")), 0);
    EXPECT_EQ(viewportSamplesFor(gpu), 4);
    EXPECT_EQ(viewportSamplesFor(llvmpipe, 4), 4) << "the benchmark's baseline forces the old 4x";
    EXPECT_EQ(viewportSamplesFor(gpu, 0), 0);

    const GlProbe onLlvmpipe{true, QString(), llvmpipe};
    const GlProbe onGpu{true, QString(), gpu};
    const GlProbe none{false, QStringLiteral("no OpenGL context could be created"), QString()};
    // Auto: the software renderer on a CPU rasteriser (it is faster there), OpenGL with 4x on a GPU.
    const RendererDecision autoCpu = decideRenderer(RendererChoice::Auto, onLlvmpipe);
    EXPECT_EQ(autoCpu.kind, RendererKind::Software);
    EXPECT_TRUE(autoCpu.reason.contains(QStringLiteral("llvmpipe"))) << autoCpu.reason.toStdString();
    const RendererDecision autoGpu = decideRenderer(RendererChoice::Auto, onGpu);
    EXPECT_EQ(autoGpu.kind, RendererKind::OpenGL);
    EXPECT_EQ(autoGpu.samples, 4);
    // --opengl-render on llvmpipe: OpenGL, without multisampling.
    const RendererDecision forcedCpu = decideRenderer(RendererChoice::OpenGL, onLlvmpipe);
    EXPECT_EQ(forcedCpu.kind, RendererKind::OpenGL);
    EXPECT_EQ(forcedCpu.samples, 0);
    EXPECT_TRUE(forcedCpu.reason.contains(QStringLiteral("no multisampling"))) << forcedCpu.reason.toStdString();
    // No OpenGL: software, saying why; --software-render: software whatever is there.
    for (const auto choice : {RendererChoice::Auto, RendererChoice::OpenGL}) {
        const RendererDecision without = decideRenderer(choice, none);
        EXPECT_EQ(without.kind, RendererKind::Software);
        EXPECT_EQ(without.reason, none.whyNot);
    }
    EXPECT_EQ(decideRenderer(RendererChoice::Software, onGpu).kind, RendererKind::Software);
}

// --- palpate --benchmark-viewport (what main() calls; no frame rate is asserted: machines are noisy) ---

TEST(ViewportBenchmark, PrintsFpsForAMeshWithTheSoftwareRenderer) {
    testing::internal::CaptureStdout();
    const int code = runViewportBenchmark(QStringLiteral("0.5"), defaultMeshPath(), RendererChoice::Software);
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_EQ(code, 0) << out;
    EXPECT_NE(out.find("fps="), std::string::npos) << out;
    EXPECT_NE(out.find("renderer=software"), std::string::npos) << out;
    EXPECT_NE(out.find("vertices=3970"), std::string::npos) << "the --mesh given, not the generated sphere\n" << out;
    EXPECT_NE(out.find("device sim:sine"), std::string::npos) << "a device that keeps pressing\n" << out;
}

TEST(ViewportBenchmark, BadArgumentsGiveAMessageAndNoHang) {
    testing::internal::CaptureStderr();
    EXPECT_EQ(runViewportBenchmark(QStringLiteral("-1"), defaultMeshPath(), RendererChoice::Software), 2);
    EXPECT_EQ(runViewportBenchmark(QStringLiteral("0.5"), QStringLiteral("/no/such/mesh.off"), RendererChoice::Software), 1);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("--seconds"), std::string::npos) << err;
    EXPECT_NE(err.find("/no/such/mesh.off"), std::string::npos) << err;
}

int main(int argc, char** argv) {
    // Before QApplication: the platform is chosen in its constructor. No GPU, no display needed.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // the windows' results databases are not the user's
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
