// The main window's docks reach the engine: Apply changes what the haptic loop computes, a bad
// preset leaves the scene alone, the device dock switches devices, recent files are kept.
#include "base/resources/ShippedResources.h"
#include "app/gui/MainWindow.h"
#include "engine/scene/TissuePreset.h"
#include "widgets/DevicePanel.h"
#include "widgets/ParameterPanel.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

using namespace palpate;

namespace {

QString meshPath() { return QString::fromStdString(findResource(kDefaultMesh)); }

/// A window in stepped mode, pressed into the tissue by the scripted press-and-hold.
std::unique_ptr<MainWindow> pressedWindow() {
    auto window = std::make_unique<MainWindow>(RendererChoice::Software, LoopMode::Stepped);
    EXPECT_EQ(window->setDeviceUri(QStringLiteral("sim:press")), QString());
    EXPECT_EQ(window->loadMesh(meshPath()), QString());
    window->advanceTicks(2500);  // deep in the hold, safety filter armed
    EXPECT_TRUE(window->session().observed().contact);
    return window;
}

}  // namespace

TEST(MainWindowDocks, ApplyReachesTheEngineInTheNextSnapshot) {
    auto window = pressedWindow();
    const float before = glm::length(window->session().observed().commandedForceN);
    ASSERT_GT(before, 0.1f);
    TissuePreset preset = window->parameterPanel()->preset();
    preset.model.slopeRing.springStiffnessNPerMm *= 2.0;  // the rendered force is k |m1| F: doubles
    window->parameterPanel()->setPreset(preset);
    ASSERT_TRUE(window->parameterPanel()->isValid());
    // 3 N/mm renders 1.125 N/mm, beyond the device's passive 1 N/mm at 1 kHz: Apply asks; yes.
    int asked = 0;
    window->parameterPanel()->setConfirmFunction([&](const QString&, const QString&) { return ++asked > 0; });
    window->parameterPanel()->apply();
    EXPECT_EQ(asked, 1);
    window->advanceTicks(1);
    EXPECT_NEAR(glm::length(window->session().observed().commandedForceN), 2.0f * before, 0.05f * before);
}

TEST(MainWindowDocks, ModelChangeFromThePanelRebuildsTheScene) {
    auto window = pressedWindow();
    const auto scene = window->session().drawnSceneId();
    TissuePreset preset = window->parameterPanel()->preset();
    preset.model.slopeRingMethod = SlopeRingMethod::Proposed;
    window->parameterPanel()->setPreset(preset);
    window->parameterPanel()->apply();
    window->advanceTicks(10);
    EXPECT_NE(window->session().drawnSceneId(), scene);
    EXPECT_EQ(window->session().preset().model.slopeRingMethod, SlopeRingMethod::Proposed);
}

TEST(MainWindowDocks, BadPresetNamesTheKeyAndLeavesTheSceneAndParametersAlone) {
    auto window = pressedWindow();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "palpate-tissue-preset", "version": 1, "name": "x", "haptic_rate_hz": "fast"})");
    file.close();
    const auto scene = window->session().drawnSceneId();
    const double k = window->session().preset().model.slopeRing.springStiffnessNPerMm;
    const QString error = window->loadPresetFile(path);
    EXPECT_TRUE(error.contains(QStringLiteral("haptic_rate_hz"))) << error.toStdString();
    EXPECT_TRUE(error.contains(path)) << error.toStdString();
    window->advanceTicks(10);
    EXPECT_EQ(window->session().drawnSceneId(), scene);
    EXPECT_EQ(window->session().preset().model.slopeRing.springStiffnessNPerMm, k);
    EXPECT_TRUE(window->session().observed().contact);
}

TEST(MainWindowDocks, ShippedPresetLoadsAndApplies) {
    auto window = pressedWindow();
    const QString preset = QString::fromStdString(findResource("presets/default.json"));
    ASSERT_FALSE(preset.isEmpty());
    EXPECT_EQ(window->loadPresetFile(preset), QString());
    EXPECT_EQ(window->session().preset().name, "default");
}

TEST(MainWindowDocks, DeviceDockSwitchesTheDeviceAndShowsItsSpec) {
    auto window = pressedWindow();
    DevicePanel* panel = window->devicePanel();
    EXPECT_TRUE(panel->isConnected());
    emit panel->connectRequested(QStringLiteral("sim:sine"));
    EXPECT_EQ(window->session().deviceUri(), "sim:sine");
    EXPECT_EQ(panel->connectedUri(), QStringLiteral("sim:sine"));
    emit panel->connectRequested(QStringLiteral("nonsense:"));
    EXPECT_TRUE(panel->errorShown());
    EXPECT_EQ(window->session().deviceUri(), "sim:sine");  // the old device stays
    emit panel->disconnectRequested();
    window->advanceTicks(5);
    EXPECT_EQ(window->session().observed().deviceState, DeviceState::Disconnected);
    EXPECT_EQ(window->session().observed().forceN, glm::vec3(0.0f));
}

TEST(MainWindowDocks, RecentFilesKeepTheLastMeshFirst) {
    auto window = std::make_unique<MainWindow>(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window->loadMesh(meshPath()), QString());
    ASSERT_FALSE(window->recentFiles().isEmpty());
    EXPECT_TRUE(window->recentFiles().front().endsWith(QStringLiteral("stomach_3970.off")));
}
