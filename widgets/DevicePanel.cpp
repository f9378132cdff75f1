#include "widgets/DevicePanel.h"

#include "device/open/DeviceUri.h"
#include "device/SafetyFilter.h"
#include "engine/loop/HapticSnapshot.h"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QFont>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace palpate {
namespace {

constexpr int kTemplateRole = Qt::UserRole;     ///< the URI as listDeviceSchemes gives it ("sim:path:FILE")
constexpr int kUriRole = Qt::UserRole + 1;      ///< the URI the entry gives now ("" = a file still to choose)
const QString kFilePlaceholder = QStringLiteral("FILE");

// deviceStateName and safetyPhaseName give identifiers; these entries let lupdate extract them so
// that they are translated in this panel's context (translated at run time in stateText/phaseText).
[[maybe_unused]] constexpr const char* kStateAndPhaseNames[] = {
    QT_TRANSLATE_NOOP("palpate::DevicePanel", "Disconnected"),
    QT_TRANSLATE_NOOP("palpate::DevicePanel", "Opening"),
    QT_TRANSLATE_NOOP("palpate::DevicePanel", "NeedsCalibration"),
    QT_TRANSLATE_NOOP("palpate::DevicePanel", "Ready"),
    QT_TRANSLATE_NOOP("palpate::DevicePanel", "Fault"),
    QT_TRANSLATE_NOOP("palpate::DevicePanel", "HoldOff"),
    QT_TRANSLATE_NOOP("palpate::DevicePanel", "RampIn"),
    QT_TRANSLATE_NOOP("palpate::DevicePanel", "Armed"),
};

QString translated(const char* name) {
    return QCoreApplication::translate("palpate::DevicePanel", name);
}

/// Whether a scheme entry needs a file before it is a URI (its form ends in FILE).
bool needsFile(const QString& uriTemplate) { return uriTemplate.endsWith(kFilePlaceholder); }

QString filePrefix(const QString& uriTemplate) { return uriTemplate.chopped(kFilePlaceholder.size()); }

/// Spec figures: as few digits as they need (3 N, 0.005 N·s/mm), in the user's locale.
QString specNumber(double value) { return QLocale().toString(value, 'g', 4); }

/// Live figures: fixed decimals so that the text does not jump.
QString liveNumber(double value, int decimals) {
    if (!std::isfinite(value)) return QStringLiteral("—");
    return QLocale().toString(value, 'f', decimals);
}

/// The scheme list: as tall as its rows (a handful), so that the panel has no empty list area.
class SchemeList final : public QTreeWidget {
public:
    using QTreeWidget::QTreeWidget;
    QSize sizeHint() const override { return {QTreeWidget::sizeHint().width(), contentHeight()}; }
    QSize minimumSizeHint() const override { return {QTreeWidget::minimumSizeHint().width(), contentHeight()}; }

private:
    int contentHeight() const {
        int height = 2 * frameWidth() + (header()->isHidden() ? 0 : header()->sizeHint().height());
        for (int row = 0; row < topLevelItemCount(); ++row) height += sizeHintForRow(row);
        return height;
    }
};

/// `wrap` for free text (URIs, names, flag lists); figures with units stay on one line.
QLabel* valueLabel(QWidget* parent, const char* objectName, bool wrap = false) {
    auto* label = new QLabel(QStringLiteral("—"), parent);
    label->setObjectName(QString::fromLatin1(objectName));
    label->setTextFormat(Qt::PlainText);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setWordWrap(wrap);
    return label;
}

}  // namespace

DevicePanel::DevicePanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("devicePanel"));

    mBanner = new QLabel(this);
    mBanner->setObjectName(QStringLiteral("deviceWarningBanner"));
    mBanner->setTextFormat(Qt::PlainText);
    mBanner->setWordWrap(true);
    mBanner->setStyleSheet(QStringLiteral("QLabel#deviceWarningBanner { background-color: #c62828; color: white;"
                                          " font-weight: bold; padding: 6px; border-radius: 3px; }"));
    mBanner->hide();

    // Choosing a device.
    auto* chooseBox = new QGroupBox(tr("Device"), this);
    mList = new SchemeList(chooseBox);
    mList->setObjectName(QStringLiteral("deviceList"));
    mList->setColumnCount(2);
    mList->setHeaderLabels({tr("URI"), tr("Description")});
    mList->setRootIsDecorated(false);
    mList->setUniformRowHeights(true);
    mList->setSelectionMode(QAbstractItemView::SingleSelection);
    mList->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    mList->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    mList->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    mList->header()->setStretchLastSection(true);
    mList->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    mList->setToolTip(tr("The devices this build knows. Double-click one to connect."));
    buildList();

    // The list elides descriptions in a narrow dock: the selected one is shown whole under it.
    mDescriptionLabel = new QLabel(chooseBox);
    mDescriptionLabel->setObjectName(QStringLiteral("deviceDescriptionLabel"));
    mDescriptionLabel->setTextFormat(Qt::PlainText);
    mDescriptionLabel->setWordWrap(true);
    mDescriptionLabel->setForegroundRole(QPalette::PlaceholderText);
    mDescriptionLabel->hide();

    mChooseFileButton = new QPushButton(tr("Waypoint File…"), chooseBox);
    mChooseFileButton->setObjectName(QStringLiteral("chooseWaypointFileButton"));
    mChooseFileButton->setToolTip(tr("Choose the waypoint file the simulated device follows"));
    mChooseFileButton->hide();  // shown with the entry that needs a file

    auto* uriLabel = new QLabel(tr("&URI:"), chooseBox);
    mUriEdit = new QLineEdit(chooseBox);
    mUriEdit->setObjectName(QStringLiteral("deviceUriEdit"));
    mUriEdit->setPlaceholderText(tr("Type a device URI, e.g. sim:stroke"));
    mUriEdit->setClearButtonEnabled(true);
    uriLabel->setBuddy(mUriEdit);

    mErrorLabel = new QLabel(chooseBox);
    mErrorLabel->setObjectName(QStringLiteral("deviceErrorLabel"));
    mErrorLabel->setTextFormat(Qt::PlainText);
    mErrorLabel->setWordWrap(true);
    mErrorLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mErrorLabel->setStyleSheet(QStringLiteral("QLabel#deviceErrorLabel { color: #b71c1c; }"));
    mErrorLabel->hide();

    mConnectButton = new QPushButton(tr("&Connect"), chooseBox);
    mConnectButton->setObjectName(QStringLiteral("deviceConnectButton"));
    mConnectButton->setToolTip(tr("Connect to the device the URI names (switching from the current one)"));
    mDisconnectButton = new QPushButton(tr("&Disconnect"), chooseBox);
    mDisconnectButton->setObjectName(QStringLiteral("deviceDisconnectButton"));
    mDisconnectButton->setToolTip(tr("Stop sending forces and release the device"));

    // The buttons keep their place whichever entry is chosen: the URI and the button row come right
    // after the list (the file button shares the row, so showing it moves nothing), and the texts
    // that vary in length, the error and the wrapped description, come below them.
    auto* uriRow = new QHBoxLayout;
    uriRow->addWidget(uriLabel);
    uriRow->addWidget(mUriEdit, 1);
    auto* buttonRow = new QHBoxLayout;
    buttonRow->addWidget(mChooseFileButton);
    buttonRow->addStretch(1);
    buttonRow->addWidget(mConnectButton);
    buttonRow->addWidget(mDisconnectButton);
    auto* chooseLayout = new QVBoxLayout(chooseBox);
    chooseLayout->addWidget(mList);
    chooseLayout->addLayout(uriRow);
    chooseLayout->addLayout(buttonRow);
    chooseLayout->addWidget(mErrorLabel);
    chooseLayout->addWidget(mDescriptionLabel);

    // What the connected device can do.
    auto* specBox = new QGroupBox(tr("Connected Device"), this);
    mConnectionLabel = valueLabel(specBox, "deviceConnectionLabel", true);
    mSpecNameLabel = valueLabel(specBox, "specNameLabel", true);
    mSpecForceLabel = valueLabel(specBox, "specMaxForceLabel");
    mSpecStiffnessLabel = valueLabel(specBox, "specMaxStiffnessLabel");
    mSpecDampingLabel = valueLabel(specBox, "specMaxDampingLabel");
    mSpecWorkspaceLabel = valueLabel(specBox, "specWorkspaceLabel");
    mSpecActuatedLabel = valueLabel(specBox, "specActuatedLabel");
    mSpecButtonsLabel = valueLabel(specBox, "specButtonsLabel");
    auto* specLayout = new QFormLayout(specBox);
    specLayout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    specLayout->addRow(tr("URI:"), mConnectionLabel);
    specLayout->addRow(tr("Name:"), mSpecNameLabel);
    specLayout->addRow(tr("Max force:"), mSpecForceLabel);
    specLayout->addRow(tr("Max stiffness:"), mSpecStiffnessLabel);
    specLayout->addRow(tr("Max damping:"), mSpecDampingLabel);
    specLayout->addRow(tr("Workspace radius:"), mSpecWorkspaceLabel);
    specLayout->addRow(tr("Actuated:"), mSpecActuatedLabel);
    specLayout->addRow(tr("Buttons:"), mSpecButtonsLabel);

    // What it is doing now (from the loop's snapshots).
    auto* stateBox = new QGroupBox(tr("State"), this);
    mStateLabel = valueLabel(stateBox, "deviceStateLabel");
    mPhaseLabel = valueLabel(stateBox, "safetyPhaseLabel");
    mFlagsLabel = valueLabel(stateBox, "safetyFlagsLabel", true);
    mForceLabel = valueLabel(stateBox, "deviceForceLabel", true);
    mToolLabel = valueLabel(stateBox, "toolPositionLabel", true);
    mStateLabel->setToolTip(tr("The device's state as the haptic loop last saw it"));
    mPhaseLabel->setToolTip(tr("The safety filter: holding forces off until the command is small, ramping in, or armed"));
    mFlagsLabel->setToolTip(tr("Why the force sent differs from the force the model asked for"));
    mForceLabel->setToolTip(tr("Force sent to the device (after the safety filter); marked when the model asked "
                               "for more than the device's maximum force and the filter clipped it"));
    mToolLabel->setToolTip(tr("Tool tip position in the scene's frame"));
    auto* stateLayout = new QFormLayout(stateBox);
    stateLayout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    stateLayout->addRow(tr("Device:"), mStateLabel);
    stateLayout->addRow(tr("Safety:"), mPhaseLabel);
    stateLayout->addRow(tr("Flags:"), mFlagsLabel);
    stateLayout->addRow(tr("Force:"), mForceLabel);
    stateLayout->addRow(tr("Tool:"), mToolLabel);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(mBanner);
    layout->addWidget(chooseBox);
    layout->addWidget(specBox);
    layout->addWidget(stateBox);
    layout->addStretch(1);

    connect(mList, &QTreeWidget::currentItemChanged, this,
            [this](QTreeWidgetItem* current, QTreeWidgetItem*) { onCurrentItemChanged(current); });
    connect(mList, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem*, int) { requestConnect(); });
    connect(mChooseFileButton, &QPushButton::clicked, this, [this] { chooseWaypointFile(); });
    connect(mUriEdit, &QLineEdit::textEdited, this, &DevicePanel::onUriEdited);
    connect(mUriEdit, &QLineEdit::textChanged, this, [this] { updateButtons(); });
    connect(mUriEdit, &QLineEdit::returnPressed, this, &DevicePanel::requestConnect);
    connect(mConnectButton, &QPushButton::clicked, this, &DevicePanel::requestConnect);
    connect(mDisconnectButton, &QPushButton::clicked, this, &DevicePanel::requestDisconnect);

    showSpec(nullptr);
    updateButtons();
}

void DevicePanel::buildList() {
    for (const DeviceSchemeInfo& scheme : listDeviceSchemes()) {
        const QString uriTemplate = QString::fromStdString(scheme.uri);
        const QString description = QString::fromStdString(scheme.description);
        auto* item = new QTreeWidgetItem(mList, {uriTemplate, description});
        item->setData(0, kTemplateRole, uriTemplate);
        item->setData(0, kUriRole, needsFile(uriTemplate) ? QString() : uriTemplate);
        item->setToolTip(0, description);
        item->setToolTip(1, description);
    }
}

QTreeWidgetItem* DevicePanel::fileEntry() const {
    QTreeWidgetItem* item = mList->currentItem();
    return item && needsFile(item->data(0, kTemplateRole).toString()) ? item : nullptr;
}

QString DevicePanel::uri() const { return mUriEdit->text().trimmed(); }

void DevicePanel::setUri(const QString& uri) {
    const QString text = uri.trimmed();
    // A URI of a file entry (sim:path:/some/file) becomes that entry's file.
    for (int i = 0; i < mList->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = mList->topLevelItem(i);
        const QString uriTemplate = item->data(0, kTemplateRole).toString();
        if (!needsFile(uriTemplate)) continue;
        const QString prefix = filePrefix(uriTemplate);
        if (text.size() > prefix.size() && text.startsWith(prefix)) setEntryFile(item, text.mid(prefix.size()));
    }
    mUriEdit->setText(text);
    onUriEdited(text);
}

void DevicePanel::setEntryFile(QTreeWidgetItem* entry, const QString& path) {
    const QString prefix = filePrefix(entry->data(0, kTemplateRole).toString());
    const QString uri = prefix + path;
    entry->setData(0, kUriRole, uri);
    entry->setText(0, prefix + QFileInfo(path).fileName());
    entry->setToolTip(0, uri);
}

void DevicePanel::markConnectedEntry() {
    for (int i = 0; i < mList->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = mList->topLevelItem(i);
        QFont font = item->font(0);
        font.setBold(mConnected && item->data(0, kUriRole).toString() == mConnectedUri);
        item->setFont(0, font);
    }
}

void DevicePanel::setWaypointFileChooser(FileChooser chooser) { mFileChooser = std::move(chooser); }

void DevicePanel::onCurrentItemChanged(QTreeWidgetItem* item) {
    mChooseFileButton->setVisible(item && needsFile(item->data(0, kTemplateRole).toString()));
    mDescriptionLabel->setText(item ? item->text(1) : QString());
    mDescriptionLabel->setVisible(item != nullptr);
    if (!mSyncingUri && item) {
        mUriEdit->setText(item->data(0, kUriRole).toString());
        clearError();
    }
    updateButtons();
}

void DevicePanel::onUriEdited(const QString& text) {
    clearError();
    const QString typed = text.trimmed();
    QTreeWidgetItem* match = nullptr;
    for (int i = 0; i < mList->topLevelItemCount() && !typed.isEmpty(); ++i) {
        QTreeWidgetItem* item = mList->topLevelItem(i);
        if (item->data(0, kUriRole).toString() == typed) {
            match = item;
            break;
        }
    }
    mSyncingUri = true;
    if (match) {
        mList->setCurrentItem(match);
    } else {
        mList->setCurrentItem(nullptr);
        mList->clearSelection();
    }
    mSyncingUri = false;
    updateButtons();
}

bool DevicePanel::chooseWaypointFile() {
    QTreeWidgetItem* entry = nullptr;
    for (int i = 0; i < mList->topLevelItemCount() && !entry; ++i)
        if (needsFile(mList->topLevelItem(i)->data(0, kTemplateRole).toString())) entry = mList->topLevelItem(i);
    if (!entry) return false;

    const QString uriTemplate = entry->data(0, kTemplateRole).toString();
    const QString prefix = filePrefix(uriTemplate);
    QString path;
    if (mFileChooser) {
        path = mFileChooser();
    } else {
        const QString previous = entry->data(0, kUriRole).toString();
        const QString startDir = previous.isEmpty() ? QString() : QFileInfo(previous.mid(prefix.size())).absolutePath();
        path = QFileDialog::getOpenFileName(this, tr("Choose a Waypoint File"), startDir,
                                            tr("Waypoint files (*.txt *.csv *.tsv);;All files (*)"));
    }
    if (path.isEmpty()) return false;

    const QString uri = prefix + path;
    setEntryFile(entry, path);
    mSyncingUri = true;
    mList->setCurrentItem(entry);
    mSyncingUri = false;
    mChooseFileButton->show();
    mUriEdit->setText(uri);
    clearError();
    updateButtons();
    return true;
}

void DevicePanel::requestConnect() {
    QString text = uri();
    // A file entry (selected without a file, or its placeholder typed as is) asks for the file first.
    const std::vector<DeviceSchemeInfo> schemes = listDeviceSchemes();
    const bool placeholderTyped = std::any_of(schemes.begin(), schemes.end(), [&](const DeviceSchemeInfo& s) {
        const QString t = QString::fromStdString(s.uri);
        return needsFile(t) && t == text;
    });
    if ((text.isEmpty() && fileEntry()) || placeholderTyped) {
        if (!chooseWaypointFile()) return;
        text = uri();
    }
    if (text.isEmpty()) {
        showError(tr("No device URI: choose a device in the list or type a URI."));
        return;
    }
    DeviceUri parsed;
    std::string error;
    if (!(error = parseDeviceUri(text.toStdString(), parsed)).empty()) {
        showError(tr("Cannot connect: %1").arg(QString::fromStdString(error)));
        return;
    }
    clearError();
    emit connectRequested(text);
}

void DevicePanel::requestDisconnect() {
    clearError();
    emit disconnectRequested();
}

void DevicePanel::setConnected(const QString& uri, const DeviceSpec& spec) {
    mConnected = true;
    mConnectedUri = uri;
    clearError();
    setUri(uri);
    markConnectedEntry();
    mConnectionLabel->setText(uri);
    mDeviceMaxForceN = std::isfinite(spec.maxForceN) && spec.maxForceN > 0.0 ? spec.maxForceN : 0.0;
    showSpec(&spec);
    if (mLossLatched) showBanner(tr("%1 is connected again: forces stay off until the safety filter has armed.").arg(uri));
    updateButtons();
}

void DevicePanel::setDisconnected() {
    mConnected = false;
    mConnectedUri.clear();
    mDeviceMaxForceN = 0.0;
    mLossLatched = false;
    hideBanner();
    markConnectedEntry();
    mConnectionLabel->setText(tr("Not connected"));
    showSpec(nullptr);
    updateButtons();
}

void DevicePanel::showError(const QString& message) {
    mErrorLabel->setText(message);
    mErrorLabel->setVisible(!message.isEmpty());
}

void DevicePanel::clearError() {
    mErrorLabel->clear();
    mErrorLabel->hide();
}

bool DevicePanel::errorShown() const { return !mErrorLabel->isHidden(); }
QString DevicePanel::errorText() const { return mErrorLabel->text(); }
bool DevicePanel::warningShown() const { return !mBanner->isHidden(); }
QString DevicePanel::warningText() const { return mBanner->text(); }
QString DevicePanel::forceText() const { return mForceLabel->text(); }
bool DevicePanel::forceClipped() const { return mForceLabel->property("clipped").toBool(); }

void DevicePanel::showSpec(const DeviceSpec* spec) {
    const QString none = QStringLiteral("—");
    if (!spec) {
        if (!mConnected) mConnectionLabel->setText(tr("Not connected"));
        for (QLabel* label : {mSpecNameLabel, mSpecForceLabel, mSpecStiffnessLabel, mSpecDampingLabel,
                              mSpecWorkspaceLabel, mSpecActuatedLabel, mSpecButtonsLabel})
            label->setText(none);
        return;
    }
    mSpecNameLabel->setText(spec->name.empty() ? none : QString::fromStdString(spec->name));
    mSpecForceLabel->setText(tr("%1 N").arg(specNumber(spec->maxForceN)));
    mSpecStiffnessLabel->setText(tr("%1 N/mm").arg(specNumber(spec->maxStiffnessNPerMm)));
    mSpecDampingLabel->setText(tr("%1 N·s/mm").arg(specNumber(spec->maxDampingNsPerMm)));
    mSpecWorkspaceLabel->setText(tr("%1 mm").arg(specNumber(spec->workspaceRadiusMm)));
    mSpecActuatedLabel->setText(spec->actuated ? tr("yes") : tr("no (input only)"));
    mSpecButtonsLabel->setText(QLocale().toString(spec->buttonCount));
}

QString DevicePanel::safetyFlagsText(std::uint32_t flags) {
    struct Word {
        std::uint32_t bit;
        const char* text;
    };
    static constexpr Word kWords[] = {
        {kSafetyHeldOff, QT_TRANSLATE_NOOP("palpate::DevicePanel", "held off")},
        {kSafetyRamping, QT_TRANSLATE_NOOP("palpate::DevicePanel", "ramping")},
        {kSafetyClamped, QT_TRANSLATE_NOOP("palpate::DevicePanel", "clamped")},
        {kSafetyStaleSample, QT_TRANSLATE_NOOP("palpate::DevicePanel", "stale sample")},
        {kSafetyOverrun, QT_TRANSLATE_NOOP("palpate::DevicePanel", "overrun")},
        {kSafetyNotReady, QT_TRANSLATE_NOOP("palpate::DevicePanel", "not ready")},
        {kSafetyNonFinite, QT_TRANSLATE_NOOP("palpate::DevicePanel", "non-finite command")},
        {kSafetyBadTime, QT_TRANSLATE_NOOP("palpate::DevicePanel", "bad clock")},
    };
    QStringList words;
    for (const Word& w : kWords)
        if (flags & w.bit) words << translated(w.text);
    if (words.isEmpty()) return tr("none");
    return words.join(tr(", "));
}

void DevicePanel::updateFromSnapshot(const HapticSnapshot& snapshot) {
    const DeviceState state = snapshot.deviceState;
    const SafetyPhase phase = snapshot.safetyPhase;
    const bool lost = state == DeviceState::Disconnected || state == DeviceState::Fault;

    mStateLabel->setText(translated(deviceStateName(state)));
    // Red when lost, orange while coming up; set only on change (a style sheet re-polishes).
    const QString stateStyle = lost                          ? QStringLiteral("color: #b71c1c; font-weight: bold;")
                               : state == DeviceState::Ready ? QString()
                                                             : QStringLiteral("color: #e65100;");
    if (mStateLabel->styleSheet() != stateStyle) mStateLabel->setStyleSheet(stateStyle);
    mPhaseLabel->setText(translated(safetyPhaseName(phase)));
    mFlagsLabel->setText(safetyFlagsText(snapshot.safetyFlags));
    const glm::vec3 f = snapshot.forceN;
    QString force = tr("%1 N  (%2, %3, %4)")
                        .arg(liveNumber(glm::length(f), 2), liveNumber(f.x, 2), liveNumber(f.y, 2), liveNumber(f.z, 2));
    // The safety filter clamps a command above the device's maximum: the user feels the maximum,
    // not what the model asked for, and the readout says so.
    const double askedN = glm::length(snapshot.commandedForceN);
    const bool clipped = (snapshot.safetyFlags & kSafetyClamped) != 0 ||
                         (mDeviceMaxForceN > 0.0 && askedN > mDeviceMaxForceN);
    if (clipped)
        force += QLatin1Char('\n') + (mDeviceMaxForceN > 0.0
                                          ? tr("clipped at device max %1 N (the model asked %2 N)")
                                                .arg(liveNumber(mDeviceMaxForceN, 2), liveNumber(askedN, 2))
                                          : tr("clipped (the model asked %1 N)").arg(liveNumber(askedN, 2)));
    mForceLabel->setText(force);
    if (mForceLabel->property("clipped").toBool() != clipped) {
        mForceLabel->setProperty("clipped", clipped);
        mForceLabel->setStyleSheet(clipped ? QStringLiteral("color: #b71c1c; font-weight: bold;") : QString());
    }
    const glm::vec3 p = snapshot.toolTipMm;
    mToolLabel->setText(tr("(%1, %2, %3) mm").arg(liveNumber(p.x, 1), liveNumber(p.y, 1), liveNumber(p.z, 1)));

    if (!mConnected) return;
    const QString who = mConnectedUri;
    if (lost) {
        mLossLatched = true;
        showBanner(state == DeviceState::Fault
                       ? tr("%1 reports a fault: forces are off. Disconnect it, or reconnect it to try again.").arg(who)
                       : tr("%1 is disconnected (unplugged?): forces are off. Plug it back in or choose another device.")
                             .arg(who));
        return;
    }
    if (!mLossLatched) return;
    if (state == DeviceState::Ready && phase == SafetyPhase::Armed) {
        mLossLatched = false;
        hideBanner();
    } else if (state != DeviceState::Ready) {
        showBanner(tr("%1 is coming back (%2): forces are off.").arg(who, translated(deviceStateName(state))));
    } else if (phase == SafetyPhase::HoldOff) {
        showBanner(tr("%1 is back: forces are held off until the tool eases off the tissue.").arg(who));
    } else {
        showBanner(tr("%1 is back: forces are ramping in.").arg(who));
    }
}

void DevicePanel::showBanner(const QString& text) {
    mBanner->setText(text);
    mBanner->show();
}

void DevicePanel::hideBanner() {
    mBanner->clear();
    mBanner->hide();
}

void DevicePanel::updateButtons() {
    mConnectButton->setEnabled(!uri().isEmpty() || fileEntry() != nullptr);
    mDisconnectButton->setEnabled(mConnected);
}

}  // namespace palpate
