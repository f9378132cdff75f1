// Touch mode under QT_QPA_PLATFORM=offscreen, stepped (deterministic): the mouse: device, steered by
// the viewport's left button (ray-picked on the drawn mesh), presses the tissue where it is touched,
// lets go on release, and presses deeper as the wheel turns. Shares widget_tests' main().
#include "base/resources/ShippedResources.h"
#include "app/gui/HapticSession.h"
#include "app/gui/MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QImage>
#include <QMouseEvent>
#include <QWheelEvent>
#include <QWidget>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <optional>
#include <set>

using namespace palpate;

namespace {

constexpr int kTicks = 300;

QString meshPath() { return QString::fromStdString(findResource(kDefaultMesh)); }

void sendMouse(QWidget& widget, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons,
               Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QMouseEvent event(type, at, widget.mapToGlobal(at), button, buttons, modifiers);
    QApplication::sendEvent(&widget, &event);
}

void sendWheel(QWidget& widget, QPointF at, int notches, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QWheelEvent event(at, widget.mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton, modifiers,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(&widget, &event);
}

/// The vertex nearest the camera's eye (faces the camera, unhidden) and where it is drawn.
struct Target {
    VertexId vertex = kNoVertex;
    QPointF pixel;
};

Target visibleVertex(const Viewport& viewport, QSize size) {
    const auto positions = viewport.scene().positionsMm();
    const glm::vec3 eye = viewport.camera().eyeMm();
    VertexId best = 0;
    for (VertexId v = 1; v < positions.size(); ++v)
        if (glm::length(positions[v] - eye) < glm::length(positions[best] - eye)) best = v;
    const auto p = viewport.camera().projectToPixel(positions[best], glm::vec2(float(size.width()), float(size.height())));
    if (!p) return {};
    return {best, QPointF(p->x, p->y)};
}

/// The touched vertex and its one-ring in the drawn mesh.
std::set<VertexId> withNeighbours(const TissueMesh& mesh, VertexId v) {
    std::set<VertexId> out{v};
    const auto& tris = mesh.triangles();
    for (const auto& t : tris)
        if (t[0] == v || t[1] == v || t[2] == v) out.insert({t[0], t[1], t[2]});
    return out;
}

class TouchMode : public ::testing::Test {
protected:
    void SetUp() override {
        window = std::make_unique<MainWindow>(RendererChoice::Software, LoopMode::Stepped);
        ASSERT_EQ(window->loadMesh(meshPath()), QString());
        ASSERT_EQ(window->setDeviceUri(QStringLiteral("mouse:")), QString());
        window->resize(900, 650);
        window->show();
        QApplication::processEvents();
        widget = window->viewport()->widget();
    }
    double force() const { return double(glm::length(window->session().observed().forceN)); }

    std::unique_ptr<MainWindow> window;
    QWidget* widget = nullptr;
};

}  // namespace

TEST_F(TouchMode, ChoosingTheMouseDeviceTurnsTouchModeOnAndTheToolStartsOffTheTissue) {
    EXPECT_TRUE(window->touchMode());
    ASSERT_NE(window->touchModeAction(), nullptr);
    EXPECT_TRUE(window->touchModeAction()->isChecked());
    EXPECT_EQ(window->touchModeAction()->shortcut(), QKeySequence(Qt::Key_T));
    EXPECT_TRUE(window->session().touchAvailable());
    EXPECT_DOUBLE_EQ(window->touchDepthMm(), Viewport::kDefaultTouchDepthMm);
    window->advanceTicks(kTicks);
    EXPECT_FALSE(window->session().observed().contact) << "the fresh mouse tool must wait off the surface";
    EXPECT_EQ(force(), 0.0);
    EXPECT_TRUE(window->statusText().contains(QStringLiteral("mouse: Ready"))) << window->statusText().toStdString();

    // Another device: touch mode off, no mouse to steer; back to mouse: turns it on again.
    ASSERT_EQ(window->setDeviceUri(QStringLiteral("sim:press")), QString());
    EXPECT_FALSE(window->touchMode());
    EXPECT_FALSE(window->session().touchAvailable());
    // The Device menu's mouse: does the same as setDeviceUri.
    QAction* mouseAction = nullptr;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->data().toString() == QStringLiteral("mouse:")) mouseAction = action;
    ASSERT_NE(mouseAction, nullptr);
    mouseAction->trigger();
    EXPECT_EQ(window->session().deviceUri(), "mouse:");
    EXPECT_TRUE(window->touchMode());
    EXPECT_TRUE(window->touchModeAction()->isChecked());
    window->touchModeAction()->trigger();
    EXPECT_FALSE(window->touchMode());
}

TEST_F(TouchMode, PressingAVertexPressesTheTissueThereAndReleaseLetsGo) {
    window->advanceTicks(10);
    const QSize size = widget->size();
    const Target target = visibleVertex(*window->viewport(), size);
    ASSERT_NE(target.vertex, kNoVertex);
    ASSERT_EQ(window->viewport()->pickVertexAt(target.pixel, size), target.vertex);

    const glm::vec3 eyeBefore = window->viewport()->camera().eyeMm();
    sendMouse(*widget, QEvent::MouseButtonPress, target.pixel, Qt::LeftButton, Qt::LeftButton);
    sendMouse(*widget, QEvent::MouseMove, target.pixel + QPointF(0.2, 0.2), Qt::NoButton, Qt::LeftButton);
    EXPECT_TRUE(window->viewport()->touching());
    window->advanceTicks(kTicks);
    const ObservedLoop& o = window->session().observed();
    EXPECT_TRUE(o.contact);
    EXPECT_GT(force(), 0.0);
    EXPECT_TRUE(withNeighbours(*window->session().drawnMesh(), target.vertex).count(o.touched))
        << "touched " << o.touched << ", picked " << target.vertex;
    // Touch mode's left drag does not orbit.
    EXPECT_EQ(window->viewport()->camera().eyeMm(), eyeBefore);

    // The tool pressing where it was touched, for a look (build/.../touch_mode_pressing.png).
    const QImage image = window->viewport()->grabImage();
    ASSERT_FALSE(image.isNull());
    image.save(QDir::current().filePath(QStringLiteral("touch_mode_pressing.png")));

    sendMouse(*widget, QEvent::MouseButtonRelease, target.pixel, Qt::LeftButton, Qt::NoButton);
    EXPECT_FALSE(window->viewport()->touching());
    window->advanceTicks(kTicks);
    EXPECT_FALSE(window->session().observed().contact);
    EXPECT_EQ(force(), 0.0);
}

TEST_F(TouchMode, TheWheelSetsTheDepthAndADeeperPressPushesHarder) {
    window->advanceTicks(10);
    const QSize size = widget->size();
    const Target target = visibleVertex(*window->viewport(), size);
    ASSERT_NE(target.vertex, kNoVertex);
    const float distanceBefore = window->viewport()->camera().distanceMm();

    // Two notches back: 3 -> 2 mm; the camera does not zoom.
    sendWheel(*widget, target.pixel, -2);
    EXPECT_DOUBLE_EQ(window->touchDepthMm(), Viewport::kDefaultTouchDepthMm - 2 * Viewport::kTouchDepthStepMm);
    EXPECT_EQ(window->viewport()->camera().distanceMm(), distanceBefore);
    sendMouse(*widget, QEvent::MouseButtonPress, target.pixel, Qt::LeftButton, Qt::LeftButton);
    window->advanceTicks(kTicks);
    ASSERT_TRUE(window->session().observed().contact);
    const double shallow = force();
    EXPECT_GT(shallow, 0.0);

    // Deeper while pressing: the touch in progress follows the wheel.
    sendWheel(*widget, target.pixel, 2);
    EXPECT_DOUBLE_EQ(window->touchDepthMm(), Viewport::kDefaultTouchDepthMm);
    window->advanceTicks(kTicks);
    ASSERT_TRUE(window->session().observed().contact);
    EXPECT_GT(force(), shallow);
    sendMouse(*widget, QEvent::MouseButtonRelease, target.pixel, Qt::LeftButton, Qt::NoButton);

    // The depth stays within 0..10 mm; Shift+wheel zooms instead.
    sendWheel(*widget, target.pixel, 100);
    EXPECT_DOUBLE_EQ(window->touchDepthMm(), Viewport::kMaxTouchDepthMm);
    sendWheel(*widget, target.pixel, -100);
    EXPECT_DOUBLE_EQ(window->touchDepthMm(), 0.0);
    sendWheel(*widget, target.pixel, 1, Qt::ShiftModifier);
    EXPECT_DOUBLE_EQ(window->touchDepthMm(), 0.0);
    EXPECT_LT(window->viewport()->camera().distanceMm(), distanceBefore);
}

TEST_F(TouchMode, RightDragOrbitsAndTouchingWithoutAMouseDeviceDoesNothing) {
    const glm::vec3 eyeBefore = window->viewport()->camera().eyeMm();
    sendMouse(*widget, QEvent::MouseButtonPress, {300, 300}, Qt::RightButton, Qt::RightButton);
    sendMouse(*widget, QEvent::MouseMove, {340, 290}, Qt::NoButton, Qt::RightButton);
    sendMouse(*widget, QEvent::MouseButtonRelease, {340, 290}, Qt::RightButton, Qt::NoButton);
    EXPECT_NE(window->viewport()->camera().eyeMm(), eyeBefore);
    EXPECT_FALSE(window->viewport()->touching());

    ASSERT_EQ(window->setDeviceUri(QStringLiteral("sim:press")), QString());
    window->touchVertex(0);  // no mouse device: ignored, nothing crashes
    window->releaseTouch();
    window->setTouchMode(true);
    sendMouse(*widget, QEvent::MouseButtonPress, {300, 300}, Qt::LeftButton, Qt::LeftButton);
    sendMouse(*widget, QEvent::MouseButtonRelease, {300, 300}, Qt::LeftButton, Qt::NoButton);
    window->advanceTicks(10);
}
