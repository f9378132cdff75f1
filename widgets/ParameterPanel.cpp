#include "widgets/ParameterPanel.h"

#include "widgets/SaveFileChoice.h"
#include "widgets/GuardedLoad.h"
#include "widgets/ScrollWheelGuard.h"

#include "widgets/ParameterCommands.h"

#include "engine/core/HapticRate.h"
#include "engine/stability/StabilityBounds.h"
#include "engine/core/Octree.h"
#include "engine/core/SceneTarget.h"
#include "engine/models/slopering/SlopeRingModel.h"
#include "engine/accuracy/ModelError.h"

#include <QAction>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGraphicsOpacityEffect>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPropertyAnimation>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSequentialAnimationGroup>
#include <QSet>
#include <QSpinBox>
#include <QStyle>
#include <QTime>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <exception>

namespace palpate {

/// One entry of an engine field table that the panel edits: the table's row (range, text), where
/// the value lives in a TissuePreset, and the widget that shows it.
struct PanelField {
    QWidget* widget = nullptr;
    const FieldSpec* spec = nullptr;
    FieldType type = FieldType::Real;
    int index = -1;       ///< the list entry (a slope); -1 for a scalar
    std::string section;  ///< the preset file's section: slope_ring, mass_spring, ..., octree, tissue
    std::function<double(const TissuePreset&)> get;
    std::function<void(TissuePreset&, double)> set;  ///< null: presetFromFields sets it (the tissue)
};

namespace {

/// A field table's text in the user's language (the engine's context, base/params/FieldTable.h).
QString fieldText(const char* text) { return QCoreApplication::translate(kFieldTextContext, text); }

/// Every row of `table` (each stored entry of a list its own field, when `lists`) as PanelFields
/// reading and writing the part of a TissuePreset `part` returns (a generic lambda: const and not).
template <class S, class Part>
void addFields(std::vector<PanelField>& out, const char* section, Part part, FieldTable<S> table, bool lists = true) {
    for (const FieldDef<S>& f : table) {
        const bool list = f.type == FieldType::RealList;
        if (list && !lists) continue;
        for (int i = 0; i < (list ? f.capacity : 1); ++i) {
            PanelField field;
            field.spec = &f.spec;
            field.type = f.type;
            field.index = list ? i : -1;
            field.section = section;
            const FieldDef<S>* row = &f;  // a row of the engine's static table
            const int index = field.index;
            field.get = [part, row, index](const TissuePreset& p) { return row->get(part(p), index); };
            field.set = [part, row, index](TissuePreset& p, double v) { row->set(part(p), index, v); };
            out.push_back(std::move(field));
        }
    }
}

/// The section of its own fields a model shows in the model-parameters form; "" for the models
/// that run on the slope-ring rows (shown in the slope and spring groups).
std::string modelParamsSectionOf(const ModelDescriptor& model) {
    return model.section == std::string_view("slope_ring") ? std::string() : std::string(model.section);
}

/// Every section the model-parameters form holds, in the selector's order.
std::vector<std::string> modelParamsSections() {
    std::vector<std::string> sections;
    for (const ModelDescriptor& d : modelDescriptors())
        if (const std::string s = modelParamsSectionOf(d);
            !s.empty() && std::find(sections.begin(), sections.end(), s) == sections.end())
            sections.push_back(s);
    return sections;
}

/// "mass_spring" -> "massSpring"
QString camelCase(const std::string& section) {
    QString out;
    bool upper = false;
    for (char c : section) {
        if (c == '_') {
            upper = true;
            continue;
        }
        out += upper ? QChar::fromLatin1(c).toUpper() : QChar::fromLatin1(c);
        upper = false;
    }
    return out;
}

QString modelData(std::string_view name) { return QString::fromLatin1(name.data(), qsizetype(name.size())); }

/// A double spin box that shows as many decimals as the value needs ("0.6", "0.0025", "1000") up to
/// its field's significant digits (FieldSpec::shownDigits): a calibrated slope reads "14.07", not
/// "14.072222222", while the value keeps every decimal.
class CompactDoubleSpinBox final : public QDoubleSpinBox {
public:
    CompactDoubleSpinBox(QWidget* parent, int shownDigits) : QDoubleSpinBox(parent), mShownDigits(shownDigits) {}

    QString textFromValue(double value) const override {
        QString text = locale().toString(value, 'f', shownDecimals(value));
        if (std::abs(value) >= 1000.0) text.remove(locale().groupSeparator());
        const QString point = locale().decimalPoint();
        if (text.contains(point)) {
            while (text.endsWith(QLatin1Char('0'))) text.chop(1);
            if (text.endsWith(point)) text.chop(point.size());
        }
        return text;
    }

    /// The text the held value shows stands for that value with all its decimals: leaving the field
    /// (which reads its text back) must not round it to the digits shown.
    double valueFromText(const QString& text) const override {
        QString core = text;
        if (!prefix().isEmpty() && core.startsWith(prefix())) core.remove(0, prefix().size());
        if (!suffix().isEmpty() && core.endsWith(suffix())) core.chop(suffix().size());
        if (core.trimmed() == textFromValue(value())) return value();
        return QDoubleSpinBox::valueFromText(text);
    }

private:
    int shownDecimals(double value) const {
        if (mShownDigits <= 0 || value == 0.0 || !std::isfinite(value)) return decimals();
        const int magnitude = int(std::floor(std::log10(std::abs(value))));
        return std::clamp(mShownDigits - 1 - magnitude, 0, decimals());
    }

    int mShownDigits;
};

QDoubleSpinBox* doubleSpin(QWidget* parent, const char* objectName, double lo, double hi, int decimals, double step,
                           int shownDigits = 0) {
    auto* spin = new CompactDoubleSpinBox(parent, shownDigits);
    spin->setObjectName(QLatin1String(objectName));
    spin->setDecimals(decimals);
    spin->setRange(lo, hi);
    spin->setSingleStep(step);
    spin->setAccelerated(true);
    spin->setAlignment(Qt::AlignRight);
    return spin;
}

QSpinBox* intSpin(QWidget* parent, const char* objectName, int lo, int hi) {
    auto* spin = new QSpinBox(parent);
    spin->setObjectName(QLatin1String(objectName));
    spin->setRange(lo, hi);
    spin->setAlignment(Qt::AlignRight);
    return spin;
}

/// The value a spin box holds after setValue(value): QDoubleSpinBox rounds to its decimals so.
double shownAs(const QDoubleSpinBox* spin, double value) {
    return QString::number(std::clamp(value, spin->minimum(), spin->maximum()), 'f', spin->decimals()).toDouble();
}

void setRowLabel(QFormLayout* form, QWidget* field, const QString& text) {
    if (auto* label = qobject_cast<QLabel*>(form->labelForField(field))) {
        label->setText(text);
        label->setBuddy(field);
    }
}

/// Problems and stability are shown in colour; a field is framed red when a problem names it and
/// amber when it is allowed but outside the paper's range.
/// A field that differs from what runs is framed blue, its label blue (a problem's red still wins).
const char* const kStyleSheet = R"(
QAbstractSpinBox[modified="true"], QComboBox[modified="true"] { border: 2px solid #1e88e5; border-radius: 3px; background-color: #eef5fd; }
QLabel[modified="true"] { color: #1565c0; }
QWidget#unappliedBar { background-color: #e3f2fd; border: 1px solid #64b5f6; border-radius: 3px; }
QLabel#unappliedLabel { color: #0d47a1; }
QLabel#appliedLabel { color: #2e7d32; }
QPushButton#applyButton[pending="true"] { font-weight: bold; }
QAbstractSpinBox[invalid="true"] { border: 2px solid #d32f2f; border-radius: 3px; background-color: #fff0f0; }
QAbstractSpinBox[outsidePaperRange="true"] { border: 2px solid #e69500; border-radius: 3px; background-color: #fff8e6; }
QAbstractSpinBox[invalid="true"]::up-button, QAbstractSpinBox[invalid="true"]::down-button,
QAbstractSpinBox[outsidePaperRange="true"]::up-button, QAbstractSpinBox[outsidePaperRange="true"]::down-button,
QAbstractSpinBox[modified="true"]::up-button, QAbstractSpinBox[modified="true"]::down-button { width: 16px; }
QLabel#messageLabel { color: #c62828; }
QLabel#noteLabel { color: #8a5a00; }
QLabel#stabilityLabel[nearLimit="true"] { color: #8a5a00; background-color: #fff3d6; border: 1px solid #e69500; border-radius: 3px; padding: 2px; }
QLabel#stabilityLabel[unstable="true"] { color: #c62828; background-color: #fff0f0; border: 1px solid #d32f2f; border-radius: 3px; padding: 2px; }
QLabel#presetTitleLabel { font-weight: bold; }
)";

}  // namespace

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
    mUndoStack = new QUndoStack(this);
    buildUi();
    retranslateUi();
    showPreset(TissuePreset{});
}

ParameterPanel::~ParameterPanel() = default;

void ParameterPanel::buildUi() {
    setObjectName(QStringLiteral("parameterPanel"));
    setStyleSheet(QLatin1String(kStyleSheet));
    buildFields();
    buildFooter();
    connectEdits();
}

void ParameterPanel::buildFields() {
    // The fields, from the engine's tables; the tissue's are read from the preset's optional
    // properties (the defaults when it has none) and written by tissueFromFields.
    addFields(mFields, "slope_ring", [](auto& p) -> auto& { return p.model.slopeRing; }, slopeRingFields());
    addFields(mFields, "octree", [](auto& p) -> auto& { return p.octree; }, octreeFields());
    addFields(mFields, "mass_spring", [](auto& p) -> auto& { return p.model.massSpring; }, massSpringFields(), false);
    addFields(mFields, "radius_of_influence", [](auto& p) -> auto& { return p.model.radiusOfInfluence; },
              radiusOfInfluenceFields(), false);
    addFields(mFields, "ffd", [](auto& p) -> auto& { return p.model.ffd; }, ffdFields(), false);
    for (const FieldDef<TissueProperties>& f : tissueFields()) {
        PanelField field;
        field.spec = &f.spec;
        field.type = f.type;
        field.section = "tissue";
        const FieldDef<TissueProperties>* row = &f;
        field.get = [row](const TissuePreset& p) { return row->get(p.tissue.value_or(TissueProperties{}), -1); };
        mFields.push_back(std::move(field));
    }
    // Each field of `section` whose key passes `pick` into `form`, in table order.
    auto place = [this](const std::string& section, QFormLayout* form, QWidget* parent, auto pick) {
        for (PanelField& f : mFields)
            if (f.section == section && pick(std::string(f.spec->key))) {
                QWidget* widget = createFieldWidget(f, parent);
                const bool slope = f.index >= 0 && std::string(f.spec->key) == "slopeMagnitudeMmPerN";
                if (f.index >= 0 && !slope) {
                    // Another list (the stiffening knots): each entry named as the engine names it.
                    auto* itemLabel = new QLabel(QString::fromStdString(f.spec->itemName(f.index)) + QLatin1Char(':'), parent);
                    itemLabel->setBuddy(widget);
                    form->addRow(itemLabel, widget);
                } else if (slope) {
                    mSlopeLabels[std::size_t(f.index)] = new QLabel(parent);
                    mSlopeLabels[std::size_t(f.index)]->setObjectName(QString::fromLatin1("slopeLabel%1").arg(f.index));
                    mSlopeLabels[std::size_t(f.index)]->setBuddy(widget);
                    form->addRow(mSlopeLabels[std::size_t(f.index)], widget);
                } else {
                    form->addRow(new QLabel(parent), widget);
                }
            }
    };
    auto all = [](const std::string&) { return true; };

    // The fields scroll (nine slope rows do not fit a short dock); feedback and buttons stay put.
    auto* fields = new QWidget;
    auto* fieldsLayout = new QVBoxLayout(fields);
    fieldsLayout->setContentsMargins(0, 0, 0, 0);

    mTitleLabel = new QLabel(fields);
    mTitleLabel->setObjectName(QStringLiteral("presetTitleLabel"));
    mTitleLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    fieldsLayout->addWidget(mTitleLabel);

    auto newForm = [&](QGroupBox*& group, QFormLayout*& form, const char* name) {
        group = new QGroupBox(fields);
        group->setObjectName(QLatin1String(name));
        form = new QFormLayout(group);
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        fieldsLayout->addWidget(group);
    };

    newForm(mModelGroup, mModelForm, "modelGroup");
    mModelCombo = new QComboBox(mModelGroup);
    mModelCombo->setObjectName(QStringLiteral("modelCombo"));
    // The slope-ring methods first, then the other registry models after a separator.
    for (const bool slopeRing : {true, false}) {
        if (!slopeRing) mModelCombo->insertSeparator(mModelCombo->count());
        for (const ModelDescriptor& d : modelDescriptors())
            if ((d.kind == ModelKind::SlopeRing) == slopeRing) mModelCombo->addItem(QString(), modelData(d.name));
    }
    mModelForm->addRow(new QLabel(fields), mModelCombo);
    mRateSpin = doubleSpin(mModelGroup, "hapticRateSpin", 0.0, 10.0 * kMaxHapticRateHz, 1, 50.0);
    mModelForm->addRow(new QLabel(fields), mRateSpin);

    // Tissue and tool: elasticity in, calibrated slopes out (into the slope group below).
    newForm(mTissueGroup, mTissueForm, "tissueGroup");
    mTissueCombo = new QComboBox(mTissueGroup);
    mTissueCombo->setObjectName(QStringLiteral("tissuePresetCombo"));
    mTissueCombo->addItem(QString());  // "Choose a tissue…": the placeholder, no file
    mTissueCombo->setEnabled(false);   // until setTissuePresetDirectory finds presets
    mTissueForm->addRow(new QLabel(fields), mTissueCombo);
    place("tissue", mTissueForm, mTissueGroup, all);
    // The button and its result in one nested widget: a spanning row, not a label column entry.
    auto* calibrateBox = new QWidget(mTissueGroup);
    auto* calibrateLayout = new QVBoxLayout(calibrateBox);
    calibrateLayout->setContentsMargins(0, 0, 0, 0);
    auto* calibrateRow = new QHBoxLayout;
    mCalibrateButton = new QPushButton(calibrateBox);
    mCalibrateButton->setObjectName(QStringLiteral("calibrateSlopesButton"));
    calibrateRow->addWidget(mCalibrateButton);
    calibrateRow->addStretch(1);
    calibrateLayout->addLayout(calibrateRow);
    mCalibrationLabel = new QLabel(calibrateBox);
    mCalibrationLabel->setObjectName(QStringLiteral("calibrationLabel"));
    mCalibrationLabel->setWordWrap(true);
    mCalibrationLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mCalibrationLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);  // wraps, never widens the dock
    mCalibrationLabel->setVisible(false);
    calibrateLayout->addWidget(mCalibrationLabel);
    mTissueForm->addRow(calibrateBox);

    newForm(mModelParamsGroup, mModelParamsForm, "modelParamsGroup");
    for (const std::string& section : modelParamsSections()) place(section, mModelParamsForm, mModelParamsGroup, all);

    newForm(mSlopeGroup, mSlopeForm, "slopeGroup");
    auto slopeRows = [](const std::string& key) {
        return key == "ringCount" || key == "slopeMagnitudeMmPerN" || key == "slopeLimitMmPerN";
    };
    place("slope_ring", mSlopeForm, mSlopeGroup, slopeRows);
    newForm(mSpringGroup, mSpringForm, "springGroup");
    place("slope_ring", mSpringForm, mSpringGroup, [&](const std::string& key) { return !slopeRows(key); });
    newForm(mOctreeGroup, mOctreeForm, "octreeGroup");
    place("octree", mOctreeForm, mOctreeGroup, all);
    // The widgets the panel's own logic refers to (ring rows, loop gain, tissue).
    for (const PanelField& f : mFields) {
        const std::string key = f.spec->key;
        if (f.section == "slope_ring" && key == "ringCount") mRingSpin = qobject_cast<QSpinBox*>(f.widget);
        if (f.section == "slope_ring" && key == "slopeMagnitudeMmPerN" && f.index >= 0)
            mSlopeSpins[std::size_t(f.index)] = qobject_cast<QDoubleSpinBox*>(f.widget);
        if (f.section == "slope_ring" && key == "contactStiffnessNPerMm")
            mContactSpin = qobject_cast<QDoubleSpinBox*>(f.widget);
        if (f.section == "slope_ring" && key == "forceRelaxation")
            mRelaxationSpin = qobject_cast<QDoubleSpinBox*>(f.widget);
        if (f.section == "tissue" && key == "youngsModulusKPa") mYoungsSpin = qobject_cast<QDoubleSpinBox*>(f.widget);
        if (f.section == "tissue" && key == "poissonRatio") mPoissonSpin = qobject_cast<QDoubleSpinBox*>(f.widget);
        if (f.section == "tissue" && key == "toolRadiusMm") mToolRadiusSpin = qobject_cast<QDoubleSpinBox*>(f.widget);
    }
    fieldsLayout->addStretch(1);

    mScroll = new QScrollArea(this);
    mScroll->setObjectName(QStringLiteral("parameterScroll"));
    mScroll->setWidget(fields);
    mScroll->setWidgetResizable(true);
    mScroll->setFrameShape(QFrame::NoFrame);
    mScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
}

void ParameterPanel::buildFooter() {
    // Feedback under the fields.
    mStabilityLabel = new QLabel(this);
    mStabilityLabel->setObjectName(QStringLiteral("stabilityLabel"));
    mStabilityLabel->setWordWrap(true);
    mMessageLabel = new QLabel(this);
    mMessageLabel->setObjectName(QStringLiteral("messageLabel"));
    mMessageLabel->setWordWrap(true);
    mMessageLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mNoteLabel = new QLabel(this);
    mNoteLabel->setObjectName(QStringLiteral("noteLabel"));
    mNoteLabel->setWordWrap(true);
    mNoteLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);

    // Actions: undo/redo from the stack, preset files.
    mUndoAction = mUndoStack->createUndoAction(this, tr("Undo"));
    mUndoAction->setObjectName(QStringLiteral("undoAction"));
    mUndoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_Z)});
    mRedoAction = mUndoStack->createRedoAction(this, tr("Redo"));
    mRedoAction->setObjectName(QStringLiteral("redoAction"));
    mRedoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)});
    mUndoAction->setIcon(QIcon::fromTheme(QStringLiteral("edit-undo"), style()->standardIcon(QStyle::SP_ArrowBack)));
    mRedoAction->setIcon(QIcon::fromTheme(QStringLiteral("edit-redo"), style()->standardIcon(QStyle::SP_ArrowForward)));
    for (QAction* action : {mUndoAction, mRedoAction}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        addAction(action);
    }
    mOpenAction = new QAction(this);
    mOpenAction->setObjectName(QStringLiteral("openPresetAction"));
    connect(mOpenAction, &QAction::triggered, this, &ParameterPanel::openPresetDialog);
    mSaveAction = new QAction(this);
    mSaveAction->setObjectName(QStringLiteral("savePresetAction"));
    connect(mSaveAction, &QAction::triggered, this, &ParameterPanel::savePresetDialog);

    mOpenButton = new QPushButton(this);
    mOpenButton->setObjectName(QStringLiteral("openPresetButton"));
    connect(mOpenButton, &QPushButton::clicked, mOpenAction, &QAction::trigger);
    mSaveButton = new QPushButton(this);
    mSaveButton->setObjectName(QStringLiteral("savePresetButton"));
    connect(mSaveButton, &QPushButton::clicked, mSaveAction, &QAction::trigger);
    auto* undoButton = new QToolButton(this);
    undoButton->setObjectName(QStringLiteral("undoButton"));
    undoButton->setDefaultAction(mUndoAction);
    auto* redoButton = new QToolButton(this);
    redoButton->setObjectName(QStringLiteral("redoButton"));
    redoButton->setDefaultAction(mRedoAction);
    mApplyButton = new QPushButton(this);
    mApplyButton->setObjectName(QStringLiteral("applyButton"));
    connect(mApplyButton, &QPushButton::clicked, this, &ParameterPanel::apply);

    // What runs against what the fields say: a bar while they differ, a confirmation after Apply.
    mUnappliedBar = new QWidget(this);
    mUnappliedBar->setObjectName(QStringLiteral("unappliedBar"));
    mUnappliedBar->setAttribute(Qt::WA_StyledBackground, true);
    mUnappliedLabel = new QLabel(mUnappliedBar);
    mUnappliedLabel->setObjectName(QStringLiteral("unappliedLabel"));
    mUnappliedLabel->setWordWrap(true);
    mUnappliedLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);  // wraps, never widens the dock
    mRevertButton = new QPushButton(mUnappliedBar);
    mRevertButton->setObjectName(QStringLiteral("revertButton"));
    connect(mRevertButton, &QPushButton::clicked, this, &ParameterPanel::revertToRunning);
    auto* barLayout = new QHBoxLayout(mUnappliedBar);
    barLayout->setContentsMargins(6, 4, 4, 4);
    barLayout->addWidget(mUnappliedLabel, 1);
    barLayout->addWidget(mRevertButton, 0, Qt::AlignVCenter);
    mUnappliedBar->hide();
    mAppliedLabel = new QLabel(this);
    mAppliedLabel->setObjectName(QStringLiteral("appliedLabel"));
    mAppliedLabel->setWordWrap(true);
    mAppliedLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mAppliedOpacity = new QGraphicsOpacityEffect(mAppliedLabel);
    mAppliedLabel->setGraphicsEffect(mAppliedOpacity);
    mAppliedLabel->hide();
    // Read for a few seconds, then faded out: a confirmation, not a state.
    mAppliedFade = new QSequentialAnimationGroup(this);
    mAppliedFade->addPause(4000);
    auto* fade = new QPropertyAnimation(mAppliedOpacity, "opacity", mAppliedFade);
    fade->setDuration(1500);
    fade->setStartValue(1.0);
    fade->setEndValue(0.0);
    mAppliedFade->addAnimation(fade);
    connect(mAppliedFade, &QAbstractAnimation::finished, mAppliedLabel, &QWidget::hide);

    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(mOpenButton);
    fileRow->addWidget(mSaveButton);
    fileRow->addStretch(1);
    auto* applyRow = new QHBoxLayout;
    applyRow->addWidget(undoButton);
    applyRow->addWidget(redoButton);
    applyRow->addStretch(1);
    applyRow->addWidget(mApplyButton);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(mScroll, 1);
    layout->addWidget(mStabilityLabel);
    layout->addWidget(mMessageLabel);
    layout->addWidget(mNoteLabel);
    layout->addLayout(fileRow);
    layout->addWidget(mUnappliedBar);
    layout->addWidget(mAppliedLabel);
    layout->addLayout(applyRow);
}

void ParameterPanel::connectEdits() {
    // Every field: an edit records an undo step and revalidates.
    connect(mModelCombo, &QComboBox::currentIndexChanged, this, [this] { onEdited(kModelEdit); });
    connect(mRateSpin, &QDoubleSpinBox::valueChanged, this, [this] { onEdited(kRateEdit); });
    for (int i = 0; i < int(mFields.size()); ++i) {
        QWidget* field = mFields[std::size_t(i)].widget;
        const int edit = kFieldEdit0 + i;
        if (auto* spin = qobject_cast<QDoubleSpinBox*>(field))
            connect(spin, &QDoubleSpinBox::valueChanged, this, [this, edit] { onEdited(edit); });
        else if (auto* ints = qobject_cast<QSpinBox*>(field))
            connect(ints, &QSpinBox::valueChanged, this, [this, edit] { onEdited(edit); });
        else if (auto* combo = qobject_cast<QComboBox*>(field))
            connect(combo, &QComboBox::currentIndexChanged, this, [this, edit] { onEdited(edit); });
    }
    connect(mTissueCombo, &QComboBox::activated, this, [this](int index) {
        const QString path = mTissueCombo->itemData(index).toString();
        if (!path.isEmpty()) loadPresetFile(path);
        syncTissueCombo();  // a failed load shows the preset that is still in the fields
    });
    connect(mCalibrateButton, &QPushButton::clicked, this, [this] { calibrateSlopes(); });

    for (QAbstractSpinBox* spin : findChildren<QAbstractSpinBox*>()) watchEdits(spin);
    guardScrollWheel(*mScroll);
}

void ParameterPanel::watchEdits(QWidget* spin) {
    // A spin box's line edit keeps its own text undo under Ctrl+Z; the panel's history is the one
    // the user means, so the line edit lets the panel's shortcuts through.
    spin->installEventFilter(this);
    for (QLineEdit* edit : spin->findChildren<QLineEdit*>()) edit->installEventFilter(this);
}

bool ParameterPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride) {
        const QKeySequence pressed(static_cast<QKeyEvent*>(event)->keyCombination());
        if (mUndoAction->shortcuts().contains(pressed) || mRedoAction->shortcuts().contains(pressed)) {
            event->ignore();  // not overridden: the shortcut (the panel's action) fires
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

QString ParameterPanel::slopeLabel(int ring) const {
    if (ring == 0) return tr("|m%1| (touched)").arg(1);
    return tr("|m%1| (ring %2)").arg(ring + 1).arg(ring);
}

QWidget* ParameterPanel::createFieldWidget(PanelField& f, QWidget* parent) {
    const FieldSpec& spec = *f.spec;
    QString name = camelCase(f.section) + QChar::fromLatin1(spec.key[0]).toUpper() + QLatin1String(spec.key + 1) +
                   QLatin1String(f.type == FieldType::Choice ? "Combo" : "Spin");
    if (f.index >= 0) name += QString::number(f.index);
    QWidget* widget = nullptr;
    if (f.type == FieldType::Choice) {
        auto* combo = new QComboBox(parent);
        for (int i = 0; i < int(spec.choices.size()); ++i) combo->addItem(QString(), i);
        widget = combo;
    } else if (f.type == FieldType::Whole) {
        widget = intSpin(parent, "", int(entryLowOf(spec)), int(entryHighOf(spec)));
    } else {
        widget = doubleSpin(parent, "", entryLowOf(spec), entryHighOf(spec), spec.decimals, spec.step, spec.shownDigits);
    }
    widget->setObjectName(name);
    f.widget = widget;
    return widget;
}

std::vector<const PanelField*> ParameterPanel::fieldsNamedBy(const std::string& section, const Problem& problem) const {
    std::vector<const PanelField*> named;
    for (const PanelField& f : mFields)
        if (f.section == section && problem.field == f.spec->key &&
            (f.index < 0 || problem.index < 0 || f.index == problem.index || f.index == problem.relatedIndex))
            named.push_back(&f);
    return named;
}

QString ParameterPanel::fieldName(int edit) const {
    if (edit == kModelEdit) return tr("deformation model");
    if (edit == kRateEdit) return tr("haptic rate");
    const PanelField& f = mFields[std::size_t(edit - kFieldEdit0)];
    if (f.index >= 0 && std::string(f.spec->key) != "slopeMagnitudeMmPerN")
        return QString::fromStdString(f.spec->itemName(f.index));
    if (f.index >= 0) return slopeLabel(f.index);
    if (*f.spec->name) return fieldText(f.spec->name);
    QString label = fieldText(f.spec->label);
    if (label.endsWith(QLatin1Char(':'))) label.chop(1);
    return label;
}

void ParameterPanel::retranslateUi() {
    mModelGroup->setTitle(tr("Model and loop"));
    mSlopeGroup->setTitle(tr("Slopes (magnitudes, |m1| > |m2| > …)"));
    mSpringGroup->setTitle(tr("Springs and contact"));
    mOctreeGroup->setTitle(tr("Octree"));
    mTissueGroup->setTitle(tr("Tissue and tool"));
    mTissueGroup->setToolTip(
        tr("The tissue's elasticity and the probe's flat tip: Calibrate slopes turns them into "
           "slopes and a spring stiffness for the current mesh (flat punch on a half-space, "
           "docs/calibration.md)."));
    setRowLabel(mTissueForm, mTissueCombo, tr("Tissue preset:"));
    mTissueCombo->setItemText(0, tr("Choose a tissue…"));
    mTissueCombo->setToolTip(
        tr("Load a shipped tissue preset: E, ν, the tool radius and slopes calibrated for the "
           "default stomach mesh (one undoable step). Each entry's tooltip names its source."));
    mCalibrateButton->setText(tr("Ca&librate slopes"));
    mCalibrateButton->setToolTip(
        tr("Slopes for the ring count and spring k for the current mesh from E, ν and the tool "
           "radius (flat punch: |m1| = 1 / (2 a E*), k = 1 / |m1|), then the error the "
           "calibrated model leaves against the punch. One undoable step; Apply sends them."));

    setRowLabel(mModelForm, mModelCombo, tr("Deformation model:"));
    for (int i = 0; i < mModelCombo->count(); ++i)
        if (const ModelDescriptor* d = findModelDescriptor(mModelCombo->itemData(i).toString().toStdString())) {
            mModelCombo->setItemText(i, QCoreApplication::translate(kModelTextContext, d->label));
            mModelCombo->setItemData(i, QCoreApplication::translate(kModelTextContext, d->description), Qt::ToolTipRole);
        }
    mModelCombo->setToolTip(
        tr("Which model deforms the tissue: the slope-ring methods (ours and the paper's three), "
           "then the literature's other models (docs/models.md)."));
    // Every table field: its label, tooltip and unit from the engine's table, translated here.
    for (const PanelField& f : mFields) {
        QFormLayout* form = qobject_cast<QFormLayout*>(f.widget->parentWidget()->layout());
        if (f.index < 0 && form) setRowLabel(form, f.widget, fieldText(f.spec->label));
        f.widget->setToolTip(fieldText(f.spec->tip));
        // Units are international ("mm/N"); tr() translates the few that are words ("vertices").
        const QString suffix = *f.spec->unit ? QLatin1Char(' ') + fieldText(f.spec->unit) : QString();
        if (auto* spin = qobject_cast<QDoubleSpinBox*>(f.widget)) spin->setSuffix(suffix);
        if (auto* ints = qobject_cast<QSpinBox*>(f.widget)) ints->setSuffix(suffix);
        if (auto* combo = qobject_cast<QComboBox*>(f.widget))
            for (int i = 0; i < combo->count() && i < int(f.spec->choiceLabels.size()); ++i)
                combo->setItemText(i, fieldText(f.spec->choiceLabels[std::size_t(i)]));
    }
    setRowLabel(mModelForm, mRateSpin, tr("Haptic rate:"));
    mRateSpin->setSuffix(tr(" Hz"));
    mRateSpin->setToolTip(tr("Ticks per second of the haptic loop, %1..%2 Hz (haptics usually runs at 1000 Hz).")
                              .arg(kMinHapticRateHz)
                              .arg(kMaxHapticRateHz));

    const auto slope = std::find_if(mFields.begin(), mFields.end(), [](const PanelField& f) { return f.index == 0; });
    const QString slopeTip =
        fieldText(slope->spec->tip) + QStringLiteral("\n\n") +
        tr("Read with signs, the paper's \"m1 > m2 > m3\" would move the outer rings further than the touched "
           "vertex. Palpate orders the magnitudes instead, |m1| > |m2| > |m3| > …, so the displacement decays away "
           "from the touched vertex.") +
        QStringLiteral("\n\n") +
        tr("The paper's range is (0, 1) mm/N; larger values need a raised slope limit and a stable loop gain.");
    for (int r = 0; r <= kMaxRings; ++r) {
        mSlopeLabels[std::size_t(r)]->setText(slopeLabel(r) + QLatin1Char(':'));
        mSlopeLabels[std::size_t(r)]->setToolTip(slopeTip);
        mSlopeSpins[std::size_t(r)]->setToolTip(slopeTip);
    }
    mRelaxationSpin->setSpecialValueText(tr("automatic"));  // 0: alpha = 1 / (1 + gain)

    // mStabilityLabel's tooltip depends on the model: validate() sets it.
    // The slope group's title states the ordering rule; its tooltip says why.
    mSlopeGroup->setToolTip(slopeTip);
    mOpenAction->setText(tr("Open preset…"));
    mOpenAction->setToolTip(tr("Read a tissue preset file (JSON) into the fields; one undoable step."));
    mSaveAction->setText(tr("Save preset…"));
    mSaveAction->setToolTip(tr("Write the fields to a tissue preset file (JSON)."));
    mOpenButton->setText(mOpenAction->text());
    mOpenButton->setToolTip(mOpenAction->toolTip());
    mSaveButton->setText(mSaveAction->text());
    mSaveButton->setToolTip(mSaveAction->toolTip());
    mRevertButton->setText(tr("&Revert"));
    mRevertButton->setToolTip(tr("Set the fields back to what the haptic loop runs (one undoable step)."));
    mApplyButton->setText(tr("Apply"));
    mApplyButton->setToolTip(tr("Send these parameters to the haptic loop (enabled while they are valid)."));

    // One label column for all groups, as wide as the widest label (the groups line up) ...
    const QList<QLabel*> rowLabels = mScroll->widget()->findChildren<QLabel*>();
    int labelWidth = 0;
    for (QFormLayout* form : {mModelForm, mModelParamsForm, mTissueForm, mSlopeForm, mSpringForm, mOctreeForm})
        for (QLabel* label : rowLabels)
            if (form->indexOf(label) >= 0) {
                label->setMinimumWidth(0);
                labelWidth = std::max(labelWidth, label->sizeHint().width());
            }
    for (QFormLayout* form : {mModelForm, mModelParamsForm, mTissueForm, mSlopeForm, mSpringForm, mOctreeForm})
        for (QLabel* label : rowLabels)
            if (form->indexOf(label) >= 0) label->setMinimumWidth(labelWidth);
    updateModelRows();  // the model group's title
    // ... and the fields wide enough for their texts and a vertical scroll bar: nothing is cut off.
    mScroll->setMinimumWidth(mScroll->widget()->sizeHint().width() + style()->pixelMetric(QStyle::PM_ScrollBarExtent) +
                             2 * mScroll->frameWidth() + 4);
    validate();  // the feedback texts are translated too
}

void ParameterPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

TissuePreset ParameterPanel::presetFromFields() const {
    TissuePreset preset = mShown;  // name, description and tissue properties are not fields
    if (const auto model = modelDefForName(mModelCombo->currentData().toString().toStdString())) {
        preset.model.kind = model->kind;
        if (model->kind == ModelKind::SlopeRing) preset.model.slopeRingMethod = model->slopeRingMethod;
    }
    preset.hapticRateHz = mRateSpin->value();
    for (const PanelField& f : mFields) {
        if (!f.set) continue;
        if (auto* spin = qobject_cast<QDoubleSpinBox*>(f.widget)) f.set(preset, spin->value());
        else if (auto* ints = qobject_cast<QSpinBox*>(f.widget)) f.set(preset, ints->value());
        else if (auto* combo = qobject_cast<QComboBox*>(f.widget)) f.set(preset, combo->currentData().toInt());
    }
    preset.tissue = tissueFromFields();
    return preset;
}

TissueProperties ParameterPanel::tissueInFields(const std::string& source) const {
    TissueProperties tissue;
    tissue.source = source;
    for (const PanelField& f : mFields)
        if (f.section == "tissue")
            if (const FieldDef<TissueProperties>* row = findField(tissueFields(), f.spec->key))
                row->set(tissue, -1, qobject_cast<const QDoubleSpinBox*>(f.widget)->value());
    return tissue;
}

bool ParameterPanel::tissueFieldsShow(const TissueProperties& tissue) const {
    TissuePreset holder;
    holder.tissue = tissue;
    for (const PanelField& f : mFields)
        if (f.section == "tissue") {
            const auto* spin = qobject_cast<const QDoubleSpinBox*>(f.widget);
            if (spin->value() != shownAs(spin, f.get(holder))) return false;
        }
    return true;
}

std::optional<TissueProperties> ParameterPanel::tissueFromFields() const {
    if (mShown.tissue) {
        if (tissueFieldsShow(*mShown.tissue)) {
            TissueProperties same = tissueInFields(mShown.tissue->source);  // its sources still hold
            same.stiffeningSource = mShown.tissue->stiffeningSource;
            return same;
        }
    } else if (tissueFieldsShow(TissueProperties{})) {
        return std::nullopt;  // the defaults of a preset without a tissue: nothing to record
    }
    TissueProperties edited = tissueInFields(tr("entered in the Parameters panel").toStdString());
    // The stiffening's source holds while its exponent is the one it was given for.
    if (mShown.tissue && edited.stiffeningExponent == mShown.tissue->stiffeningExponent)
        edited.stiffeningSource = mShown.tissue->stiffeningSource;
    return edited;
}

ToolContact ParameterPanel::toolContact() const {
    ToolContact contact;
    contact.material.youngsModulusNPerMm2 = mYoungsSpin->value() * 1e-3;  // 1 kPa = 0.001 N/mm^2
    contact.material.poissonRatio = mPoissonSpin->value();
    contact.toolRadiusMm = mToolRadiusSpin->value();
    contact.stiffeningExponent = tissueInFields({}).stiffeningExponent;
    return contact;
}

ToolContact ParameterPanel::toolContactOf(const TissuePreset& preset) {
    const TissueProperties tissue = preset.tissue.value_or(TissueProperties{});
    ToolContact contact;
    contact.material.youngsModulusNPerMm2 = tissue.youngsModulusKPa * 1e-3;  // 1 kPa = 0.001 N/mm^2
    contact.material.poissonRatio = tissue.poissonRatio;
    contact.toolRadiusMm = tissue.toolRadiusMm;
    contact.stiffeningExponent = tissue.stiffeningExponent;
    return contact;
}

QStringList ParameterPanel::tissueProblems(QList<QWidget*>* invalid) const {
    const TissueProperties tissue = tissueInFields({});
    QStringList problems;
    for (const Problem& problem : validateTissueProperties(tissue))
        for (const PanelField* f : fieldsNamedBy("tissue", problem)) {
            problems << tr("%1: %2").arg(fieldName(kFieldEdit0 + int(f - mFields.data())),
                                         QString::fromStdString(problem.message));
            if (invalid) invalid->append(f->widget);
        }
    return problems;
}

void ParameterPanel::setMeshProvider(MeshProvider provider) {
    mMeshProvider = std::move(provider);
    validate();
}

void ParameterPanel::setTissuePresetDirectory(const QString& directory) {
    while (mTissueCombo->count() > 1) mTissueCombo->removeItem(1);
    const QDir dir(directory);
    const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files | QDir::Readable, QDir::Name);
    for (const QString& file : files) {
        const QString path = dir.absoluteFilePath(file);
        const std::string native = QDir::toNativeSeparators(path).toStdString();
        const PresetLoadResult loaded = guardedLoad(native, [&] { return loadTissuePreset(native); });
        if (!loaded.preset) continue;  // a broken file is reported when loaded by hand, not here
        const TissuePreset& preset = *loaded.preset;
        QString tip = QString::fromStdString(preset.description);
        if (preset.tissue)
            tip += QStringLiteral("\n\n") +
                   tr("E = %1 kPa, ν = %2, tool radius %3 mm")
                       .arg(locale().toString(preset.tissue->youngsModulusKPa, 'g', 4),
                            locale().toString(preset.tissue->poissonRatio, 'g', 4),
                            locale().toString(preset.tissue->toolRadiusMm, 'g', 4)) +
                   QStringLiteral("\n") + tr("Source: %1").arg(QString::fromStdString(preset.tissue->source));
        mTissueCombo->addItem(QString::fromStdString(preset.name), path);
        mTissueCombo->setItemData(mTissueCombo->count() - 1, tip, Qt::ToolTipRole);
    }
    mTissueCombo->setEnabled(mTissueCombo->count() > 1);
    syncTissueCombo();
}

void ParameterPanel::syncTissueCombo() {
    // The entry of the preset shown, by name; the placeholder once the fields are someone else's.
    int index = 0;
    for (int i = 1; i < mTissueCombo->count(); ++i)
        if (mTissueCombo->itemText(i).toStdString() == mShown.name) index = i;
    const QSignalBlocker block(mTissueCombo);
    mTissueCombo->setCurrentIndex(index);
}

bool ParameterPanel::calibrateSlopes(QString* error) {
    auto fail = [&](const QString& message) {
        mCalibratedParams.reset();
        mCalibrationText = message;
        mCalibrationLabel->setProperty("problem", true);
        updateCalibrationLabel();
        if (error) *error = message;
        return false;
    };
    const TissueMesh* mesh = mMeshProvider ? mMeshProvider() : nullptr;
    if (!mesh || mesh->vertexCount() == 0) return fail(tr("Calibrate slopes needs a mesh: open one first."));
    if (const QStringList problems = tissueProblems(); !problems.isEmpty())
        return fail(tr("Not calibrated: %1").arg(problems.join(QStringLiteral("; "))));

    const TissuePreset before = presetFromFields();
    const ToolContact contact = toolContact();
    const VertexId touched = defaultTargetVertex(*mesh);
    SlopeCalibration calibration;
    ModelError measured;
    try {
        calibration = calibrateSlopesFromPunch(*mesh, touched, contact, before.model.slopeRing);
        // The error the calibrated model leaves: a private model of the same mesh, pressed and let
        // settle (PressDef: 300 ticks), never the haptic loop's.
        const OctreeDef octreeDef = validateOctreeDef(before.octree).empty() ? before.octree : OctreeDef{};
        const Octree octree(*mesh, octreeDef);
        const auto model = makeSlopeRing(*mesh, octree, calibration.params, before.model.slopeRingMethod);
        measured = measureModelError(*model, *mesh, touched, contact);
    } catch (const std::exception& e) {
        return fail(tr("Not calibrated: %1").arg(QString::fromStdString(e.what())));
    }

    TissuePreset after = before;
    after.model.slopeRing = calibration.params;
    after.tissue = before.tissue.value_or(
        tissueInFields(tr("Parameters panel default (gelatin phantom, as palpate-cli)").toStdString()));
    if (!samePreset(before, after))
        mUndoStack->push(new ParameterEditCommand(before, after, tr("Calibrate slopes"), ParameterEditCommand::kNoMerge,
                                                  /*alreadyShown=*/false,
                                                  [this](const TissuePreset& preset) { showPreset(preset); }));

    const QLocale locale = this->locale();
    QStringList lines;
    lines << tr("displacement error %1 % (RMS/peak over r ≤ 5a), force error %2 %")
                 .arg(locale.toString(measured.displacementError * 100.0, 'f', 1),
                      locale.toString(measured.forceError * 100.0, 'f', 1));
    const int rings = calibration.params.ringCount;
    lines << (rings == 1 ? tr("1 ring") : tr("%1 rings").arg(rings)) + QLatin1Char(' ') +
                 tr("at vertex %1 of %2 vertices, pressed %3 mm in; %4 vertices compared.")
                     .arg(touched)
                     .arg(mesh->vertexCount())
                     .arg(locale.toString(measured.indentationMm, 'f', 2))
                     .arg(measured.verticesCompared);
    for (const std::string& note : calibration.notes) lines << tr("Note: %1").arg(QString::fromStdString(note));
    mCalibratedParams = mShown.model.slopeRing;  // as the fields hold them
    mCalibrationText = lines.join(QLatin1Char('\n'));
    mCalibrationLabel->setProperty("problem", false);
    updateCalibrationLabel();
    if (error) error->clear();
    return true;
}

void ParameterPanel::updateCalibrationLabel() {
    QString text = mCalibrationText;
    const bool stale = mCalibratedParams &&
                       !(presetFromFields().model.slopeRing.slopeMagnitudeMmPerN == mCalibratedParams->slopeMagnitudeMmPerN &&
                         presetFromFields().model.slopeRing.ringCount == mCalibratedParams->ringCount);
    if (stale) text += QLatin1Char('\n') + tr("(for the calibrated slopes; the slopes have changed since)");
    mCalibrationLabel->setText(text);
    mCalibrationLabel->setVisible(!text.isEmpty());
    const bool problem = mCalibrationLabel->property("problem").toBool();
    mCalibrationLabel->setStyleSheet(problem ? QStringLiteral("color: #c62828;")
                                     : stale ? QStringLiteral("color: #757575;")
                                             : QString());
}

TissuePreset ParameterPanel::preset() const { return presetFromFields(); }

void ParameterPanel::setPreset(const TissuePreset& preset) {
    mUndoStack->clear();
    mRunning = preset;
    showPreset(preset);
    mUndoStack->setClean();
}

QString ParameterPanel::applyStiffeningKnots(const StiffeningCalibration& calibration) {
    const TissuePreset before = presetFromFields();
    TissuePreset after = before;
    try {
        applyStiffening(calibration, after.model.slopeRing);
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    if (!samePreset(before, after))
        mUndoStack->push(new ParameterEditCommand(before, after, tr("Apply stiffening knots"),
                                                  ParameterEditCommand::kNoMerge,
                                                  /*alreadyShown=*/false,
                                                  [this](const TissuePreset& preset) { showPreset(preset); }));
    if (!mValid) return tr("Not applied: the parameters are not valid (see the Parameters panel).");
    apply();
    return {};
}

void ParameterPanel::showPreset(const TissuePreset& preset) {
    mShowing = true;
    const QString model = QString::fromStdString(presetModelName(preset));
    for (int i = 0; i < mModelCombo->count(); ++i)
        if (mModelCombo->itemData(i).toString() == model) mModelCombo->setCurrentIndex(i);
    mRateSpin->setValue(preset.hapticRateHz);
    for (const PanelField& f : mFields) {
        const double value = f.get(preset);
        if (auto* spin = qobject_cast<QDoubleSpinBox*>(f.widget)) spin->setValue(value);
        else if (auto* ints = qobject_cast<QSpinBox*>(f.widget)) ints->setValue(int(value));
        else if (auto* combo = qobject_cast<QComboBox*>(f.widget)) combo->setCurrentIndex(combo->findData(int(value)));
    }
    mShowing = false;

    mShown = preset;
    mShown = presetFromFields();  // as the fields hold it (rounded to their decimals)
    mFileErrors.clear();
    mFileNote.clear();
    mTitleLabel->setText(tr("Preset: %1").arg(QString::fromStdString(mShown.name)));
    mTitleLabel->setToolTip(QString::fromStdString(mShown.description));
    syncTissueCombo();
    updateSlopeRows();
    updateModelRows();
    validate();
}

void ParameterPanel::onEdited(int field) {
    if (mShowing) return;
    const bool ringCount = field >= kFieldEdit0 && mFields[std::size_t(field - kFieldEdit0)].widget == mRingSpin;
    updateSlopeRows();  // the ring count and the stiffening knots show their list rows
    if (field == kModelEdit) updateModelRows();
    mFileErrors.clear();
    mFileNote.clear();
    const TissuePreset after = presetFromFields();
    if (!samePreset(after, mShown)) {
        const TissuePreset before = mShown;
        mShown = after;
        // Typing "0.45" or holding an arrow is one step; the model and the ring count are choices.
        const int mergeKey = (field == kModelEdit || ringCount) ? ParameterEditCommand::kNoMerge : field;
        mUndoStack->push(new ParameterEditCommand(before, after, tr("Change %1").arg(fieldName(field)), mergeKey,
                                                  /*alreadyShown=*/true,
                                                  [this](const TissuePreset& preset) { showPreset(preset); }));
    }
    validate();
}

void ParameterPanel::updateSlopeRows() {
    const int rings = mRingSpin->value();
    for (int r = 0; r <= kMaxRings; ++r) mSlopeForm->setRowVisible(mSlopeSpins[std::size_t(r)], r <= rings);
    // The stiffening curve's knots, as many as its count says (docs/method.md).
    const PanelField* knots = nullptr;
    for (const PanelField& f : mFields)
        if (f.section == "slope_ring" && std::string(f.spec->key) == "stiffeningKnots") knots = &f;
    const int used = knots ? qobject_cast<QSpinBox*>(knots->widget)->value() : 0;
    for (const PanelField& f : mFields)
        if (f.section == "slope_ring" && f.index >= 0 && std::string(f.spec->key).rfind("stiffening", 0) == 0)
            mSpringForm->setRowVisible(f.widget, f.index < used);
}

void ParameterPanel::showApplied(const TissuePreset& running) {
    mRunning = running;
    validate();
    mAppliedLabel->setText(
        tr("Applied to the running tissue at %1").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))));
    mAppliedFade->stop();
    mAppliedOpacity->setOpacity(1.0);
    mAppliedLabel->show();
    mAppliedFade->start();
}

void ParameterPanel::revertToRunning() {
    const TissuePreset before = presetFromFields();
    if (mUnapplied.isEmpty()) return;
    mUndoStack->push(new ParameterEditCommand(before, mRunning, tr("Revert to the running tissue"),
                                              ParameterEditCommand::kNoMerge, /*alreadyShown=*/false,
                                              [this](const TissuePreset& preset) { showPreset(preset); }));
}

QLabel* ParameterPanel::rowLabelOf(QWidget* field) const {
    auto* form = qobject_cast<QFormLayout*>(field->parentWidget() ? field->parentWidget()->layout() : nullptr);
    return form ? qobject_cast<QLabel*>(form->labelForField(field)) : nullptr;
}

void ParameterPanel::updateUnappliedMarks() {
    QStringList names;
    auto mark = [&](QWidget* field, bool differs, int edit) {
        markField(field, "modified", differs);
        if (QLabel* label = rowLabelOf(field)) markField(label, "modified", differs);
        if (differs) names << fieldName(edit);
    };
    mark(mModelCombo,
         mModelCombo->currentData().toString() != QString::fromStdString(presetModelName(mRunning)), kModelEdit);
    mark(mRateSpin, mRateSpin->value() != shownAs(mRateSpin, mRunning.hapticRateHz), kRateEdit);
    const int rings = mRingSpin->value();
    for (int i = 0; i < int(mFields.size()); ++i) {
        const PanelField& f = mFields[std::size_t(i)];
        const double running = f.get(mRunning);
        bool differs = false;
        if (auto* spin = qobject_cast<QDoubleSpinBox*>(f.widget)) differs = spin->value() != shownAs(spin, running);
        else if (auto* ints = qobject_cast<QSpinBox*>(f.widget)) differs = ints->value() != int(running);
        else if (auto* combo = qobject_cast<QComboBox*>(f.widget)) differs = combo->currentData().toInt() != int(running);
        // A slope beyond the ring count is hidden and not used: the ring count says the difference.
        if (f.section == "slope_ring" && f.index >= 0) {
            const bool isSlope = std::string(f.spec->key) == "slopeMagnitudeMmPerN";
            if (isSlope ? f.index > rings : f.index >= mShown.model.slopeRing.stiffeningKnots) differs = false;
        }
        mark(f.widget, differs, kFieldEdit0 + i);
    }
    mUnapplied = names;
    if (!names.isEmpty()) {
        constexpr int kNamed = 4;
        QStringList shown = names.mid(0, kNamed);
        if (names.size() > kNamed) shown << tr("%n more", "", int(names.size() - kNamed));
        mUnappliedLabel->setText(tr("Not applied: %1 differ from the running tissue. Apply (Ctrl+Return) sends "
                                    "them; Revert goes back to what runs.")
                                     .arg(locale().createSeparatedList(shown)));
        mAppliedFade->stop();
        mAppliedLabel->hide();
    }
    mUnappliedBar->setVisible(!names.isEmpty());
    markField(mApplyButton, "pending", !names.isEmpty());
}

void ParameterPanel::setConfirmFunction(ConfirmFunction confirm) { mConfirm = std::move(confirm); }

std::optional<StabilityMargin> ParameterPanel::stabilityMargin() const {
    const TissuePreset p = presetFromFields();
    const TissueMesh* mesh = mMeshProvider ? mMeshProvider() : nullptr;
    if (mMarginOf && mesh == mMarginMesh && samePreset(p, *mMarginOf)) return mMargin;
    const double dtS = p.hapticRateHz > 0.0 ? 1.0 / p.hapticRateHz : 1e-3;
    mMargin = stabilityMarginIfKnown(presetModelDef(p), mesh, dtS);
    mMarginOf = p;
    mMarginMesh = mesh;
    return mMargin;
}

void ParameterPanel::updateModelRows() {
    const ModelDescriptor* model = findModelDescriptor(mModelCombo->currentData().toString().toStdString());
    const std::string section = model ? modelParamsSectionOf(*model) : std::string();
    const std::string name = model ? std::string(model->name) : std::string();
    const std::vector<std::string> sections = modelParamsSections();
    for (const PanelField& f : mFields)
        if (std::find(sections.begin(), sections.end(), f.section) != sections.end())
            mModelParamsForm->setRowVisible(f.widget,
                                            f.section == section && (!*f.spec->onlyFor || name == f.spec->onlyFor));
    mModelParamsGroup->setVisible(!section.empty());
    // The slope rows stay for the models that run on them (the slope-ring methods, volumetric-rings).
    const bool slopeRing = !model || model->section == std::string_view("slope_ring");
    mSlopeGroup->setVisible(slopeRing);
    mSpringGroup->setVisible(slopeRing);
    mStabilityLabel->setVisible(true);  // every model has a margin (docs/stability.md section 7)
    if (model) mModelParamsGroup->setTitle(tr("%1 parameters").arg(mModelCombo->currentText()));
}

void ParameterPanel::markField(QWidget* field, const char* property, bool on) {
    if (field->property(property).toBool() == on) return;
    field->setProperty(property, on);
    field->style()->unpolish(field);  // re-evaluate the style sheet's [property] selectors
    field->style()->polish(field);
    field->update();
}

QList<QWidget*> ParameterPanel::showStability(const TissuePreset& p) {
    const QLocale locale = this->locale();
    auto number = [&](double v) { return locale.toString(v, 'g', 6); };  // like the engine's messages
    QList<QWidget*> unstableFields;
    // The slope model's loop gain and its bound, shown whether or not the rest is valid.
    const double gain = p.model.slopeRing.loopGain();
    const double alpha = p.model.slopeRing.effectiveRelaxation();
    const double product = p.model.slopeRing.loopProduct();
    const bool automatic = p.model.slopeRing.forceRelaxation == 0.0;
    const QString alphaText = automatic ? tr("%1 (automatic)").arg(number(alpha)) : number(alpha);
    QString stability = tr("Loop gain |m1| × k_c = %1, α = %2").arg(number(gain), alphaText);
    const bool unstable = !(std::isfinite(product) && product < kLoopProductLimit);
    if (unstable) {
        stability += QLatin1Char('\n') +
                     tr("α·(1 + gain) = %1 ≥ 2: unstable (the surface oscillates and grows)").arg(number(product));
        unstableFields = {mSlopeSpins[0], mContactSpin, mRelaxationSpin};
    } else {
        stability += QLatin1Char('\n') + tr("α·(1 + gain) = %1 < 2: loop-gain margin %2\u00a0%")
                                             .arg(number(product))
                                             .arg(locale.toString(100.0 * slopeRingMargin(alpha, gain), 'f', 0));
    }
    // Every model's margin: the smaller of its own bound and the passivity of what it renders
    // (docs/stability.md section 7). Beyond it a set the validators allow is not refused: Apply
    // asks first; below kStabilityMarginWarning the label warns.
    const bool slopeRing = presetUsesSlopeRingParams(p);
    const std::optional<StabilityMargin> margin = stabilityMargin();
    QStringList lines;
    bool beyond = slopeRing && unstable;
    bool nearLimit = false;
    if (!margin) {
        lines << tr("Stability margin: needs the mesh (the mass-spring step bound depends on its springs)");
    } else {
        const QString percent = locale.toString(100.0 * margin->margin, 'f', 0);
        beyond = beyond || !(margin->margin > 0.0);
        nearLimit = !beyond && margin->margin < kStabilityMarginWarning;
        // (A slope-ring set beyond its loop gain says so below, and is refused.)
        if (beyond && !(slopeRing && unstable)) {
            // Far beyond (more than twice the limit) a percentage says little; the lines below say how far.
            lines << (margin->margin >= -1.0
                          ? tr("Beyond the stability margin (%1\u00a0%): Apply asks for confirmation").arg(percent)
                          : tr("Far beyond the stability margin: Apply asks for confirmation"));
        } else if (nearLimit) {
            lines << tr("Close to the stability margin: %1\u00a0% left (warning below %2\u00a0%)")
                         .arg(percent, locale.toString(100.0 * kStabilityMarginWarning, 'f', 0));
        } else if (!beyond) {
            lines << tr("Stability margin %1\u00a0%").arg(percent);
        }
    }
    if (slopeRing) lines << stability;  // the loop gain and its bound, shown whether or not the rest is valid
    if (margin) {
        QStringList engine = QString::fromStdString(margin->text).split(QLatin1Char('\n'));
        if (slopeRing && !engine.isEmpty()) engine.removeFirst();  // the loop gain, said above
        lines << engine;
    }
    mStabilityLabel->setText(lines.join(QLatin1Char('\n')));
    markField(mStabilityLabel, "unstable", beyond);
    markField(mStabilityLabel, "nearLimit", nearLimit);
    if (slopeRing) {
        mStabilityLabel->setToolTip(
            tr("The contact force iteration converges while α·(1 + gain) < 2, with the loop "
               "gain |m1| × k_c (docs/method.md): the loop-gain margin is 1 − α·(1 + gain) / 2. What the model "
               "renders, k_s·|m1|·k_c / (1 + gain) (and, for ours with friction, the proxy's spring), must stay "
               "below the stiffness the device renders passively at the haptic rate (1 N/mm at 1 kHz); a lagging "
               "or alternating relaxation (α away from 1 / (1 + gain)) asks more of it (docs/stability.md)."));
    } else {
        mStabilityLabel->setToolTip(tr(
            "How far the set is from its derived stability bound at the haptic rate (docs/stability.md): the "
            "explicit mass-spring integrators' step bound h·ω_max < 2 (RK4 2.78), ω_max from Gershgorin's bound "
            "and the sub-steps the model takes; and for every model the stiffness it renders (for mass-spring "
            "measured on the mesh) against the stiffness the device renders passively (Colgate and Brown, 1 N/mm "
            "at 1 kHz). Backward Euler has no step bound."));
    }
    return unstableFields;
}

void ParameterPanel::validate() {
    const TissuePreset p = presetFromFields();
    const QLocale locale = this->locale();
    auto number = [&](double v) { return locale.toString(v, 'g', 6); };  // like the engine's messages

    QStringList problems;
    QSet<QWidget*> invalid;
    // The engine's own validators: each problem names its field, which names the widget.
    auto take = [&](const std::string& section, const Problems& found, bool withName) {
        for (const Problem& problem : found) {
            const std::vector<const PanelField*> named = fieldsNamedBy(section, problem);
            for (const PanelField* f : named) invalid.insert(f->widget);
            const QString message = QString::fromStdString(problem.message);
            problems << (withName && named.size() == 1
                             ? tr("%1: %2").arg(fieldName(kFieldEdit0 + int(named.front() - mFields.data())), message)
                             : message);
        }
    };
    take("slope_ring", validateSlopeRingParams(p.model.slopeRing), false);
    // The chosen registry model's own validator.
    if (const std::string section = modelParamsSectionOf(modelDescriptor(presetModelDef(p))); !section.empty())
        take(section, validateModelDef(presetModelDef(p)), true);
    take("octree", validateOctreeDef(p.octree), false);
    {
        QList<QWidget*> badTissue;
        problems << tissueProblems(&badTissue);
        for (QWidget* field : badTissue) invalid.insert(field);
    }
    if (!hapticRateInRange(p.hapticRateHz)) {
        problems << tr("haptic rate = %1 Hz must be in %2..%3 Hz")
                        .arg(number(p.hapticRateHz))
                        .arg(number(kMinHapticRateHz))
                        .arg(number(kMaxHapticRateHz));
        invalid.insert(mRateSpin);
    }

    for (QWidget* field : showStability(p)) invalid.insert(field);

    // Allowed, but not the paper's: slopes above 1 mm/N under a raised limit.
    QStringList notes;
    QSet<QWidget*> outside;
    QStringList outsideNames;
    for (int r = 0; r <= p.model.slopeRing.ringCount && r <= kMaxRings; ++r) {
        QDoubleSpinBox* spin = mSlopeSpins[std::size_t(r)];
        if (p.model.slopeRing.slopeMagnitudeMmPerN[std::size_t(r)] >= kPaperSlopeMaxMmPerN && !invalid.contains(spin)) {
            outside.insert(spin);
            outsideNames << QStringLiteral("|m%1|").arg(r + 1);
        }
    }
    if (!outsideNames.isEmpty()) {
        const QString text = outsideNames.size() == 1
                                 ? tr("%1 is outside the paper's range (0, 1) mm/N: allowed by the slope limit %2 "
                                      "mm/N and the loop-gain bound.")
                                 : tr("%1 are outside the paper's range (0, 1) mm/N: allowed by the slope limit %2 "
                                      "mm/N and the loop-gain bound.");
        notes << text.arg(locale.createSeparatedList(outsideNames), number(p.model.slopeRing.slopeLimitMmPerN));
    }
    if (!mFileNote.isEmpty()) notes.prepend(mFileNote);

    const QList<QWidget*> fields = findChildren<QWidget*>();
    for (QWidget* field : fields) {
        if (!qobject_cast<QAbstractSpinBox*>(field)) continue;
        markField(field, "invalid", invalid.contains(field));
        markField(field, "outsidePaperRange", outside.contains(field));
    }

    QStringList shown = mFileErrors;
    shown << problems;
    mMessageLabel->setText(shown.join(QLatin1Char('\n')));
    mMessageLabel->setVisible(!shown.isEmpty());
    mNoteLabel->setText(notes.join(QLatin1Char('\n')));
    mNoteLabel->setVisible(!notes.isEmpty());
    updateCalibrationLabel();

    mProblems = problems;
    const bool valid = problems.isEmpty();
    mApplyButton->setEnabled(valid);
    updateUnappliedMarks();
    if (valid != mValid) {
        mValid = valid;
        emit validityChanged(valid);
    }
}

void ParameterPanel::apply() {
    validate();
    if (!mValid) return;
    const TissuePreset p = preset();
    // A slope-ring set beyond its loop gain is invalid (above); beyond the margin otherwise (the
    // passivity of any model, a mass-spring step bound) Apply asks (docs/stability.md section 7).
    if (const auto margin = stabilityMargin(); margin && !(margin->margin > 0.0)) {
            const QString title = tr("Beyond the stability margin");
            const QString text =
                tr("This parameter set is beyond its stability margin:\n%1\n\nThe model may diverge (or the device "
                   "buzz); the divergence guard would then zero the force and reset the tissue. Apply anyway?")
                    .arg(QString::fromStdString(margin->text));
            const bool go = mConfirm ? mConfirm(title, text) : [&] {
                QMessageBox box(QMessageBox::Warning, title, text, QMessageBox::Yes | QMessageBox::No, this);
                box.setObjectName(QStringLiteral("stabilityConfirmBox"));
                box.setDefaultButton(QMessageBox::No);
                return box.exec() == QMessageBox::Yes;
            }();
            if (!go) return;
        }
    emit applyRequested(p);
}

bool ParameterPanel::loadPresetFile(const QString& path, QString* error) {
    const std::string file = QDir::toNativeSeparators(path).toStdString();
    const PresetLoadResult result = guardedLoad(file, [&] { return loadTissuePreset(file); });
    if (!result.preset) {
        mFileErrors.clear();
        for (const std::string& message : result.errors) mFileErrors << QString::fromStdString(message);
        if (mFileErrors.isEmpty()) mFileErrors << tr("%1: could not be read").arg(path);
        mFileErrors.prepend(tr("Preset not loaded; the fields are unchanged:"));
        mFileNote.clear();
        validate();
        if (error) *error = mFileErrors.mid(1).join(QLatin1Char('\n'));
        return false;
    }
    const TissuePreset before = presetFromFields();
    if (!samePreset(before, *result.preset))
        mUndoStack->push(new ParameterEditCommand(before, *result.preset,
                                                  tr("Load preset %1").arg(QFileInfo(path).fileName()),
                                                  ParameterEditCommand::kNoMerge, /*alreadyShown=*/false,
                                                  [this](const TissuePreset& preset) { showPreset(preset); }));
    mUndoStack->setClean();
    mLastDirectory = QFileInfo(path).absolutePath();
    mPresetFile = QFileInfo(path).absoluteFilePath();
    mFileErrors.clear();
    mFileNote = tr("Loaded %1").arg(QDir::toNativeSeparators(path));
    if (const auto& stored = result.preset->stabilityMargin)
        mFileNote += QLatin1Char(' ') + tr("(saved with a stability margin of %1 % at %2 Hz)")
                                            .arg(locale().toString(100.0 * stored->margin, 'f', 0))
                                            .arg(locale().toString(1.0 / stored->dtS, 'g', 6));
    validate();
    if (error) error->clear();
    return true;
}

bool ParameterPanel::savePresetFile(const QString& path, QString* error) {
    QString problem;
    if (!mValid) {
        problem = tr("%1: not saved, the parameters are not valid (see above); the file could not be read back")
                      .arg(QDir::toNativeSeparators(path));
    } else {
        // The margin of the set at its haptic rate goes with it (informational on load); without
        // the mesh a mass-spring margin is unknown and none is written.
        TissuePreset toSave = preset();
        // Saved under another file's name, it is that name's preset (a copy made to be changed):
        // "Save preset" suggests NAME.json, so keeping the suggestion keeps the name.
        const QFileInfo target(path);
        if (target.absoluteFilePath() != mPresetFile &&
            target.completeBaseName() != QString::fromStdString(toSave.name))
            toSave.name = target.completeBaseName().toStdString();
        toSave.stabilityMargin.reset();
        if (const auto margin = stabilityMargin())
            toSave.stabilityMargin = PresetStabilityMargin{margin->margin, 1.0 / toSave.hapticRateHz};
        problem = QString::fromStdString(saveTissuePreset(toSave, QDir::toNativeSeparators(path).toStdString()));
        if (problem.isEmpty() && toSave.name != mShown.name) {
            mShown.name = toSave.name;
            mTitleLabel->setText(tr("Preset: %1").arg(QString::fromStdString(mShown.name)));
        }
    }
    if (!problem.isEmpty()) {
        mFileErrors = QStringList{problem};
        mFileNote.clear();
        validate();
        if (error) *error = problem;
        return false;
    }
    mUndoStack->setClean();
    mLastDirectory = QFileInfo(path).absolutePath();
    mPresetFile = QFileInfo(path).absoluteFilePath();
    mFileErrors.clear();
    mFileNote = tr("Saved %1").arg(QDir::toNativeSeparators(path));
    validate();
    if (error) error->clear();
    return true;
}

void ParameterPanel::openPresetDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open preset"), mLastDirectory,
                                                      tr("Tissue presets (*.json);;All files (*)"));
    if (!path.isEmpty()) loadPresetFile(path);
}

void ParameterPanel::savePresetDialog() {
    QString start = mLastDirectory;
    if (!mShown.name.empty())
        start = QDir(mLastDirectory.isEmpty() ? QDir::currentPath() : mLastDirectory)
                    .filePath(QString::fromStdString(mShown.name) + QStringLiteral(".json"));
    QString path = QFileDialog::getSaveFileName(this, tr("Save preset"), start,
                                                tr("Tissue presets (*.json);;All files (*)"));
    path = withSuffixConfirmed(this, path, QStringLiteral(".json"));
    if (path.isEmpty()) return;
    savePresetFile(path);
}

}  // namespace palpate
