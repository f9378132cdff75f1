// The device panel under QT_QPA_PLATFORM=offscreen (main() is in test_viewport.cpp): it lists every
// URI form of listDeviceSchemes, refuses an invalid URI with an error naming it, asks for a waypoint
// file for sim:path:FILE, emits connect requests without owning the loop, shows the spec and the
// live state, and raises a red banner when the connected device is lost until it is Ready and armed.
// Set PALPATE_DEVICE_PANEL_PNG_DIR to keep the rendered panels as PNGs.
#include "base/resources/ShippedResources.h"
#include "app/gui/MainWindow.h"
#include "device/open/DeviceUri.h"
#include "device/SafetyFilter.h"
#include "engine/loop/HapticSnapshot.h"
#include "widgets/DevicePanel.h"
#include "widgets/ParameterPanel.h"
#include "tests/support/StubDevice.h"

#include <QDir>
#include <QImage>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSet>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <thread>

using namespace palpate;

namespace {

/// Numbers in the panel follow QLocale(); the expectations below are written for en_US.
class DevicePanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        mSavedLocale = QLocale();
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        panel = std::make_unique<DevicePanel>();
        panel->resize(360, 720);
    }
    void TearDown() override {
        panel.reset();
        QLocale::setDefault(mSavedLocale);
    }

    QTreeWidget* list() const { return panel->findChild<QTreeWidget*>(QStringLiteral("deviceList")); }
    QLineEdit* uriEdit() const { return panel->findChild<QLineEdit*>(QStringLiteral("deviceUriEdit")); }
    QPushButton* button(const char* name) const { return panel->findChild<QPushButton*>(QString::fromLatin1(name)); }
    QString label(const char* name) const {
        const QLabel* l = panel->findChild<QLabel*>(QString::fromLatin1(name));
        return l ? l->text() : QStringLiteral("<no label %1>").arg(QString::fromLatin1(name));
    }
    QTreeWidgetItem* itemFor(const QString& uriTemplate) const {
        for (int i = 0; i < list()->topLevelItemCount(); ++i)
            if (list()->topLevelItem(i)->data(0, Qt::UserRole).toString() == uriTemplate) return list()->topLevelItem(i);
        return nullptr;
    }
    void typeUri(const QString& text) {
        uriEdit()->clear();
        QTest::keyClicks(uriEdit(), text);
    }
    void clickConnect() { QTest::mouseClick(button("deviceConnectButton"), Qt::LeftButton); }

    static std::unique_ptr<HapticSnapshot> snapshot(DeviceState state, SafetyPhase phase, std::uint32_t flags = 0) {
        auto s = std::make_unique<HapticSnapshot>();
        s->deviceState = state;
        s->safetyPhase = phase;
        s->safetyFlags = flags;
        return s;
    }
    static DeviceSpec testSpec() {
        DeviceSpec spec;
        spec.name = "Test Falcon";
        spec.maxForceN = 8.5;
        spec.maxStiffnessNPerMm = 2.5;
        spec.maxDampingNsPerMm = 0.012;
        spec.workspaceRadiusMm = 60.0;
        spec.actuated = true;
        spec.buttonCount = 3;
        return spec;
    }

    /// Renders the panel (shown, laid out) and keeps it as a PNG when asked to.
    QImage render(const QString& name) {
        panel->show();
        QCoreApplication::processEvents();
        const QImage image = panel->grab().toImage();
        if (const QByteArray dir = qgetenv("PALPATE_DEVICE_PANEL_PNG_DIR"); !dir.isEmpty()) {
            QDir().mkpath(QString::fromLocal8Bit(dir));
            image.save(QString::fromLocal8Bit(dir) + QLatin1Char('/') + name + QStringLiteral(".png"));
        }
        return image;
    }

    std::unique_ptr<DevicePanel> panel;

private:
    QLocale mSavedLocale;
};

}  // namespace

TEST_F(DevicePanelTest, ListsEverySchemeOfListDeviceSchemes) {
    const std::vector<DeviceSchemeInfo> schemes = listDeviceSchemes();
    ASSERT_NE(list(), nullptr);
    ASSERT_EQ(list()->topLevelItemCount(), int(schemes.size()));
    for (int i = 0; i < int(schemes.size()); ++i) {
        const QTreeWidgetItem* item = list()->topLevelItem(i);
        EXPECT_EQ(item->text(0).toStdString(), schemes[i].uri);
        EXPECT_EQ(item->text(1).toStdString(), schemes[i].description);
    }
    for (const char* uri : {"sim:press", "sim:stroke", "sim:scan", "sim:sine", "sim:path:FILE", "mouse:"})
        EXPECT_NE(itemFor(QString::fromLatin1(uri)), nullptr) << uri;
    EXPECT_FALSE(panel->isConnected());
    EXPECT_EQ(label("deviceConnectionLabel"), QStringLiteral("Not connected"));
    EXPECT_FALSE(button("deviceDisconnectButton")->isEnabled());
}

TEST_F(DevicePanelTest, InvalidTypedUriShowsAnErrorNamingItAndEmitsNothing) {
    QSignalSpy connects(panel.get(), &DevicePanel::connectRequested);
    const struct {
        const char* uri;
        const char* problem;
    } cases[] = {
        {"bogus:thing", "unknown scheme"},
        {"sim:wobble", "unknown simulated trajectory"},
        {"sim:path:", "needs a waypoint file"},
        {"mouse:left", "takes no argument"},
        {"nocolon", "no ':'"},
    };
    for (const auto& c : cases) {
        typeUri(QString::fromLatin1(c.uri));
        clickConnect();
        EXPECT_TRUE(panel->errorShown()) << c.uri;
        EXPECT_TRUE(panel->errorText().contains(QStringLiteral("'%1'").arg(QString::fromLatin1(c.uri))))
            << panel->errorText().toStdString();
        EXPECT_TRUE(panel->errorText().contains(QString::fromLatin1(c.problem))) << panel->errorText().toStdString();
    }
    // Return in the field is Connect too.
    typeUri(QStringLiteral("sim:nope"));
    QTest::keyClick(uriEdit(), Qt::Key_Return);
    EXPECT_TRUE(panel->errorText().contains(QStringLiteral("'sim:nope'")));
    EXPECT_EQ(connects.count(), 0);
    render(QStringLiteral("device_panel_error"));

    // Editing clears the error; a valid URI then goes through.
    QTest::keyClick(uriEdit(), Qt::Key_Backspace);
    EXPECT_FALSE(panel->errorShown());
    typeUri(QStringLiteral("sim:sine"));
    clickConnect();
    ASSERT_EQ(connects.count(), 1);
    EXPECT_EQ(connects.at(0).at(0).toString(), QStringLiteral("sim:sine"));
    EXPECT_FALSE(panel->errorShown());
}

TEST_F(DevicePanelTest, ConnectEmitsTheSelectedUri) {
    QSignalSpy connects(panel.get(), &DevicePanel::connectRequested);
    QSignalSpy disconnects(panel.get(), &DevicePanel::disconnectRequested);

    list()->setCurrentItem(itemFor(QStringLiteral("sim:scan")));
    EXPECT_EQ(panel->uri(), QStringLiteral("sim:scan"));
    clickConnect();
    ASSERT_EQ(connects.count(), 1);
    EXPECT_EQ(connects.at(0).at(0).toString(), QStringLiteral("sim:scan"));
    // The panel does not decide it is connected: the main window tells it.
    EXPECT_FALSE(panel->isConnected());

    // Typing a listed URI selects its entry.
    typeUri(QStringLiteral("mouse:"));
    EXPECT_EQ(list()->currentItem(), itemFor(QStringLiteral("mouse:")));
    clickConnect();
    ASSERT_EQ(connects.count(), 2);
    EXPECT_EQ(connects.at(1).at(0).toString(), QStringLiteral("mouse:"));

    panel->setConnected(QStringLiteral("mouse:"), DeviceSpec{});
    EXPECT_TRUE(button("deviceDisconnectButton")->isEnabled());
    QTest::mouseClick(button("deviceDisconnectButton"), Qt::LeftButton);
    EXPECT_EQ(disconnects.count(), 1);
    panel->setDisconnected();
    EXPECT_FALSE(panel->isConnected());
    EXPECT_FALSE(button("deviceDisconnectButton")->isEnabled());
}

TEST_F(DevicePanelTest, WaypointEntryAsksForAFileAndBecomesSimPathFile) {
    QSignalSpy connects(panel.get(), &DevicePanel::connectRequested);
    int asked = 0;
    QString answer;  // "" = the user cancels
    panel->setWaypointFileChooser([&] {
        ++asked;
        return answer;
    });

    list()->setCurrentItem(itemFor(QStringLiteral("sim:path:FILE")));
    EXPECT_FALSE(button("chooseWaypointFileButton")->isHidden());
    EXPECT_TRUE(button("deviceConnectButton")->isEnabled());
    clickConnect();  // no file yet: asks; cancelled: nothing happens
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(connects.count(), 0);
    EXPECT_FALSE(panel->errorShown());

    answer = QStringLiteral("/data/paths/walk:1.txt");
    clickConnect();
    EXPECT_EQ(asked, 2);
    ASSERT_EQ(connects.count(), 1);
    EXPECT_EQ(connects.at(0).at(0).toString(), QStringLiteral("sim:path:/data/paths/walk:1.txt"));
    EXPECT_EQ(panel->uri(), QStringLiteral("sim:path:/data/paths/walk:1.txt"));
    EXPECT_EQ(itemFor(QStringLiteral("sim:path:FILE"))->data(0, Qt::UserRole + 1).toString(),
              QStringLiteral("sim:path:/data/paths/walk:1.txt"));

    // Chosen once, the entry keeps its file: selecting it again gives the same URI without asking.
    list()->setCurrentItem(itemFor(QStringLiteral("sim:press")));
    EXPECT_TRUE(button("chooseWaypointFileButton")->isHidden());
    list()->setCurrentItem(itemFor(QStringLiteral("sim:path:FILE")));
    clickConnect();
    EXPECT_EQ(asked, 2);
    ASSERT_EQ(connects.count(), 2);
    EXPECT_EQ(connects.at(1).at(0).toString(), QStringLiteral("sim:path:/data/paths/walk:1.txt"));

    // The button picks another file.
    answer = QStringLiteral("/other.txt");
    QTest::mouseClick(button("chooseWaypointFileButton"), Qt::LeftButton);
    EXPECT_EQ(panel->uri(), QStringLiteral("sim:path:/other.txt"));

    // Connected to it (in a narrow dock): the entry shows the file's name and is marked.
    panel->setConnected(QStringLiteral("sim:path:/data/paths/walk:1.txt"), testSpec());
    EXPECT_EQ(panel->uri(), QStringLiteral("sim:path:/data/paths/walk:1.txt"));
    EXPECT_EQ(list()->currentItem(), itemFor(QStringLiteral("sim:path:FILE")));
    EXPECT_TRUE(itemFor(QStringLiteral("sim:path:FILE"))->font(0).bold());
    EXPECT_EQ(itemFor(QStringLiteral("sim:path:FILE"))->text(0), QStringLiteral("sim:path:walk:1.txt"));
    panel->resize(240, 700);
    render(QStringLiteral("device_panel_path_narrow"));
}

TEST_F(DevicePanelTest, SpecFieldsShowTheValuesGiven) {
    panel->setConnected(QStringLiteral("sim:stroke"), testSpec());
    EXPECT_TRUE(panel->isConnected());
    EXPECT_EQ(panel->connectedUri(), QStringLiteral("sim:stroke"));
    EXPECT_EQ(label("deviceConnectionLabel"), QStringLiteral("sim:stroke"));
    EXPECT_EQ(label("specNameLabel"), QStringLiteral("Test Falcon"));
    EXPECT_EQ(label("specMaxForceLabel"), QStringLiteral("8.5 N"));
    EXPECT_EQ(label("specMaxStiffnessLabel"), QStringLiteral("2.5 N/mm"));
    EXPECT_EQ(label("specMaxDampingLabel"), QStringLiteral("0.012 N·s/mm"));
    EXPECT_EQ(label("specWorkspaceLabel"), QStringLiteral("60 mm"));
    EXPECT_EQ(label("specActuatedLabel"), QStringLiteral("yes"));
    EXPECT_EQ(label("specButtonsLabel"), QStringLiteral("3"));

    DeviceSpec mouse;
    mouse.name = "mouse";
    mouse.actuated = false;
    panel->setConnected(QStringLiteral("mouse:"), mouse);
    EXPECT_EQ(label("specActuatedLabel"), QStringLiteral("no (input only)"));
    EXPECT_EQ(label("specButtonsLabel"), QStringLiteral("0"));

    panel->setDisconnected();
    EXPECT_EQ(label("specNameLabel"), QStringLiteral("—"));
    EXPECT_EQ(label("specMaxForceLabel"), QStringLiteral("—"));
}

TEST_F(DevicePanelTest, SnapshotShowsStatePhaseFlagsForceAndTool) {
    auto s = snapshot(DeviceState::Ready, SafetyPhase::RampIn, kSafetyRamping | kSafetyClamped);
    s->forceN = glm::vec3(0.0f, 3.0f, 4.0f);
    s->toolTipMm = glm::vec3(1.5f, -2.0f, 30.0f);
    panel->updateFromSnapshot(*s);
    EXPECT_EQ(label("deviceStateLabel"), QString::fromLatin1(deviceStateName(DeviceState::Ready)));
    EXPECT_EQ(label("safetyPhaseLabel"), QString::fromLatin1(safetyPhaseName(SafetyPhase::RampIn)));
    EXPECT_EQ(label("safetyFlagsLabel"), QStringLiteral("ramping, clamped"));
    EXPECT_TRUE(label("deviceForceLabel").startsWith(QStringLiteral("5.00 N"))) << label("deviceForceLabel").toStdString();
    EXPECT_EQ(label("toolPositionLabel"), QStringLiteral("(1.5, -2.0, 30.0) mm"));

    EXPECT_EQ(DevicePanel::safetyFlagsText(0), QStringLiteral("none"));
    EXPECT_EQ(DevicePanel::safetyFlagsText(kSafetyHeldOff | kSafetyRamping | kSafetyClamped | kSafetyStaleSample |
                                           kSafetyOverrun | kSafetyNotReady),
              QStringLiteral("held off, ramping, clamped, stale sample, overrun, not ready"));
}

// The model asked for more than the device can give: the readout says the force was clipped.
TEST_F(DevicePanelTest, ForceAboveTheDeviceMaximumIsShownAsClipped) {
    DeviceSpec spec = testSpec();
    spec.maxForceN = 3.3;
    panel->setConnected(QStringLiteral("sim:stroke"), spec);
    auto s = snapshot(DeviceState::Ready, SafetyPhase::Armed, kSafetyClamped);
    s->commandedForceN = glm::vec3(0.0f, 0.0f, 4.12f);
    s->forceN = glm::vec3(0.0f, 0.0f, 3.3f);
    panel->updateFromSnapshot(*s);
    EXPECT_TRUE(panel->forceClipped());
    EXPECT_TRUE(panel->forceText().startsWith(QStringLiteral("3.30 N"))) << panel->forceText().toStdString();
    EXPECT_TRUE(panel->forceText().contains(QStringLiteral("clipped at device max 3.30 N (the model asked 4.12 N)")))
        << panel->forceText().toStdString();

    // Below the maximum: the plain reading.
    s = snapshot(DeviceState::Ready, SafetyPhase::Armed, 0);
    s->commandedForceN = glm::vec3(0.0f, 0.0f, 1.2f);
    s->forceN = s->commandedForceN;
    panel->updateFromSnapshot(*s);
    EXPECT_FALSE(panel->forceClipped());
    EXPECT_FALSE(panel->forceText().contains(QStringLiteral("clipped"))) << panel->forceText().toStdString();

    // Above the spec's maximum without the filter's flag (a device that clips itself) is clipped too.
    s->commandedForceN = glm::vec3(0.0f, 0.0f, 5.0f);
    s->forceN = glm::vec3(0.0f, 0.0f, 3.3f);
    panel->updateFromSnapshot(*s);
    EXPECT_TRUE(panel->forceClipped());
    render(QStringLiteral("clipped"));
}

// The Connect button keeps its place whichever entry (long or short description, with or without
// the waypoint file button) is chosen.
TEST_F(DevicePanelTest, ConnectButtonStaysPutWhicheverEntryIsChosen) {
    panel->resize(320, 720);  // narrow: the descriptions wrap onto different numbers of lines
    render(QStringLiteral("narrow"));
    QPushButton* connect = button("deviceConnectButton");
    std::optional<QPoint> first;
    QSet<int> descriptionHeights;
    for (int i = 0; i < list()->topLevelItemCount(); ++i) {
        list()->setCurrentItem(list()->topLevelItem(i));
        panel->layout()->activate();
        QCoreApplication::processEvents();
        const QPoint at = connect->mapTo(panel.get(), QPoint(0, 0));
        descriptionHeights.insert(panel->findChild<QLabel*>(QStringLiteral("deviceDescriptionLabel"))->height());
        if (!first) first = at;
        EXPECT_EQ(at, *first) << "entry " << list()->topLevelItem(i)->text(0).toStdString();
    }
    EXPECT_GT(descriptionHeights.size(), 1) << "the descriptions should differ in height at this width";
}

TEST_F(DevicePanelTest, UnplugMidSessionRaisesTheBannerUntilReadyAndArmed) {
    // Not connected: a Disconnected device is no surprise.
    panel->updateFromSnapshot(*snapshot(DeviceState::Disconnected, SafetyPhase::HoldOff, kSafetyNotReady));
    EXPECT_FALSE(panel->warningShown());

    panel->setConnected(QStringLiteral("sim:stroke"), testSpec());
    panel->updateFromSnapshot(*snapshot(DeviceState::Ready, SafetyPhase::HoldOff, kSafetyHeldOff));
    EXPECT_FALSE(panel->warningShown()) << "the hold-off at start is normal";
    panel->updateFromSnapshot(*snapshot(DeviceState::Ready, SafetyPhase::Armed));
    EXPECT_FALSE(panel->warningShown());

    // Unplugged.
    panel->updateFromSnapshot(*snapshot(DeviceState::Disconnected, SafetyPhase::HoldOff, kSafetyNotReady));
    EXPECT_TRUE(panel->warningShown());
    EXPECT_TRUE(panel->warningText().contains(QStringLiteral("sim:stroke")));
    EXPECT_TRUE(panel->warningText().contains(QStringLiteral("disconnected")));
    const QImage unplugged = render(QStringLiteral("device_panel_unplugged"));

    // Back, but the safety filter holds forces off, then ramps: the banner stays.
    panel->updateFromSnapshot(*snapshot(DeviceState::Opening, SafetyPhase::HoldOff, kSafetyNotReady));
    EXPECT_TRUE(panel->warningShown());
    panel->updateFromSnapshot(*snapshot(DeviceState::Ready, SafetyPhase::HoldOff, kSafetyHeldOff));
    EXPECT_TRUE(panel->warningShown());
    EXPECT_TRUE(panel->warningText().contains(QStringLiteral("held off")));
    render(QStringLiteral("device_panel_held_off"));
    panel->updateFromSnapshot(*snapshot(DeviceState::Ready, SafetyPhase::RampIn, kSafetyRamping));
    EXPECT_TRUE(panel->warningShown());

    // Ready and armed: gone.
    panel->updateFromSnapshot(*snapshot(DeviceState::Ready, SafetyPhase::Armed));
    EXPECT_FALSE(panel->warningShown());

    // A fault does the same; an explicit disconnect clears it.
    panel->updateFromSnapshot(*snapshot(DeviceState::Fault, SafetyPhase::HoldOff, kSafetyNotReady));
    EXPECT_TRUE(panel->warningShown());
    EXPECT_TRUE(panel->warningText().contains(QStringLiteral("fault")));
    panel->setDisconnected();
    EXPECT_FALSE(panel->warningShown());

    // The banner is drawn: a red band at the top of the panel with light (bold) text on it.
    int red = 0;
    int light = 0;
    for (int y = 0; y < std::min(unplugged.height(), 80); ++y)
        for (int x = 0; x < unplugged.width(); ++x) {
            const QRgb p = unplugged.pixel(x, y);
            if (std::abs(qRed(p) - 0xc6) < 12 && std::abs(qGreen(p) - 0x28) < 12 && std::abs(qBlue(p) - 0x28) < 12) ++red;
            if (qRed(p) > 230 && qGreen(p) > 230 && qBlue(p) > 230) ++light;
        }
    EXPECT_GT(red, 2000);
    EXPECT_GT(light, 50);
}

TEST_F(DevicePanelTest, ShowErrorKeepsTheConnectionAndConnectClearsIt) {
    panel->setConnected(QStringLiteral("sim:press"), testSpec());
    panel->showError(QStringLiteral("device URI 'sim:path:/x': cannot open"));
    EXPECT_TRUE(panel->errorShown());
    EXPECT_TRUE(panel->isConnected());
    EXPECT_EQ(panel->connectedUri(), QStringLiteral("sim:press"));
    panel->setConnected(QStringLiteral("sim:scan"), testSpec());
    EXPECT_FALSE(panel->errorShown());

    auto s = snapshot(DeviceState::Ready, SafetyPhase::Armed);
    s->forceN = glm::vec3(0.4f, -1.2f, 0.9f);
    s->toolTipMm = glm::vec3(12.0f, -3.5f, 41.0f);
    list()->setCurrentItem(itemFor(QStringLiteral("sim:scan")));
    panel->updateFromSnapshot(*s);
    const QImage connected = render(QStringLiteral("device_panel_connected"));
    EXPECT_FALSE(connected.isNull());
    EXPECT_FALSE(panel->warningShown());
}

// Real hardware opens on a worker thread (a Falcon's firmware upload takes seconds): the window
// answers at once, the running session keeps its device until the new one is open, and a failed
// open is shown in the Device dock. A registered factory stands in for the hardware.
namespace {

class SlowDevice final : public test::StubDevice {
public:
    SlowDevice(std::shared_ptr<std::atomic<bool>> release, bool succeed) : mRelease(std::move(release)), mSucceed(succeed) {
        mState = DeviceState::Disconnected;
    }
    bool open() override {
        for (int waitedMs = 0; waitedMs < 10000 && !mRelease->load(); ++waitedMs)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        mState = mSucceed ? DeviceState::Ready : DeviceState::Fault;
        return mSucceed;
    }
    std::string lastError() const override { return mSucceed ? std::string() : "falcon:0: firmware file missing (test)"; }

private:
    std::shared_ptr<std::atomic<bool>> mRelease;
    bool mSucceed;
};

}  // namespace

// End to end: a tissue stiff enough that the stroke's press asks more than sim:stroke's 3.3 N; the
// safety filter clamps it, and the Device dock and the status bar say the force was clipped.
TEST(DevicePanelWindow, AForceClampedToTheDeviceMaximumIsShownAsClipped) {
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window.setDeviceUri(QStringLiteral("sim:stroke")), QString());
    ASSERT_EQ(window.loadMesh(QString::fromStdString(findResource(kDefaultMesh))), QString());
    TissuePreset stiff = window.session().preset();
    stiff.model.slopeRing.springStiffnessNPerMm *= 4.0;  // rendered stiffness x4: several newtons at the press's depth
    window.parameterPanel()->setPreset(stiff);
    ASSERT_EQ(window.applyPreset(stiff), QString());
    bool clipped = false, statusSaidSo = true;
    for (int ticks = 0; ticks < 8000 && !clipped; ticks += 50) {
        window.advanceTicks(50);
        if (window.devicePanel()->forceClipped()) {
            clipped = true;
            statusSaidSo = window.statusText().contains(QStringLiteral("clipped at device max"));
        }
    }
    ASSERT_TRUE(clipped) << window.devicePanel()->forceText().toStdString();
    EXPECT_TRUE(window.devicePanel()->forceText().contains(QStringLiteral("clipped at device max 3.30 N")))
        << window.devicePanel()->forceText().toStdString();
    EXPECT_TRUE(statusSaidSo) << window.statusText().toStdString();
}

TEST(DevicePanelWindow, HardwareOpensOffTheGuiThreadAndFailuresAreShown) {
    auto release = std::make_shared<std::atomic<bool>>(false);
    bool succeed = true;
    registerDeviceFactory(DeviceKind::Falcon, [release, &succeed](const DeviceUri&, std::string&) {
        return std::unique_ptr<HapticDevice>(new SlowDevice(release, succeed));
    });
    {
        MainWindow window(RendererChoice::Software, LoopMode::Threaded);
        ASSERT_EQ(window.setDeviceUri(QStringLiteral("sim:stroke")), QString());
        ASSERT_EQ(window.loadMesh(QString::fromStdString(findResource(kDefaultMesh))), QString());
        ASSERT_TRUE(window.session().threadRunning());

        // Returns while the device is still opening; the loop keeps the old device meanwhile.
        EXPECT_EQ(window.setDeviceUri(QStringLiteral("falcon:0")), QString());
        EXPECT_TRUE(window.deviceOpening());
        EXPECT_EQ(window.session().deviceUri(), "sim:stroke");
        EXPECT_FALSE(window.devicePanel()->isEnabled());
        // A second request while one opens is refused with the reason.
        EXPECT_FALSE(window.setDeviceUri(QStringLiteral("falcon:1")).isEmpty());
        release->store(true);
        ASSERT_TRUE(QTest::qWaitFor([&] { return !window.deviceOpening(); }, 15000));
        EXPECT_EQ(window.session().deviceUri(), "falcon:0");
        EXPECT_TRUE(window.devicePanel()->isEnabled());

        // A failing open: the error reaches the Device dock; the session keeps its device.
        succeed = false;
        EXPECT_EQ(window.setDeviceUri(QStringLiteral("falcon:2")), QString());
        ASSERT_TRUE(QTest::qWaitFor([&] { return !window.deviceOpening(); }, 15000));
        EXPECT_EQ(window.session().deviceUri(), "falcon:0");
        EXPECT_TRUE(window.devicePanel()->errorText().contains(QStringLiteral("firmware file missing")))
            << window.devicePanel()->errorText().toStdString();

        // Closing the window while a device opens waits for it, then goes.
        release->store(false);
        succeed = true;
        EXPECT_EQ(window.setDeviceUri(QStringLiteral("falcon:3")), QString());
        std::thread releaser([release] {
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            release->store(true);
        });
        window.close();
        releaser.join();
    }
    unregisterDeviceFactory(DeviceKind::Falcon);
}
