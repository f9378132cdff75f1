#include "app/gui/DeviceController.h"

#include "base/concurrency/HandOff.h"

#include "app/gui/ExerciseController.h"
#include "device/open/DeviceUri.h"
#include "widgets/DevicePanel.h"

#include <QAction>
#include <QActionGroup>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>
#include <QThread>

#include <algorithm>
#include <array>
#include <exception>
#include <memory>

namespace palpate {

namespace {

/// The simulated devices the Device menu offers (listDeviceSchemes() also has forms that need an
/// argument, or a viewport that steers them).
constexpr std::array<const char*, 5> kMenuDevices = {"sim:press", "sim:stroke", "sim:scan", "sim:sine", "mouse:"};

}  // namespace

DeviceController::DeviceController(QMainWindow& window, HapticSession& session, DevicePanel& panel,
                                   const ExerciseController& exercises, QObject* parent)
    : QObject(parent), mWindow(window), mSession(session), mPanel(panel), mExercises(exercises) {
    connect(&mPanel, &DevicePanel::connectRequested, this, [this](const QString& uri) {
        if (const QString error = setDeviceUri(uri); !error.isEmpty()) mPanel.showError(error);
    });
    connect(&mPanel, &DevicePanel::disconnectRequested, this, [this] {
        if (const std::string error = mSession.disconnectDevice(); !error.empty())
            mPanel.showError(QString::fromStdString(error));
        else mPanel.setDisconnected();
    });
}

void DeviceController::addDeviceMenu(QMenu* simulation) {
    QMenu* devices = simulation->addMenu(tr("&Device"));
    mDeviceGroup = new QActionGroup(&mWindow);
    mDeviceGroup->setExclusive(true);
    for (const DeviceSchemeInfo& scheme : listDeviceSchemes()) {
        if (std::find(kMenuDevices.begin(), kMenuDevices.end(), scheme.uri) == kMenuDevices.end()) continue;
        const QString uri = QString::fromStdString(scheme.uri);
        QAction* action = devices->addAction(uri);
        action->setCheckable(true);
        action->setData(uri);
        action->setStatusTip(QString::fromStdString(scheme.description));
        action->setToolTip(QString::fromStdString(scheme.description));
        mDeviceGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, uri] {
            if (const QString error = setDeviceUri(uri); !error.isEmpty()) {
                QMessageBox::warning(&mWindow, tr("Cannot switch the device"), error);
                checkCurrentDevice();
            }
        });
    }
    checkCurrentDevice();
}

void DeviceController::checkCurrentDevice() {
    if (!mDeviceGroup) return;
    const QString current = QString::fromStdString(mSession.deviceUri());
    // None is checked for a URI the menu does not list (e.g. sim:path:FILE from --device).
    for (QAction* action : mDeviceGroup->actions()) action->setChecked(action->data().toString() == current);
}

void DeviceController::setSwitchingEnabled(bool enabled) {
    mPanel.setEnabled(enabled);
    if (mDeviceGroup) mDeviceGroup->setEnabled(enabled);
}

void DeviceController::waitForOpening() {
    if (mOpenThread) mOpenThread->wait();
}

QString DeviceController::setDeviceUri(const QString& uri) {
    if (HapticSession::opensSlowly(uri.toStdString()) && mSession.threadRunning()) return openInBackground(uri);
    const std::string error = mSession.setDevice(uri.toStdString());
    deviceSwitched(uri, error);
    return QString::fromStdString(error);
}

void DeviceController::deviceSwitched(const QString& uri, const std::string& error) {
    checkCurrentDevice();
    if (error.empty()) {
        std::string ignored;
        const auto device = createDeviceFromUri(uri.toStdString(), ignored);  // for its spec only
        mPanel.setConnected(uri, device ? device->spec() : DeviceSpec{});
    }
    emit switched(uri, error.empty());
}

QString DeviceController::openInBackground(const QString& uri) {
    if (mOpenThread) return tr("%1 is still being opened: wait for it first").arg(mOpeningUri);
    // Real hardware can take seconds to open (a Falcon's firmware upload, homing checks): on a
    // worker thread, so the window and the running session go on meanwhile. The old device stays
    // in the loop until the new one is open.
    struct Job {
        std::string uri;
        std::unique_ptr<HapticDevice> device;
        std::string error;
    };
    auto job = std::make_shared<Job>();
    job->uri = uri.toStdString();
    mOpeningUri = uri;
    mOpenThread = QThread::create([job] {
        try {  // no event loop catches it here: it would end the process
            job->device = openDeviceUri(job->uri, job->error);
        } catch (const std::exception& e) {
            job->error = job->uri + ": " + e.what();
        }
        handOffRelease();  // the job goes to the window through QThread::finished
    });
    mOpenThread->setParent(this);  // deleted with the window if it closes first (waitForOpening waits for it)
    connect(mOpenThread, &QThread::finished, this, [this, job] {
        handOffAcquire();
        mOpenThread->deleteLater();
        mOpenThread = nullptr;
        mPanel.setEnabled(!mExercises.running());
        std::string error = job->error;
        if (job->device) error = mSession.setOpenedDevice(job->uri, std::move(job->device));
        deviceSwitched(QString::fromStdString(job->uri), error);
        if (!error.empty()) {
            mPanel.showError(QString::fromStdString(error));
            mWindow.statusBar()->showMessage(tr("Cannot open %1: %2").arg(mOpeningUri, QString::fromStdString(error)),
                                             15000);
        } else {
            mWindow.statusBar()->showMessage(tr("%1 is connected").arg(mOpeningUri), 5000);
        }
    });
    mPanel.setEnabled(false);
    mWindow.statusBar()->showMessage(tr("Opening %1…").arg(uri));
    mOpenThread->start();
    return {};
}

}  // namespace palpate
