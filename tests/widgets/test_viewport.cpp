// The viewport and the main window under QT_QPA_PLATFORM=offscreen: the factory falls back to the
// software renderer, which draws the mesh and the touched-vertex highlight; the window loads, steps
// and reports contact; bad meshes give errors naming the file.
#include "app/cli/DefaultScene.h"
#include "app/gui/MainWindow.h"
#include "app/gui/SceneSimulation.h"
#include "widgets/SceneOverlay.h"
#include "widgets/SceneStyle.h"
#include "widgets/SoftwareViewport.h"
#include "widgets/ViewportFactory.h"

#include <QApplication>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

using namespace palpate;

namespace {

constexpr int kTicksIntoContact = 800;  // the scripted path is pressing by then

QString defaultMeshPath() { return QString::fromStdString(cli::findResource(cli::kDefaultMesh)); }

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
    ASSERT_FALSE(path.isEmpty()) << "resources/" << cli::kDefaultMesh << " not found";
    auto outcome = SceneSimulation::load(path.toStdString());
    ASSERT_TRUE(outcome.simulation) << outcome.error;
    SceneSimulation& simulation = *outcome.simulation;

    SoftwareViewport viewport;
    viewport.resize(640, 480);
    viewport.setMesh(simulation.mesh());
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

    simulation.advance(kTicksIntoContact);
    ASSERT_TRUE(simulation.lastTick().contact) << "the scripted path should be pressing after " << kTicksIntoContact;
    SceneSnapshot snapshot;
    simulation.fillSnapshot(snapshot);
    viewport.setSnapshot(snapshot);
    const QImage pressed = viewport.grabImage();
    EXPECT_GT(countNear(pressed, all, highlight, 10), 20) << "no touched-vertex highlight in contact";
    // The pressed tissue is drawn deformed: the picture changed beyond the markers.
    EXPECT_NE(pressed, atRest);
}

TEST(MainWindow, OpensStepsAndShowsContactInTheStatusBar) {
    MainWindow window(RendererChoice::Auto);
    EXPECT_EQ(window.viewport()->kind(), RendererKind::Software);
    const QString path = defaultMeshPath();
    ASSERT_EQ(window.loadMesh(path), QString());
    window.resize(800, 600);
    window.show();
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("stomach_3970.off")));
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("3970 vertices")));
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("software")));
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("contact: no"))) << window.statusText().toStdString();

    window.advanceTicks(kTicksIntoContact);
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("contact: yes"))) << window.statusText().toStdString();
    EXPECT_FALSE(window.statusText().contains(QStringLiteral("force 0.00 N"))) << window.statusText().toStdString();
    EXPECT_FALSE(window.viewport()->grabImage().isNull());

    window.setPlaying(true);
    EXPECT_TRUE(window.isPlaying());
    window.setPlaying(false);
    EXPECT_FALSE(window.isPlaying());
}

TEST(MainWindow, BadMeshGivesAnErrorNamingTheFileAndKeepsTheScene) {
    MainWindow window(RendererChoice::Software);
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

    // The failed loads left the previous scene in place.
    EXPECT_TRUE(window.statusText().contains(QStringLiteral("stomach_3970.off")));
    EXPECT_EQ(window.viewport()->scene().vertexCount(), 3970u);
}

int main(int argc, char** argv) {
    // Before QApplication: the platform is chosen in its constructor. No GPU, no display needed.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
