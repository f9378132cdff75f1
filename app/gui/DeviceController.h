#pragma once
// Switches the session's haptic device: the Device dock's Connect and Disconnect, Simulation >
// Device, MainWindow::setDeviceUri. Real hardware opens on a worker thread while the loop runs
// with the old device (docs/devices.md); the window hears of every switch (the switched signal).

#include "app/gui/HapticSession.h"

#include <QObject>
#include <QString>

#include <string>

class QActionGroup;
class QMainWindow;
class QMenu;
class QThread;

namespace palpate {

class DevicePanel;
class ExerciseController;

class DeviceController final : public QObject {
    Q_OBJECT
public:
    /// Its dialogs and messages are `window`'s; the Device dock's `panel` connects and disconnects
    /// through it; while `exercises` runs one, the device stays.
    DeviceController(QMainWindow& window, HapticSession& session, DevicePanel& panel,
                     const ExerciseController& exercises, QObject* parent = nullptr);

    /// Switches the device; see MainWindow::setDeviceUri. "" or an error naming the URI; no dialog.
    QString setDeviceUri(const QString& uri);
    /// A device is being opened on the worker thread.
    bool opening() const { return mOpenThread != nullptr; }
    /// Waits for a device being opened (it is closed with its job): before the window goes.
    void waitForOpening();
    /// Simulation > Device: the simulated devices, the current one checked.
    void addDeviceMenu(QMenu* simulation);
    /// During an exercise the device stays as the exercise set it: the dock and the menu are off.
    void setSwitchingEnabled(bool enabled);

signals:
    /// A switch to `uri` ended: `ok`, or failed (the error is the caller's to show).
    void switched(const QString& uri, bool ok);

private:
    QString openInBackground(const QString& uri);
    /// After a switch (or its failure): the menu, the Device dock, then switched().
    void deviceSwitched(const QString& uri, const std::string& error);
    /// Checks the menu's entry of the session's device.
    void checkCurrentDevice();

    QMainWindow& mWindow;
    HapticSession& mSession;
    DevicePanel& mPanel;
    const ExerciseController& mExercises;
    QActionGroup* mDeviceGroup = nullptr;
    QThread* mOpenThread = nullptr;  // a hardware device being opened (openInBackground)
    QString mOpeningUri;
};

}  // namespace palpate
