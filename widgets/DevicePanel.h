#pragma once
// The device panel (docs/devices.md): choose a device by URI, ask to connect or disconnect, and watch
// its state, the safety filter and the force. It does not own the haptic loop: it emits requests,
// and the main window answers with setConnected / setDisconnected / showError and feeds it the
// loop's snapshots. A red banner warns when a device that should be connected is lost (unplug,
// fault) and stays until the device is Ready again and the safety filter has armed.

#include "device/HapticDevice.h"

#include <QString>
#include <QWidget>

#include <cstdint>
#include <functional>

class QLabel;
class QLineEdit;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace palpate {

struct HapticSnapshot;

class DevicePanel final : public QWidget {
    Q_OBJECT
public:
    /// Returns the chosen waypoint file, or "" when the user cancelled.
    using FileChooser = std::function<QString()>;

    explicit DevicePanel(QWidget* parent = nullptr);

    /// The URI Connect would request (the URI field, trimmed).
    QString uri() const;
    /// Puts `uri` in the URI field and selects the list entry that gives it, if any (a
    /// `sim:path:/some/file` becomes the file of the `sim:path:FILE` entry).
    void setUri(const QString& uri);
    /// Replaces the file dialog of the `sim:path:FILE` entry (tests, scripted use).
    void setWaypointFileChooser(FileChooser chooser);

    /// The main window's answers to connectRequested / disconnectRequested.
    void setConnected(const QString& uri, const DeviceSpec& spec);
    void setDisconnected();
    /// Shows `message` (which names the URI and the problem) under the URI field. The connection
    /// state does not change: a failed switch keeps the previous device.
    void showError(const QString& message);
    void clearError();

    /// Shows the device state, the safety filter's phase and flags, the force (marked "clipped at
    /// device max" when the model asked for more than the device's maximum) and the tool from one
    /// snapshot, and raises or clears the warning banner. Cheap enough for every frame.
    void updateFromSnapshot(const HapticSnapshot& snapshot);

    bool isConnected() const { return mConnected; }
    const QString& connectedUri() const { return mConnectedUri; }
    bool warningShown() const;
    QString warningText() const;
    bool errorShown() const;
    QString errorText() const;
    /// The force readout as shown (for tests and the accessibility tree).
    QString forceText() const;
    bool forceClipped() const;

    /// The SafetyFlag bits in words ("held off, ramping"), or "none".
    static QString safetyFlagsText(std::uint32_t flags);

signals:
    void connectRequested(const QString& uri);
    void disconnectRequested();

public slots:
    /// Validates the URI (a `sim:path:FILE` entry without a file asks for one first) and emits
    /// connectRequested, or shows why not and emits nothing.
    void requestConnect();
    void requestDisconnect();
    /// Opens the waypoint file chooser for the `…FILE` entry; true when a file was chosen.
    bool chooseWaypointFile();

private:
    void buildList();
    void onCurrentItemChanged(QTreeWidgetItem* item);
    void onUriEdited(const QString& text);
    QTreeWidgetItem* fileEntry() const;
    void setEntryFile(QTreeWidgetItem* entry, const QString& path);
    void markConnectedEntry();
    void showSpec(const DeviceSpec* spec);
    void showBanner(const QString& text);
    void hideBanner();
    void updateButtons();

    QLabel* mBanner = nullptr;
    QTreeWidget* mList = nullptr;
    QLabel* mDescriptionLabel = nullptr;
    QPushButton* mChooseFileButton = nullptr;
    QLineEdit* mUriEdit = nullptr;
    QLabel* mErrorLabel = nullptr;
    QPushButton* mConnectButton = nullptr;
    QPushButton* mDisconnectButton = nullptr;

    QLabel* mConnectionLabel = nullptr;
    QLabel* mSpecNameLabel = nullptr;
    QLabel* mSpecForceLabel = nullptr;
    QLabel* mSpecStiffnessLabel = nullptr;
    QLabel* mSpecDampingLabel = nullptr;
    QLabel* mSpecWorkspaceLabel = nullptr;
    QLabel* mSpecActuatedLabel = nullptr;
    QLabel* mSpecButtonsLabel = nullptr;

    QLabel* mStateLabel = nullptr;
    QLabel* mPhaseLabel = nullptr;
    QLabel* mFlagsLabel = nullptr;
    QLabel* mForceLabel = nullptr;
    QLabel* mToolLabel = nullptr;

    FileChooser mFileChooser;
    bool mSyncingUri = false;      ///< setting the field from the list: do not re-select
    bool mConnected = false;       ///< the main window said a device is connected
    QString mConnectedUri;
    bool mLossLatched = false;     ///< the device was lost while connected; cleared at Ready+Armed
    double mDeviceMaxForceN = 0.0;  ///< the connected device's spec; 0: none known
};

}  // namespace palpate
