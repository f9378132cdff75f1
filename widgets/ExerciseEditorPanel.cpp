#include "widgets/ExerciseEditorPanel.h"

#include "widgets/ExerciseText.h"

#include "widgets/SaveFileChoice.h"
#include "widgets/GuardedLoad.h"
#include "widgets/ScrollWheelGuard.h"

#include "widgets/ExerciseEditCommands.h"
#include "widgets/Viewport.h"

#include "device/HapticDevice.h"
#include "engine/exercise/ExerciseBundle.h"
#include "engine/exercise/ExerciseTravel.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/scene/TissuePreset.h"
#include "engine/exercise/ExerciseKind.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSet>
#include <QSpinBox>
#include <QStackedWidget>
#include <QStyle>
#include <QStyledItemDelegate>
#include <QTableWidget>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace palpate {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }
std::string ss(const QString& s) { return s.toStdString(); }

/// The index of a type in exerciseKinds() (the order of the type combo, the New actions and the pages).
int typeIndex(ExerciseType type) {
    const auto kinds = exerciseKinds();
    for (std::size_t i = 0; i < kinds.size(); ++i)
        if (kinds[i]->type() == type) return int(i);
    return 0;
}

/// Files the shipped resources are found by (their folder is resources/).
constexpr const char* kResourceAnchors[] = {"meshes/stomach_3970.off", "meshes/sphere_1442.off",
                                            "presets/tissues/phantom_gel.json"};
constexpr const char* kDefaultMesh = "meshes/stomach_3970.off";
/// The new exercise's tissue: the stomach wall on the default stomach, else the gel phantom.
constexpr const char* kDefaultPresets[] = {"presets/tissues/stomach_wall.json", "presets/tissues/phantom_gel.json"};

/// The item table's columns: its number, its vertex, then the item's numbers (ExerciseEditing.h).
enum ItemColumn { kItemNumber, kItemVertex, kItemNumbers };
enum RubricColumn { kRubricMetric, kRubricUnit, kRubricWeight, kRubricFull, kRubricZero, kRubricColumns };
constexpr const char* kRubricKeys[] = {"", "", "weight", "full", "zero"};

/// Sets a flag for the duration of a scope (widgets being set by code, not by the user).
class Guard {
public:
    explicit Guard(bool& flag) : mFlag(flag), mOld(flag) { mFlag = true; }
    ~Guard() { mFlag = mOld; }
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;

private:
    bool& mFlag;
    bool mOld;
};

/// In-place numbers in the tables: a spin box with the column's range, shown with as many
/// digits as the value needs.
class NumberDelegate final : public QStyledItemDelegate {
public:
    NumberDelegate(QObject* parent, double lo, double hi, int decimals)
        : QStyledItemDelegate(parent), mLo(lo), mHi(hi), mDecimals(decimals) {}

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex&) const override {
        if (mDecimals == 0) {
            auto* spin = new QSpinBox(parent);
            spin->setRange(int(mLo), int(mHi));
            spin->setFrame(false);
            spin->setAlignment(Qt::AlignRight);
            return spin;
        }
        auto* spin = new QDoubleSpinBox(parent);
        spin->setRange(mLo, mHi);
        spin->setDecimals(mDecimals);
        spin->setFrame(false);
        spin->setAlignment(Qt::AlignRight);
        return spin;
    }

    QString displayText(const QVariant& value, const QLocale& locale) const override {
        if (value.typeId() == QMetaType::Double) return locale.toString(value.toDouble(), 'g', 6);
        return QStyledItemDelegate::displayText(value, locale);
    }

private:
    double mLo, mHi;
    int mDecimals;
};

/// The unit combo's rows: the named units (engine/core/MeshUnit.h has their factors), then
/// "scale…" (a factor of the exercise's own).
const char* const kMeshUnitNames[] = {"mm", "cm", "m", "in"};
constexpr int kScaleChoice = 4;
constexpr int kMeshUnitChoices = 5;

MeshUnit namedMeshUnit(int index) {
    std::string ignored;
    return parseMeshUnit(kMeshUnitNames[index], ignored).value_or(kMillimetres);
}

int meshUnitChoice(const MeshUnit& unit) {
    for (int i = 0; i < kScaleChoice; ++i)
        if (unit.name == kMeshUnitNames[i]) return i;
    return kScaleChoice;
}

QDoubleSpinBox* doubleSpin(QWidget* parent, const char* objectName, double lo, double hi, int decimals, double step) {
    auto* spin = new QDoubleSpinBox(parent);
    spin->setObjectName(QLatin1String(objectName));
    spin->setDecimals(decimals);
    spin->setRange(lo, hi);
    spin->setSingleStep(step);
    spin->setAccelerated(true);
    spin->setAlignment(Qt::AlignRight);
    return spin;
}

/// The value a spin box holds after setValue(value): QDoubleSpinBox rounds to its decimals so.
double shownAs(const QDoubleSpinBox* spin, double value) {
    return QString::number(std::clamp(value, spin->minimum(), spin->maximum()), 'f', spin->decimals()).toDouble();
}

/// Sets a spin box only when it shows another value, so that the one being typed in keeps its text.
void setSpin(QDoubleSpinBox* spin, double value) {
    if (spin->value() != shownAs(spin, value)) spin->setValue(value);
}

QTableWidgetItem* cell(QTableWidget* table, int row, int column) {
    QTableWidgetItem* item = table->item(row, column);
    if (!item) {
        item = new QTableWidgetItem;
        table->setItem(row, column, item);
    }
    return item;
}

/// Sets a cell's value only when it differs (a change re-emits itemChanged and resets an editor).
void setCellValue(QTableWidget* table, int row, int column, const QVariant& value, bool editable) {
    QTableWidgetItem* item = cell(table, row, column);
    if (item->data(Qt::EditRole) != value) item->setData(Qt::EditRole, value);
    const Qt::ItemFlags flags = Qt::ItemIsSelectable | Qt::ItemIsEnabled | (editable ? Qt::ItemIsEditable : Qt::NoItemFlags);
    if (item->flags() != flags) item->setFlags(flags);
    const Qt::Alignment alignment = (column == 0 ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter;
    if (Qt::Alignment(item->textAlignment()) != alignment) item->setTextAlignment(alignment);
}

/// A table tall enough for `rows` rows (at most `maxRows`, then it scrolls itself): inside the
/// panel's scroll area a table should not also scroll when it fits.
void fitTableHeight(QTableWidget* table, int rows, int maxRows) {
    const int rowHeight = table->verticalHeader()->defaultSectionSize();
    const int shown = std::clamp(rows, 1, maxRows);
    table->setFixedHeight(table->horizontalHeader()->sizeHint().height() + shown * rowHeight + 2 * table->frameWidth() + 2);
}

/// The key a problem names ("press_targets.targets[0].force_max_n: ..." -> its key).
QString problemKey(const QString& problem) { return problem.section(QLatin1Char(':'), 0, 0).trimmed(); }

/// Styles: a field named by a problem is framed red; problems in red, notes muted.
const char* const kStyleSheet = R"(
QAbstractSpinBox[invalid="true"], QLineEdit[invalid="true"], QComboBox[invalid="true"] {
  border: 2px solid #d32f2f; border-radius: 3px; background-color: #fff0f0; }
QLabel#problemsLabel { color: #c62828; }
QLabel#warningsLabel { color: #8a5a00; background-color: #fff8e1; border: 1px solid #ffcc80; border-radius: 3px; padding: 3px; }
QLabel#checkingLabel { color: #616161; font-style: italic; }
QLabel#messageLabel[error="true"] { color: #c62828; }
QLabel#messageLabel[error="false"] { color: #2e7d32; }
QLabel#placingLabel { background-color: #e3f2fd; border: 1px solid #90caf9; border-radius: 3px; padding: 3px; }
QLabel#exerciseTitleLabel { font-weight: bold; }
)";

const QColor kInvalidCell(255, 224, 224);
/// How long a reach check runs before the editor says it is checking.
constexpr int kCheckingShownAfterMs = 250;
const QColor kWarningCell(255, 236, 179);
const QColor kDefaultRubricText(120, 120, 120);

/// A titled group of `fields` with a form layout, added to `fieldsLayout`.
QFormLayout* addFormGroup(QWidget* fields, QVBoxLayout* fieldsLayout, QGroupBox*& group, const char* name) {
    group = new QGroupBox(fields);
    group->setObjectName(QLatin1String(name));
    auto* form = new QFormLayout(group);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setRowWrapPolicy(QFormLayout::DontWrapRows);
    fieldsLayout->addWidget(group);
    return form;
}

}  // namespace

ExerciseEditorPanel::ExerciseEditorPanel(ResourceFinder findResource, QWidget* parent)
    : QWidget(parent),
      mFindResource(std::move(findResource)),
      mDocument(std::make_unique<ExerciseDocument>(mFindResource, touchReach())) {
    // resources/ itself: the folder a shipped file is found in (the finder only finds files).
    if (mFindResource)
        for (const char* anchor : kResourceAnchors) {
            const QString found = qs(mFindResource(anchor));
            if (found.endsWith(QLatin1String(anchor))) {
                mResourceRoot = QDir::cleanPath(found.chopped(int(std::strlen(anchor))));
                break;
            }
        }
    mUndoStack = new QUndoStack(this);
    mDiscardQuestion = [this](const QString& name) {
        const auto answer = QMessageBox::warning(
            this, tr("Unsaved exercise"),
            tr("The exercise \"%1\" has changes that are not saved. Save them first?").arg(name),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        return answer == QMessageBox::Save ? DiscardAnswer::Save
               : answer == QMessageBox::Discard ? DiscardAnswer::Discard
                                                : DiscardAnswer::Cancel;
    };
    buildUi();
    retranslateUi();
    fillResourceCombos();
    connect(mUndoStack, &QUndoStack::cleanChanged, this, [this](bool clean) {
        updateTitle();
        emit modifiedChanged(!clean);
    });
    newExercise(ExerciseType::PressTargets);
}

ExerciseEditorPanel::~ExerciseEditorPanel() {
    // Nothing the children say on their way out (a field losing focus, the undo stack's
    // cleanChanged) may reach this half-destroyed panel.
    for (QObject* child : findChildren<QObject*>()) child->blockSignals(true);
    // Waits for a running reach check: its callback must not reach a panel that is half gone.
    mDocument.reset();
}

QLabel* ExerciseEditorPanel::rowLabel(const char* text) {
    auto* label = new QLabel(this);
    mRowLabels.emplace_back(label, text);
    return label;
}

void ExerciseEditorPanel::buildUi() {
    setObjectName(QStringLiteral("exerciseEditorPanel"));
    setStyleSheet(QLatin1String(kStyleSheet));
    createActions();
    QHBoxLayout* fileRow = buildFileRow();
    mTitleLabel = new QLabel(this);
    mTitleLabel->setObjectName(QStringLiteral("exerciseTitleLabel"));
    mTitleLabel->setWordWrap(true);
    mTitleLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The form scrolls; the file row, the title, the placing hint, the problems and Try it stay put.
    auto* fields = new QWidget;
    auto* fieldsLayout = new QVBoxLayout(fields);
    fieldsLayout->setContentsMargins(0, 0, 0, 0);
    buildExerciseForm(addFormGroup(fields, fieldsLayout, mExerciseGroup, "exerciseGroup"));
    buildSceneForm(addFormGroup(fields, fieldsLayout, mSceneGroup, "sceneGroup"));
    buildLimitsForm(addFormGroup(fields, fieldsLayout, mLimitsGroup, "limitsGroup"));
    fieldsLayout->addWidget(buildTypeGroup(fields));
    fieldsLayout->addWidget(buildRubricGroup(fields));
    fieldsLayout->addStretch(1);

    auto* scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("exerciseEditorScroll"));
    scroll->setWidget(fields);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    guardScrollWheel(*scroll);

    QHBoxLayout* previewRow = buildFeedback();
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(fileRow);
    layout->addWidget(mTitleLabel);
    layout->addWidget(scroll, 1);
    layout->addWidget(mPlacingLabel);
    layout->addWidget(mProblemsLabel);
    layout->addWidget(mCheckingLabel);
    layout->addWidget(mWarningsLabel);
    layout->addWidget(mMessageLabel);
    layout->addLayout(previewRow);

    connectEdits();
}

void ExerciseEditorPanel::createActions() {
    mUndoAction = mUndoStack->createUndoAction(this, tr("Undo"));
    mUndoAction->setObjectName(QStringLiteral("exerciseUndoAction"));
    mUndoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_Z)});
    mUndoAction->setIcon(QIcon::fromTheme(QStringLiteral("edit-undo"), style()->standardIcon(QStyle::SP_ArrowBack)));
    mRedoAction = mUndoStack->createRedoAction(this, tr("Redo"));
    mRedoAction->setObjectName(QStringLiteral("exerciseRedoAction"));
    mRedoAction->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)});
    mRedoAction->setIcon(QIcon::fromTheme(QStringLiteral("edit-redo"), style()->standardIcon(QStyle::SP_ArrowForward)));
    for (const ExerciseKind* kind : exerciseKinds()) {
        auto* action = new QAction(this);
        action->setObjectName(QStringLiteral("newExerciseAction_") + qs(std::string(kind->key())));
        const ExerciseType type = kind->type();
        connect(action, &QAction::triggered, this, [this, type] {
            if (confirmDiscard()) newExercise(type);
        });
        mNewActions.push_back(action);
    }
    mOpenAction = new QAction(this);
    mOpenAction->setObjectName(QStringLiteral("openExerciseAction"));
    mOpenAction->setShortcut(QKeySequence::Open);
    mOpenAction->setIcon(style()->standardIcon(QStyle::SP_DialogOpenButton));
    connect(mOpenAction, &QAction::triggered, this, &ExerciseEditorPanel::openDialog);
    mSaveAction = new QAction(this);
    mSaveAction->setObjectName(QStringLiteral("saveExerciseAction"));
    mSaveAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_S));
    mSaveAction->setIcon(style()->standardIcon(QStyle::SP_DialogSaveButton));
    connect(mSaveAction, &QAction::triggered, this, [this] { save(); });
    mSaveAsAction = new QAction(this);
    mSaveAsAction->setObjectName(QStringLiteral("saveExerciseAsAction"));
    mSaveAsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    connect(mSaveAsAction, &QAction::triggered, this, &ExerciseEditorPanel::saveAsDialog);
    mExportBundleAction = new QAction(this);
    mExportBundleAction->setObjectName(QStringLiteral("exportBundleAction"));
    connect(mExportBundleAction, &QAction::triggered, this, &ExerciseEditorPanel::exportBundleDialog);
    mPreviewAction = new QAction(this);
    mPreviewAction->setObjectName(QStringLiteral("previewExerciseAction"));
    mPreviewAction->setShortcut(QKeySequence(Qt::Key_F5));
    mPreviewAction->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    connect(mPreviewAction, &QAction::triggered, this, &ExerciseEditorPanel::preview);
    mStopPlacingAction = new QAction(this);
    mStopPlacingAction->setObjectName(QStringLiteral("stopPlacingAction"));
    mStopPlacingAction->setShortcut(QKeySequence(Qt::Key_Escape));
    connect(mStopPlacingAction, &QAction::triggered, this, [this] { setPlacing(Placing::None); });
    for (QAction* action : {mUndoAction, mRedoAction, mOpenAction, mSaveAction, mSaveAsAction, mPreviewAction,
                            mStopPlacingAction}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        addAction(action);
    }
    // The click that placed a point gave the viewport the focus: Esc still stops (the action is
    // enabled only while placing, so it takes Esc from nothing else).
    mStopPlacingAction->setShortcutContext(Qt::WindowShortcut);
    // Remove and move act on the selected row of the table or list that has the focus.
    mRemoveAction = new QAction(this);
    mRemoveAction->setShortcut(QKeySequence::Delete);
    connect(mRemoveAction, &QAction::triggered, this, &ExerciseEditorPanel::removeSelected);
    mMoveUpAction = new QAction(this);
    mMoveUpAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Up));
    connect(mMoveUpAction, &QAction::triggered, this, [this] { moveSelected(-1); });
    mMoveDownAction = new QAction(this);
    mMoveDownAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Down));
    connect(mMoveDownAction, &QAction::triggered, this, [this] { moveSelected(+1); });
}

QHBoxLayout* ExerciseEditorPanel::buildFileRow() {
    // The file row: New (a menu of the three types), Open, Save, Save As, undo, redo; Try it.
    auto toolButton = [this](const char* name, QAction* action) {
        auto* button = new QToolButton(this);
        button->setObjectName(QLatin1String(name));
        if (action) button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setAutoRaise(true);
        return button;
    };
    mNewButton = toolButton("newExerciseButton", nullptr);
    mNewButton->setIcon(style()->standardIcon(QStyle::SP_FileIcon));
    auto* newMenu = new QMenu(mNewButton);
    for (QAction* action : mNewActions) newMenu->addAction(action);
    mNewButton->setMenu(newMenu);
    mNewButton->setPopupMode(QToolButton::InstantPopup);
    mOpenButton = toolButton("openExerciseButton", mOpenAction);
    mSaveButton = toolButton("saveExerciseButton", mSaveAction);
    mSaveAsButton = toolButton("saveExerciseAsButton", mSaveAsAction);
    mSaveAsButton->setToolButtonStyle(Qt::ToolButtonTextOnly);
    mUndoButton = toolButton("exerciseUndoButton", mUndoAction);
    mUndoButton->setToolButtonStyle(Qt::ToolButtonIconOnly);
    mRedoButton = toolButton("exerciseRedoButton", mRedoAction);
    mRedoButton->setToolButtonStyle(Qt::ToolButtonIconOnly);
    auto* fileRow = new QHBoxLayout;
    fileRow->setSpacing(2);
    for (QToolButton* b : {mNewButton, mOpenButton, mSaveButton, mSaveAsButton}) fileRow->addWidget(b);
    fileRow->addStretch(1);
    fileRow->addWidget(mUndoButton);
    fileRow->addWidget(mRedoButton);

    return fileRow;
}

void ExerciseEditorPanel::buildExerciseForm(QFormLayout* exerciseForm) {
    mTypeCombo = new QComboBox(mExerciseGroup);
    mTypeCombo->setObjectName(QStringLiteral("exerciseTypeCombo"));
    for (std::size_t i = 0; i < exerciseKinds().size(); ++i) mTypeCombo->addItem(QString());
    exerciseForm->addRow(rowLabel(QT_TR_NOOP("Type:")), mTypeCombo);
    mTextLanguageCombo = new QComboBox(mExerciseGroup);
    mTextLanguageCombo->setObjectName(QStringLiteral("exerciseTextLanguageCombo"));
    for (const char* code : {"", "de", "ms"}) mTextLanguageCombo->addItem(QString(), QString::fromLatin1(code));
    exerciseForm->addRow(rowLabel(QT_TR_NOOP("Text in:")), mTextLanguageCombo);
    mNameEdit = new QLineEdit(mExerciseGroup);
    mNameEdit->setObjectName(QStringLiteral("exerciseNameEdit"));
    exerciseForm->addRow(rowLabel(QT_TR_NOOP("Name:")), mNameEdit);
    mDescriptionEdit = new QPlainTextEdit(mExerciseGroup);
    mDescriptionEdit->setObjectName(QStringLiteral("exerciseDescriptionEdit"));
    mDescriptionEdit->setTabChangesFocus(true);
    mDescriptionEdit->setFixedHeight(mDescriptionEdit->fontMetrics().lineSpacing() * 3 + 12);
    exerciseForm->addRow(rowLabel(QT_TR_NOOP("Description:")), mDescriptionEdit);
}

void ExerciseEditorPanel::buildSceneForm(QFormLayout* sceneForm) {
    auto pathRow = [&](QComboBox*& combo, QPushButton*& browse, const char* comboName, const char* browseName) {
        auto* row = new QWidget(mSceneGroup);
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(4);
        combo = new QComboBox(row);
        combo->setObjectName(QLatin1String(comboName));
        combo->setEditable(true);
        combo->setInsertPolicy(QComboBox::NoInsert);
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(12);
        combo->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        browse = new QPushButton(row);
        browse->setObjectName(QLatin1String(browseName));
        layout->addWidget(combo, 1);
        layout->addWidget(browse);
        return row;
    };
    // Labels above the paths: a path needs the dock's whole width.
    sceneForm->setRowWrapPolicy(QFormLayout::WrapAllRows);
    sceneForm->addRow(rowLabel(QT_TR_NOOP("Mesh:")), pathRow(mMeshCombo, mMeshBrowseButton, "meshCombo", "meshBrowseButton"));
    {
        auto* row = new QWidget(mSceneGroup);
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        mShowMeshButton = new QPushButton(row);
        mShowMeshButton->setObjectName(QStringLiteral("showMeshButton"));
        mMeshStateLabel = new QLabel(row);
        mMeshStateLabel->setObjectName(QStringLiteral("meshStateLabel"));
        layout->addWidget(mShowMeshButton);
        layout->addWidget(mMeshStateLabel, 1);
        sceneForm->addRow(row);
    }
    {
        // The mesh file's unit: named units, or a factor typed beside "scale…".
        auto* row = new QWidget(mSceneGroup);
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(4);
        mMeshUnitCombo = new QComboBox(row);
        mMeshUnitCombo->setObjectName(QStringLiteral("meshUnitCombo"));
        for (int i = 0; i < kMeshUnitChoices; ++i) mMeshUnitCombo->addItem(QString());
        mMeshScaleSpin = doubleSpin(row, "meshScaleSpin", kMinMmPerUnit, kMaxMmPerUnit, 6, 0.1);
        mMeshScaleSpin->setValue(1.0);
        layout->addWidget(mMeshUnitCombo);
        layout->addWidget(mMeshScaleSpin, 1);
        layout->addStretch(0);
        sceneForm->addRow(rowLabel(QT_TR_NOOP("Mesh unit:")), row);
    }
    sceneForm->addRow(rowLabel(QT_TR_NOOP("Tissue preset:")),
                      pathRow(mPresetCombo, mPresetBrowseButton, "tissuePresetCombo", "tissuePresetBrowseButton"));
}

void ExerciseEditorPanel::buildLimitsForm(QFormLayout* limitsForm) {
    mTimeLimitSpin = doubleSpin(mLimitsGroup, "timeLimitSpin", 0.0, 3600.0, 1, 5.0);
    limitsForm->addRow(rowLabel(QT_TR_NOOP("Time limit:")), mTimeLimitSpin);
    mDisplacementSpin = doubleSpin(mLimitsGroup, "displacementLimitSpin", 0.0, 1000.0, 2, 0.5);
    limitsForm->addRow(rowLabel(QT_TR_NOOP("Damage beyond:")), mDisplacementSpin);
    mExcessiveSpin = doubleSpin(mLimitsGroup, "excessiveForceSpin", 0.0, 1000.0, 2, 0.1);
    limitsForm->addRow(rowLabel(QT_TR_NOOP("Excessive force:")), mExcessiveSpin);
    mLiveScoreCheck = new QCheckBox(mLimitsGroup);
    mLiveScoreCheck->setObjectName(QStringLiteral("liveScoreCheck"));
    limitsForm->addRow(mLiveScoreCheck);
    // Level-of-detail targets (docs/lod.md): optional; the Level of Detail dock plans against them.
    mNeedsCheck = new QCheckBox(tr("State level-of-detail targets"), mLimitsGroup);
    mNeedsCheck->setObjectName(QStringLiteral("needsCheck"));
    mNeedsCheck->setToolTip(tr("The accuracy and haptic time the model for this exercise must meet (needs)"));
    limitsForm->addRow(mNeedsCheck);
    mNeedsErrorSpin = doubleSpin(mLimitsGroup, "needsErrorSpin", 0.1, 1000.0, 1, 1.0);
    mNeedsErrorSpin->setSuffix(QStringLiteral(" %"));
    mNeedsErrorSpin->setToolTip(tr("Largest displacement error against the reference (needs.max_error)"));
    limitsForm->addRow(rowLabel(QT_TR_NOOP("Max error:")), mNeedsErrorSpin);
    mNeedsBudgetSpin = doubleSpin(mLimitsGroup, "needsBudgetSpin", 0.001, 1e6, 3, 10.0);
    mNeedsBudgetSpin->setSuffix(QStringLiteral(" µs"));
    mNeedsBudgetSpin->setToolTip(tr("Longest haptic tick the model may take (needs.budget_us)"));
    limitsForm->addRow(rowLabel(QT_TR_NOOP("Tick budget:")), mNeedsBudgetSpin);
}

QGroupBox* ExerciseEditorPanel::buildTypeGroup(QWidget* fields) {
    mTypeGroup = new QGroupBox(fields);
    mTypeGroup->setObjectName(QStringLiteral("typeGroup"));
    auto* typeLayout = new QVBoxLayout(mTypeGroup);
    mTypePages = new QStackedWidget(mTypeGroup);
    mTypePages->setObjectName(QStringLiteral("typePages"));
    typeLayout->addWidget(mTypePages);
    buildTypePages();
    // A stacked widget is as tall as its tallest page; the type group should fit the page shown.
    const auto fitPage = [this](int current) {
        for (int i = 0; i < mTypePages->count(); ++i)
            mTypePages->widget(i)->setSizePolicy(i == current ? QSizePolicy::Preferred : QSizePolicy::Ignored,
                                                 i == current ? QSizePolicy::Preferred : QSizePolicy::Ignored);
        mTypePages->updateGeometry();
    };
    connect(mTypePages, &QStackedWidget::currentChanged, this, fitPage);
    fitPage(mTypePages->currentIndex());

    return mTypeGroup;
}

QGroupBox* ExerciseEditorPanel::buildRubricGroup(QWidget* fields) {
    mRubricGroup = new QGroupBox(fields);
    mRubricGroup->setObjectName(QStringLiteral("rubricGroup"));
    auto* rubricLayout = new QVBoxLayout(mRubricGroup);
    mRubricTable = new QTableWidget(0, kRubricColumns, mRubricGroup);
    mRubricTable->setObjectName(QStringLiteral("rubricTable"));
    mRubricTable->verticalHeader()->setVisible(false);
    mRubricTable->verticalHeader()->setDefaultSectionSize(mRubricTable->fontMetrics().height() + 8);
    mRubricTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    mRubricTable->setSelectionMode(QAbstractItemView::SingleSelection);
    mRubricTable->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                                  QAbstractItemView::AnyKeyPressed);
    mRubricTable->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    mRubricTable->setTextElideMode(Qt::ElideMiddle);  // "excessive_…_events": both ends say which
    mRubricTable->setItemDelegateForColumn(kRubricWeight, new NumberDelegate(mRubricTable, 0.0, 1000.0, 3));
    mRubricTable->setItemDelegateForColumn(kRubricFull, new NumberDelegate(mRubricTable, -1.0e6, 1.0e6, 4));
    mRubricTable->setItemDelegateForColumn(kRubricZero, new NumberDelegate(mRubricTable, -1.0e6, 1.0e6, 4));
    mRubricTable->horizontalHeader()->setSectionResizeMode(kRubricMetric, QHeaderView::Stretch);
    for (int c = kRubricUnit; c < kRubricColumns; ++c)
        mRubricTable->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    rubricLayout->addWidget(mRubricTable);
    auto* rubricRow = new QHBoxLayout;
    mRubricTotalLabel = new QLabel(mRubricGroup);
    mRubricTotalLabel->setObjectName(QStringLiteral("rubricTotalLabel"));
    mRubricTotalLabel->setWordWrap(true);
    mRubricTotalLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mResetRubricButton = new QPushButton(mRubricGroup);
    mResetRubricButton->setObjectName(QStringLiteral("resetRubricButton"));
    rubricRow->addWidget(mRubricTotalLabel, 1);
    rubricRow->addWidget(mResetRubricButton);
    rubricLayout->addLayout(rubricRow);
    return mRubricGroup;
}

QHBoxLayout* ExerciseEditorPanel::buildFeedback() {
    mPlacingLabel = new QLabel(this);
    mPlacingLabel->setObjectName(QStringLiteral("placingLabel"));
    mPlacingLabel->setWordWrap(true);
    mPlacingLabel->setVisible(false);
    mProblemsLabel = new QLabel(this);
    mProblemsLabel->setObjectName(QStringLiteral("problemsLabel"));
    mProblemsLabel->setWordWrap(true);
    mProblemsLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mProblemsLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mCheckingLabel = new QLabel(this);
    mCheckingLabel->setObjectName(QStringLiteral("checkingLabel"));
    mCheckingLabel->setWordWrap(true);
    mCheckingLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mCheckingLabel->setVisible(false);
    mCheckingTimer = new QTimer(this);
    mCheckingTimer->setSingleShot(true);
    mCheckingTimer->setInterval(kCheckingShownAfterMs);
    connect(mCheckingTimer, &QTimer::timeout, this, [this] { mCheckingLabel->setVisible(mChecking); });
    mWarningsLabel = new QLabel(this);
    mWarningsLabel->setObjectName(QStringLiteral("warningsLabel"));
    mWarningsLabel->setWordWrap(true);
    mWarningsLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mWarningsLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mWarningsLabel->setVisible(false);
    mMessageLabel = new QLabel(this);
    mMessageLabel->setObjectName(QStringLiteral("messageLabel"));
    mMessageLabel->setWordWrap(true);
    mMessageLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mMessageLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mMessageLabel->setVisible(false);
    mPreviewButton = new QPushButton(this);
    mPreviewButton->setObjectName(QStringLiteral("previewButton"));
    mPreviewButton->setIcon(mPreviewAction->icon());
    connect(mPreviewButton, &QPushButton::clicked, mPreviewAction, &QAction::trigger);
    auto* previewRow = new QHBoxLayout;
    previewRow->addStretch(1);
    previewRow->addWidget(mPreviewButton);

    return previewRow;
}

void ExerciseEditorPanel::connectEdits() {
    // Each edit is one undo step.
    connect(mTypeCombo, &QComboBox::activated, this, [this](int index) {
        if (index >= 0 && index < int(exerciseKinds().size())) changeType(exerciseKinds()[std::size_t(index)]->type());
    });
    connect(mTextLanguageCombo, &QComboBox::currentIndexChanged, this, [this] {
        const Guard guard(mShowing);
        showExerciseText(exercise());
    });
    connect(mNameEdit, &QLineEdit::textEdited, this, [this] { onFieldEdited(kName); });
    connect(mDescriptionEdit, &QPlainTextEdit::textChanged, this, [this] { onFieldEdited(kDescription); });
    const std::pair<QDoubleSpinBox*, Field> spins[] = {
        {mTimeLimitSpin, kTimeLimit},   {mDisplacementSpin, kDisplacementLimit}, {mExcessiveSpin, kExcessiveForce},
        {mNeedsErrorSpin, kNeedsError}, {mNeedsBudgetSpin, kNeedsBudget},        {mMeshScaleSpin, kMeshScale}};
    for (const auto& [spin, field] : spins) {
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, field = field] { onFieldEdited(field); });
        // Leaving the field ends its step: a later edit of it is a step of its own.
        connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { ++mMergeEpoch; });
    }
    connect(mNameEdit, &QLineEdit::editingFinished, this, [this] { ++mMergeEpoch; });
    connect(mNeedsCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (mShowing) return;
        Exercise e = exercise();
        if (on) e.needs = LodNeeds{mNeedsErrorSpin->value() / 100.0, mNeedsBudgetSpin->value()};
        else e.needs.reset();
        pushEdit(e, on ? tr("State targets") : tr("Remove targets"), -1);
    });
    for (const bool mesh : {true, false}) {
        QComboBox* combo = mesh ? mMeshCombo : mPresetCombo;
        connect(combo, &QComboBox::activated, this, [this, combo, mesh](int index) { commitPath(mesh, combo->itemText(index)); });
        connect(combo->lineEdit(), &QLineEdit::editingFinished, this, [this, combo, mesh] { commitPath(mesh, combo->currentText()); });
        connect(mesh ? mMeshBrowseButton : mPresetBrowseButton, &QPushButton::clicked, this, [this, mesh] { browsePath(mesh); });
    }
    connect(mMeshUnitCombo, &QComboBox::activated, this, &ExerciseEditorPanel::commitMeshUnit);
    connect(mShowMeshButton, &QPushButton::clicked, this, [this] {
        const QString path = resolved(exercise(), exercise().meshPath);
        if (path.isEmpty()) showMessage(tr("The mesh '%1' cannot be found.").arg(qs(exercise().meshPath)), true);
        else emit meshRequested(path);
    });
    connect(mLiveScoreCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (mShowing) return;
        Exercise e = exercise();
        e.showLiveScore = on;
        pushEdit(e, on ? tr("Show the live score") : tr("Hide the live score"));
    });
    connect(mRubricTable, &QTableWidget::cellChanged, this, &ExerciseEditorPanel::onRubricCellChanged);
    connect(mResetRubricButton, &QPushButton::clicked, this, &ExerciseEditorPanel::resetRubric);

    // A line edit keeps its own text undo under Ctrl+Z; the panel's history is the one the user
    // means, so the fields let the panel's shortcuts through.
    for (QWidget* w : findChildren<QWidget*>())
        if (qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QLineEdit*>(w) || qobject_cast<QPlainTextEdit*>(w))
            w->installEventFilter(this);
}

void ExerciseEditorPanel::buildTypePages() {
    for (const ExerciseKind* kind : exerciseKinds()) mTypePages->addWidget(buildKindPage(*kind));
}

QWidget* ExerciseEditorPanel::buildKindPage(const ExerciseKind& kind) {
    const ExerciseEditing& editing = kind.editing();
    const PlacedItems& items = editing.items;
    const QString name = QLatin1String(items.listKey);
    KindPage p;
    p.kind = &kind;
    p.page = new QWidget(mTypePages);
    p.page->setObjectName(qs(std::string(kind.key())) + QStringLiteral("Page"));
    auto* layout = new QVBoxLayout(p.page);
    layout->setContentsMargins(0, 0, 0, 0);

    // The items, edited in place: number, vertex, then the item's numbers.
    const int columns = kItemNumbers + int(items.numbers.size());
    p.table = new QTableWidget(0, columns, p.page);
    p.table->setObjectName(name);
    p.table->verticalHeader()->setVisible(false);
    p.table->verticalHeader()->setDefaultSectionSize(p.table->fontMetrics().height() + 8);
    p.table->setSelectionBehavior(QAbstractItemView::SelectRows);
    p.table->setSelectionMode(items.single ? QAbstractItemView::NoSelection : QAbstractItemView::SingleSelection);
    // Tab leaves the table: typing into the next cell would move a point by its vertex number.
    p.table->setTabKeyNavigation(false);
    p.table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);
    p.table->setItemDelegateForColumn(kItemVertex, new NumberDelegate(p.table, 0, 0x7fffffff, 0));
    for (std::size_t c = 0; c < items.numbers.size(); ++c) {
        const EditedNumber& n = items.numbers[c];
        p.table->setItemDelegateForColumn(kItemNumbers + int(c), new NumberDelegate(p.table, n.lo, n.hi, n.decimals));
    }
    p.table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    p.table->horizontalHeader()->setSectionResizeMode(kItemNumber, QHeaderView::ResizeToContents);
    p.table->horizontalHeader()->setMinimumSectionSize(24);
    for (QAction* action : {mRemoveAction, mMoveUpAction, mMoveDownAction}) p.table->addAction(action);
    layout->addWidget(p.table);

    // Tool buttons: push buttons' minimum widths would not fit five in a narrow dock.
    auto* row = new QHBoxLayout;
    row->setSpacing(4);
    auto button = [&](const char* suffix, bool checkable) {
        auto* b = new QToolButton(p.page);
        b->setObjectName(name + QLatin1String(suffix));
        b->setCheckable(checkable);
        return b;
    };
    p.add = button(".add", true);
    p.move = button(".move", true);
    p.remove = button(".remove", false);
    p.up = button(".up", false);
    p.up->setArrowType(Qt::UpArrow);
    p.down = button(".down", false);
    p.down->setArrowType(Qt::DownArrow);
    row->addWidget(p.add);
    row->addWidget(p.move);
    row->addWidget(p.remove);
    row->addStretch(1);
    row->addWidget(p.up);
    row->addWidget(p.down);
    layout->addLayout(row);
    // A single item is placed, not added, removed or reordered; an unordered list has no order to change.
    p.add->setVisible(!items.single);
    p.remove->setVisible(!items.single);
    p.up->setVisible(!items.single && items.ordered);
    p.down->setVisible(!items.single && items.ordered);
    connect(p.remove, &QToolButton::clicked, this, &ExerciseEditorPanel::removeSelected);
    connect(p.up, &QToolButton::clicked, this, [this] { moveSelected(-1); });
    connect(p.down, &QToolButton::clicked, this, [this] { moveSelected(+1); });
    connect(p.add, &QToolButton::clicked, this, [this](bool on) { setPlacing(on ? Placing::AddItem : Placing::None); });
    connect(p.move, &QToolButton::clicked, this,
            [this](bool on) { setPlacing(on ? Placing::MoveSelected : Placing::None); });
    connect(p.table, &QTableWidget::cellChanged, this, &ExerciseEditorPanel::onItemCellChanged);
    QTableWidget* table = p.table;
    connect(table, &QTableWidget::itemSelectionChanged, this, [this, table] {
        if (mShowing) return;
        const auto rows = table->selectionModel()->selectedRows();
        setSelectedIndex(rows.isEmpty() ? -1 : rows.front().row());
    });

    // The section's numbers.
    if (!editing.numbers.empty()) {
        auto* form = new QFormLayout;
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        for (std::size_t i = 0; i < editing.numbers.size(); ++i) {
            const EditedNumber& n = editing.numbers[i];
            QDoubleSpinBox* spin = doubleSpin(p.page, n.key, n.lo, n.hi, n.decimals, n.step);
            auto* label = new QLabel(p.page);
            form->addRow(label, spin);
            p.numbers.push_back(spin);
            p.numberLabels.push_back(label);
            const int field = kSectionNumber + int(i);
            connect(spin, &QDoubleSpinBox::valueChanged, this, [this, field] { onFieldEdited(field); });
            connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { ++mMergeEpoch; });
        }
        layout->addLayout(form);
    }
    mPages.push_back(p);
    return p.page;
}

ExerciseEditorPanel::KindPage& ExerciseEditorPanel::page() { return mPages[std::size_t(typeIndex(exercise().type))]; }

const ExerciseEditorPanel::KindPage& ExerciseEditorPanel::page() const {
    return mPages[std::size_t(typeIndex(exercise().type))];
}

int ExerciseEditorPanel::itemCount() const {
    return int(exerciseKind(exercise().type).editing().items.count(exercise()));
}

QAction* ExerciseEditorPanel::newAction(ExerciseType type) const { return mNewActions[std::size_t(typeIndex(type))]; }

QString ExerciseEditorPanel::typeText(ExerciseType type) const {
    return exerciseText(ViewText{exerciseKind(type).label()});
}

void ExerciseEditorPanel::retranslateUi() {
    for (const auto& [label, text] : mRowLabels) label->setText(tr(text));
    mUndoAction->setText(tr("Undo"));
    mRedoAction->setText(tr("Redo"));
    mCheckingLabel->setText(tr("Checking whether the mouse can do what the exercise asks…"));
    // What each type asks of the trainee: the New action's and the type combo's tooltips.
    const std::pair<ExerciseType, QString> newTips[] = {
        {ExerciseType::PressTargets, tr("press a sequence of surface targets, each with a force window and a hold.")},
        {ExerciseType::FindLump, tr("find a hidden stiff inclusion by palpation and mark it.")},
        {ExerciseType::Trace, tr("trace a path on the surface, keeping the force in a band.")},
        {ExerciseType::DetectLumps,
         tr("examine the whole surface for lumps under it (or none), mark each and finish.")}};
    for (const auto& [type, tip] : newTips) {
        const int i = typeIndex(type);
        mNewActions[std::size_t(i)]->setText(tr("New: %1").arg(typeText(type)));
        mNewActions[std::size_t(i)]->setToolTip(tr("A new exercise: %1").arg(tip));
        mTypeCombo->setItemText(i, typeText(type));
        mTypeCombo->setItemData(i, tip, Qt::ToolTipRole);
    }
    mNewButton->setText(tr("New"));
    mNewButton->setToolTip(tr("A new exercise of a type; asks before unsaved changes are lost."));
    mLiveScoreCheck->setText(tr("Show the score while it runs"));
    mLiveScoreCheck->setToolTip(
        tr("Whether the trainee sees the score so far (show_live_score). Off by default where it "
           "would give the answer away: in detecting lumps a mark on a lump would raise it."));
    mOpenAction->setText(tr("Open…"));
    mOpenAction->setToolTip(tr("Open an exercise file (Ctrl+O)."));
    mSaveAction->setText(tr("Save"));
    mSaveAction->setToolTip(tr("Save the exercise to its file (Ctrl+S); refused while it has problems."));
    mSaveAsAction->setText(tr("Save As…"));
    mExportBundleAction->setText(tr("Export Bundle…"));
    mExportBundleAction->setToolTip(
        tr("Write the exercise with its mesh, preset and scripted paths as one file, to "
           "open on a trainee's computer (Exercise > Open Exercise…)."));
    mSaveAsAction->setToolTip(tr("Save the exercise to a new file (Ctrl+Shift+S)."));
    mPreviewAction->setText(tr("Try it"));
    mPreviewAction->setToolTip(tr("Run this exercise now as a trainee would, without saving it (F5)."));
    mPreviewButton->setText(mPreviewAction->text());
    mPreviewButton->setToolTip(mPreviewAction->toolTip());
    mStopPlacingAction->setText(tr("Stop placing"));
    mRemoveAction->setText(tr("Remove"));
    mMoveUpAction->setText(tr("Move up"));
    mMoveDownAction->setText(tr("Move down"));

    mExerciseGroup->setTitle(tr("Exercise"));
    mTypeCombo->setToolTip(tr("What the trainee does. Each type keeps its own points: switching back restores them."));
    mTextLanguageCombo->setToolTip(
        tr("Which language's name and description you edit: the exercise's own, or a "
           "translation trainees who use Palpate in that language see (translations). "
           "An empty translation shows the exercise's own words."));
    for (int i = 0; i < mTextLanguageCombo->count(); ++i)
        mTextLanguageCombo->setItemText(i, textLanguageName(mTextLanguageCombo->itemData(i).toString()));
    mNameEdit->setToolTip(tr("The name trainees and score reports see (name)."));
    showTextPlaceholders(exercise());
    mDescriptionEdit->setToolTip(tr("What the trainee is asked to do, shown before the exercise starts (description)."));
    mSceneGroup->setTitle(tr("Tissue"));
    mMeshCombo->setToolTip(tr("The mesh file (mesh): a shipped mesh, a path relative to resources/ or to the exercise "
                              "file, or an absolute path. Points are vertices of this file."));
    mMeshBrowseButton->setText(tr("Browse…"));
    mMeshBrowseButton->setToolTip(tr("Choose a mesh file (OBJ, OFF, PLY, STL, OM)."));
    const QString unitTexts[kMeshUnitChoices] = {tr("millimetres (mm)"), tr("centimetres (cm)"), tr("metres (m)"),
                                                 tr("inches (in)"), tr("scale…")};
    for (int i = 0; i < kMeshUnitChoices; ++i) mMeshUnitCombo->setItemText(i, unitTexts[i]);
    mMeshUnitCombo->setToolTip(tr("The unit of the mesh file's coordinates (mesh_unit): a mesh from another tool may be "
                                  "in metres, inches or centimetres; it is scaled to mm wherever it is loaded."));
    mMeshScaleSpin->setSuffix(tr(" mm per file unit"));
    mMeshScaleSpin->setToolTip(tr("How many millimetres one unit of the mesh file is (mesh_unit as a number)."));
    mShowMeshButton->setText(tr("Show this mesh"));
    mShowMeshButton->setToolTip(tr("Draw the exercise's mesh in the viewport, so that points can be placed by clicking."));
    mPresetCombo->setToolTip(tr("The tissue preset file (tissue_preset): how the tissue feels."));
    mPresetBrowseButton->setText(tr("Browse…"));
    mPresetBrowseButton->setToolTip(tr("Choose a tissue preset file (JSON)."));
    mLimitsGroup->setTitle(tr("Limits"));
    mTimeLimitSpin->setSuffix(tr(" s"));
    mTimeLimitSpin->setToolTip(tr("Time the trainee has (time_limit_s); what happens after it is not scored."));
    mDisplacementSpin->setSuffix(tr(" mm"));
    mDisplacementSpin->setToolTip(tr("Tissue displaced further than this counts as damage (damage.displacement_limit_mm)."));
    mExcessiveSpin->setSuffix(tr(" N"));
    mExcessiveSpin->setToolTip(tr("A force above this is excessive (force.excessive_n); every target's lower force "
                                  "must stay below it."));

    for (KindPage& p : mPages) {
        const PlacedItems& items = p.kind->editing().items;
        const auto text = [](const char* english) { return exerciseText(ViewText{english}); };
        const auto withUnit = [&](const EditedNumber& n) {
            return *n.unit ? tr("%1 %2").arg(text(n.label), QLatin1String(n.unit)) : text(n.label);
        };
        QStringList headers{tr("#"), tr("Vertex")};
        QStringList tips{items.ordered ? tr("The order the trainee follows.") : tr("The item's number."),
                         tr("Its vertex, in the mesh file's numbering (vertex).")};
        for (const EditedNumber& n : items.numbers) {
            headers << withUnit(n);
            tips << text(n.tip);
        }
        p.table->setHorizontalHeaderLabels(headers);
        for (int c = 0; c < headers.size(); ++c)
            if (QTableWidgetItem* header = p.table->horizontalHeaderItem(c)) header->setToolTip(tips[c]);
        p.add->setText(tr("Add by clicking"));
        p.add->setToolTip(text(items.addTip));
        p.move->setText(items.single ? tr("Place by clicking") : tr("Move"));
        p.move->setToolTip(items.single ? text(items.addTip)
                                        : tr("The next click on the mesh moves the selected row's point there."));
        p.remove->setText(tr("Remove"));
        p.remove->setToolTip(tr("Remove the selected row (Delete)."));
        p.up->setToolTip(tr("Move the selected row earlier (Ctrl+Up)."));
        p.down->setToolTip(tr("Move the selected row later (Ctrl+Down)."));
        const auto& numbers = p.kind->editing().numbers;
        for (std::size_t i = 0; i < numbers.size(); ++i) {
            p.numberLabels[i]->setText(text(numbers[i].label));
            p.numbers[i]->setSuffix(*numbers[i].unit ? QLatin1Char(' ') + QLatin1String(numbers[i].unit) : QString());
            p.numbers[i]->setToolTip(text(numbers[i].tip));
        }
    }

    mRubricGroup->setTitle(tr("Rubric"));
    mRubricTable->setHorizontalHeaderLabels({tr("Metric"), tr("Unit"), tr("Weight"), tr("Full"), tr("Zero")});
    const QString rubricTips[] = {tr("What is measured (the rubric key; its tooltip says what it is)."), tr("The metric's unit."),
                                  tr("Relative weight (0: reported, not scored)."),
                                  tr("At or beyond this value the line scores full marks."),
                                  tr("At or beyond this value (away from full) the line scores zero.")};
    for (int c = 0; c < kRubricColumns; ++c)
        if (QTableWidgetItem* header = mRubricTable->horizontalHeaderItem(c)) header->setToolTip(rubricTips[c]);
    mRubricTable->setToolTip(tr("Grey lines are the defaults (docs/scoring.md), computed from the exercise's own "
                                "numbers; editing a line sets it in the exercise."));
    mResetRubricButton->setText(tr("Reset to defaults"));
    mResetRubricButton->setToolTip(tr("Remove every rubric line the exercise sets: all metrics use the defaults."));
    showExercise(exercise());
}

void ExerciseEditorPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

bool ExerciseEditorPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride) {
        const QKeySequence pressed(static_cast<QKeyEvent*>(event)->keyCombination());
        if (mUndoAction->shortcuts().contains(pressed) || mRedoAction->shortcuts().contains(pressed)) {
            event->ignore();  // not overridden: the shortcut (the panel's action) fires
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

QList<QAction*> ExerciseEditorPanel::editorActions() const {
    QList<QAction*> out(mNewActions.begin(), mNewActions.end());
    out << mOpenAction << mSaveAction << mSaveAsAction << mExportBundleAction << mUndoAction << mRedoAction
        << mPreviewAction;
    return out;
}

// ---- Files and resources ------------------------------------------------------------------------

void ExerciseEditorPanel::fillResourceCombos() {
    for (const bool mesh : {true, false}) {
        QComboBox* combo = mesh ? mMeshCombo : mPresetCombo;
        const Guard guard(mShowing);
        combo->clear();
        if (mResourceRoot.isEmpty()) continue;
        const QString folder = mesh ? QStringLiteral("meshes") : QStringLiteral("presets/tissues");
        const QStringList filters = mesh ? QStringList{QStringLiteral("*.off"), QStringLiteral("*.obj"), QStringLiteral("*.ply"),
                                                       QStringLiteral("*.stl"), QStringLiteral("*.om")}
                                         : QStringList{QStringLiteral("*.json")};
        const QDir dir(mResourceRoot + QLatin1Char('/') + folder);
        for (const QFileInfo& file : dir.entryInfoList(filters, QDir::Files, QDir::Name)) {
            combo->addItem(folder + QLatin1Char('/') + file.fileName());
            combo->setItemData(combo->count() - 1, file.absoluteFilePath(), Qt::ToolTipRole);
        }
    }
}

QString ExerciseEditorPanel::resolved(const Exercise& exercise, const std::string& path) const {
    return qs(resolveExercisePath(exercise, path, mFindResource));
}

QString ExerciseEditorPanel::storablePath(const Exercise& exercise, const QString& absolutePath) const {
    const QString canonical = QFileInfo(absolutePath).canonicalFilePath();
    if (canonical.isEmpty()) return absolutePath;
    auto resolvesHere = [&](const QString& candidate) {
        return QFileInfo(resolved(exercise, ss(candidate))).canonicalFilePath() == canonical;
    };
    // Relative to resources/, as the shipped exercises are: the shortest tail of the path that
    // the finder maps to this very file.
    const QStringList parts = QDir::fromNativeSeparators(canonical).split(QLatin1Char('/'), Qt::SkipEmptyParts);
    if (mFindResource)
        for (int n = 1; n <= std::min<int>(6, int(parts.size()) - 1); ++n) {
            const QString tail = parts.mid(parts.size() - n).join(QLatin1Char('/'));
            if (QFileInfo(qs(mFindResource(ss(tail)))).canonicalFilePath() == canonical && resolvesHere(tail)) return tail;
        }
    // Beside the exercise file (or below it): relative, so the folder can move as a whole.
    if (!exercise.sourcePath.empty()) {
        const QString relative = QFileInfo(qs(exercise.sourcePath)).absoluteDir().relativeFilePath(canonical);
        if (!relative.startsWith(QLatin1String("..")) && resolvesHere(relative)) return relative;
    }
    return canonical;
}

void ExerciseEditorPanel::setDrawnMesh(std::shared_ptr<const TissueMesh> mesh, const QString& path) {
    mDocument->setDrawnMesh(std::move(mesh), ss(path));
    if (!drawnMeshMatches() && mPlacing != Placing::None) updatePlacingUi();
    refresh();
}

bool ExerciseEditorPanel::drawnMeshMatches() const { return mDocument->drawnMeshMatches(); }

const Exercise& ExerciseEditorPanel::exercise() const { return mDocument->exercise(); }

void ExerciseEditorPanel::newExercise(ExerciseType type) {
    Exercise e;
    e.type = type;
    e.name = ss(tr("New exercise: %1").arg(typeText(type).toLower()));
    // The drawn mesh (the instructor places points on what they see), else the default stomach.
    const std::shared_ptr<const TissueMesh>& drawnMesh = mDocument->drawnMesh();
    if (drawnMesh && !mDocument->drawnMeshPath().empty())
        e.meshPath = ss(storablePath(e, qs(mDocument->drawnMeshPath())));
    else if (!resolved(e, kDefaultMesh).isEmpty()) e.meshPath = kDefaultMesh;
    else if (mMeshCombo->count() > 0) e.meshPath = ss(mMeshCombo->itemText(0));
    for (const char* preset : kDefaultPresets)
        if (!resolved(e, preset).isEmpty()) {
            e.tissuePresetPath = preset;
            break;
        }
    if (e.tissuePresetPath.empty() && mPresetCombo->count() > 0) e.tissuePresetPath = ss(mPresetCombo->itemText(0));
    // The lump starts on the mesh's +x side (where the shipped example hides it), so that it is
    // visible at once; the instructor moves it.
    if (drawnMesh && drawnMesh->vertexCount() > 0) {
        const auto& rest = drawnMesh->restPositionsMm();
        const auto it = std::max_element(rest.begin(), rest.end(), [](const glm::vec3& a, const glm::vec3& b) { return a.x < b.x; });
        const VertexId v = VertexId(it - rest.begin());
        e.findLump.inclusion.centre.vertex = drawnMesh->originalIndex().empty() ? v : drawnMesh->originalIndex()[v];
    } else {
        e.findLump.inclusion.centre.vertex = 0;
    }
    setPlacing(Placing::None);
    mPath.clear();
    mSelected = -1;
    mUndoStack->clear();
    showExercise(e);
    // An examination starts with the force the mouse's default press gives (before the wheel
    // turns): a sweep examines from the start. The file's default may be out of reach on a soft
    // tissue.
    if (exerciseKind(type).palpation())
        if (const auto reach = mDocument->examineReach(); reach && reach->defaultPressN >= 1e-3) {
            e = exercise();
            e.coverage.minForceN = reach->defaultPressN;
            showExercise(e);
        }
    mUndoStack->setClean();
    showMessage(QString(), false);
    updateTitle();
}

QString ExerciseEditorPanel::openExercise(const QString& path) {
    const ExerciseLoadResult result = guardedLoad(ss(path), [&] { return loadExercise(ss(path)); });
    if (!result.exercise) {
        QStringList errors;
        for (const std::string& error : result.errors) errors << qs(error);
        const QString text = errors.join(QLatin1Char('\n'));
        showMessage(tr("Not opened:") + QLatin1Char('\n') + text, true);
        return text;
    }
    setPlacing(Placing::None);
    mPath = QFileInfo(path).absoluteFilePath();
    mLastDirectory = QFileInfo(path).absolutePath();
    mSelected = -1;
    mUndoStack->clear();
    showExercise(*result.exercise);
    mUndoStack->setClean();
    showMessage(tr("Opened %1.").arg(QDir::toNativeSeparators(mPath)), false);
    updateTitle();
    return {};
}

QString ExerciseEditorPanel::saveExercise(const QString& path) {
    if (path.isEmpty()) return tr("No file to save to.");
    if (!mBlocking.isEmpty()) {
        const QString text = tr("Not saved: the exercise has problems:") + QStringLiteral("\n") + mBlocking.join(QLatin1Char('\n'));
        showMessage(text, true);
        return text;
    }
    // The paths as they will be read from the new file: relative to resources/ when there.
    Exercise out = exercise();
    out.sourcePath = ss(QFileInfo(path).absoluteFilePath());
    const QString meshFile = resolved(exercise(), exercise().meshPath);
    const QString presetFile = resolved(exercise(), exercise().tissuePresetPath);
    out.meshPath = ss(storablePath(out, meshFile));
    out.tissuePresetPath = ss(storablePath(out, presetFile));
    // A file neither under resources/ nor in the exercise's folder would be named by its absolute
    // path, which another computer does not have: it is copied into the folder, so that the
    // folder travels as a whole.
    QStringList copied;
    for (std::string* stored : {&out.meshPath, &out.tissuePresetPath}) {
        if (stored->empty() || !QFileInfo(qs(*stored)).isAbsolute()) continue;
        std::string error;
        const auto name = copyIntoFolder(*stored, ss(QFileInfo(path).absolutePath()), error);
        if (!name) {
            showMessage(tr("Not saved:") + QLatin1Char('\n') + qs(error), true);
            return qs(error);
        }
        *stored = *name;
        copied << qs(*name);
    }
    const std::string error = palpate::saveExercise(out, ss(path));
    if (!error.empty()) {
        showMessage(tr("Not saved:") + QLatin1Char('\n') + qs(error), true);
        return qs(error);
    }
    mPath = QFileInfo(path).absoluteFilePath();
    mLastDirectory = QFileInfo(path).absolutePath();
    ++mMergeEpoch;  // an edit after the save never merges into the saved step
    // Not an undo step: the same exercise, written from its new place. Earlier steps keep their
    // own sourcePath, so their relative paths still resolve after undo.
    {
        const Guard guard(mShowing);
        showExercise(out);
    }
    mUndoStack->setClean();
    QString saved = tr("Saved %1.").arg(QDir::toNativeSeparators(mPath));
    if (!copied.isEmpty())
        saved += QLatin1Char(' ') + tr("Copied %1 beside it, so that the exercise opens on other computers.")
                                        .arg(copied.join(QStringLiteral(", ")));
    showMessage(saved, false);
    updateTitle();
    return {};
}

QString ExerciseEditorPanel::save() {
    if (mPath.isEmpty()) return saveAsDialog() ? QString() : tr("Not saved.");
    return saveExercise(mPath);
}

bool ExerciseEditorPanel::saveAsDialog() {
    QString suggested = mPath;
    if (suggested.isEmpty()) {
        QString base = qs(exercise().name).toLower();
        base.replace(QRegularExpression(QStringLiteral("[^a-z0-9]+")), QStringLiteral("_"));
        base.remove(QRegularExpression(QStringLiteral("^_+|_+$")));
        suggested = (mLastDirectory.isEmpty() ? QDir::homePath() : mLastDirectory) + QLatin1Char('/') +
                    (base.isEmpty() ? QStringLiteral("exercise") : base) + QStringLiteral(".json");
    }
    QString path = QFileDialog::getSaveFileName(this, tr("Save exercise"), suggested, tr("Exercises (*.json)"));
    path = withSuffixConfirmed(this, path, QStringLiteral(".json"));
    if (path.isEmpty()) return false;
    return saveExercise(path).isEmpty();
}

QString ExerciseEditorPanel::exportBundle(const QString& bundlePath) {
    if (mPath.isEmpty() || isModified())
        if (const QString error = save(); !error.isEmpty()) return error;
    const std::string error = writeExerciseBundle(ss(mPath), ss(bundlePath), mFindResource);
    if (!error.empty()) {
        showMessage(tr("Bundle not written:") + QLatin1Char('\n') + qs(error), true);
        return qs(error);
    }
    showMessage(tr("Bundle written: %1, with the exercise's mesh, preset and scripted paths.")
                    .arg(QDir::toNativeSeparators(bundlePath)),
                false);
    return {};
}

void ExerciseEditorPanel::exportBundleDialog() {
    if (mPath.isEmpty() || isModified())
        if (!save().isEmpty()) return;
    const QString suggested = QFileInfo(mPath).absoluteDir().filePath(QFileInfo(mPath).completeBaseName() +
                                                                      QStringLiteral(".palpex"));
    QString path = QFileDialog::getSaveFileName(this, tr("Export exercise bundle"), suggested,
                                                tr("Exercise bundles (*.palpex)"));
    path = withSuffixConfirmed(this, path, QStringLiteral(".palpex"));
    if (!path.isEmpty()) exportBundle(path);
}

void ExerciseEditorPanel::openDialog() {
    if (!confirmDiscard()) return;
    QString dir = mLastDirectory;
    if (dir.isEmpty() && mFindResource) {
        const QString example = qs(mFindResource("exercises/press_targets.json"));
        dir = example.isEmpty() ? QDir::homePath() : QFileInfo(example).absolutePath();
    }
    const QString path = QFileDialog::getOpenFileName(this, tr("Open exercise"), dir, tr("Exercises (*.json);;All files (*)"));
    if (!path.isEmpty()) openExercise(path);
}

void ExerciseEditorPanel::browsePath(bool mesh) {
    QString start = resolved(exercise(), mesh ? exercise().meshPath : exercise().tissuePresetPath);
    if (start.isEmpty()) start = mResourceRoot;
    const QString path = mesh ? QFileDialog::getOpenFileName(this, tr("Choose a mesh"), start,
                                                             tr("Meshes (*.off *.obj *.ply *.stl *.om);;All files (*)"))
                              : QFileDialog::getOpenFileName(this, tr("Choose a tissue preset"), start,
                                                             tr("Tissue presets (*.json);;All files (*)"));
    if (!path.isEmpty()) commitPath(mesh, storablePath(exercise(), path));
}

void ExerciseEditorPanel::setDiscardQuestion(DiscardQuestion question) { mDiscardQuestion = std::move(question); }

bool ExerciseEditorPanel::confirmDiscard() {
    if (!isModified()) return true;
    switch (mDiscardQuestion ? mDiscardQuestion(qs(exercise().name)) : DiscardAnswer::Cancel) {
        case DiscardAnswer::Discard: return true;
        case DiscardAnswer::Save: return save().isEmpty();
        case DiscardAnswer::Cancel: return false;
    }
    return false;
}

bool ExerciseEditorPanel::isModified() const { return !mUndoStack->isClean(); }

namespace {

/// Sets the name or description of `language` ("" the exercise's own). A translation left with
/// neither is removed: a file never holds an empty one.
void setExerciseText(Exercise& e, const std::string& language, std::string ExerciseTextDef::*field, std::string text) {
    if (language.empty()) {
        ExerciseTextDef own{e.name, e.description};
        own.*field = std::move(text);
        e.name = own.name;
        e.description = own.description;
        return;
    }
    ExerciseTextDef& translation = e.translations[language];
    translation.*field = std::move(text);
    if (translation.name.empty() && translation.description.empty()) e.translations.erase(language);
}

}  // namespace

// ---- Showing and editing ---------------------------------------------------------------------------

QString ExerciseEditorPanel::textLanguage() const {
    return mTextLanguageCombo ? mTextLanguageCombo->currentData().toString() : QString();
}

QString ExerciseEditorPanel::textLanguageName(const QString& code) {
    if (code.isEmpty()) return tr("Its own words");
    const QString language = QLocale(code).nativeLanguageName();
    return language.isEmpty() ? code : tr("%1 (%2)").arg(language, code);
}

void ExerciseEditorPanel::showExerciseText(const Exercise& e) {
    // A file may carry languages this build does not offer: they are edited like the others.
    for (const auto& [code, words] : e.translations)
        if (mTextLanguageCombo->findData(qs(code)) < 0)
            mTextLanguageCombo->addItem(textLanguageName(qs(code)), qs(code));
    const std::string code = textLanguage().toStdString();
    ExerciseTextDef text{e.name, e.description};
    if (!code.empty()) {
        const auto found = e.translations.find(code);
        text = found == e.translations.end() ? ExerciseTextDef{} : found->second;
    }
    if (mNameEdit->text() != qs(text.name)) mNameEdit->setText(qs(text.name));
    if (mDescriptionEdit->toPlainText() != qs(text.description)) mDescriptionEdit->setPlainText(qs(text.description));
    showTextPlaceholders(e);
}

void ExerciseEditorPanel::showTextPlaceholders(const Exercise& e) {
    // A translation's empty field shows the words the trainee then reads: the exercise's own.
    const bool own = textLanguage().isEmpty();
    mNameEdit->setPlaceholderText(own ? tr("Required") : qs(e.name));
    mDescriptionEdit->setPlaceholderText(own ? QString() : qs(e.description));
}

void ExerciseEditorPanel::showExercise(const Exercise& exercise) {
    {
        const Guard guard(mShowing);
        mDocument->setExercise(exercise);
        const Exercise& e = mDocument->exercise();
        mTypeCombo->setCurrentIndex(typeIndex(e.type));
        mTypePages->setCurrentIndex(typeIndex(e.type));
        mTypeGroup->setTitle(typeText(e.type));
        showExerciseText(e);
        if (mMeshCombo->currentText() != qs(e.meshPath)) mMeshCombo->setEditText(qs(e.meshPath));
        if (mPresetCombo->currentText() != qs(e.tissuePresetPath)) mPresetCombo->setEditText(qs(e.tissuePresetPath));
        const int unitIndex = meshUnitChoice(e.meshUnit);
        mMeshUnitCombo->setCurrentIndex(unitIndex);
        setSpin(mMeshScaleSpin, e.meshUnit.mmPerUnit);
        mMeshScaleSpin->setVisible(unitIndex == kScaleChoice);
        setSpin(mTimeLimitSpin, e.timeLimitS);
        setSpin(mDisplacementSpin, e.displacementLimitMm);
        setSpin(mExcessiveSpin, e.excessiveForceN);
        const LodNeeds shownNeeds = e.needs.value_or(LodNeeds{});
        mNeedsCheck->setChecked(e.needs.has_value());
        setSpin(mNeedsErrorSpin, 100.0 * shownNeeds.maxErrorFraction);
        setSpin(mNeedsBudgetSpin, shownNeeds.budgetUs);
        mNeedsErrorSpin->setEnabled(e.needs.has_value());
        mNeedsBudgetSpin->setEnabled(e.needs.has_value());

        mLiveScoreCheck->setChecked(showsLiveScore(e));
        showItems(e);

        // The rubric: the metrics of the type; defaults in grey until the exercise sets a line.
        std::vector<Metric> metrics;
        for (std::size_t i = 0; i < kMetricCount; ++i)
            if (exerciseKind(e.type).measures(Metric(i))) metrics.push_back(Metric(i));
        mRubricTable->setRowCount(int(metrics.size()));
        double totalWeight = 0.0;
        for (int r = 0; r < int(metrics.size()); ++r) {
            const Metric m = metrics[std::size_t(r)];
            const auto& line = e.rubric[std::size_t(m)];
            const RubricItem item = line ? *line : defaultRubricItem(e, m);
            totalWeight += item.weight;
            setCellValue(mRubricTable, r, kRubricMetric, qs(std::string(metricName(m))), false);
            QTableWidgetItem* nameItem = mRubricTable->item(r, kRubricMetric);
            nameItem->setData(Qt::UserRole, int(m));
            nameItem->setToolTip(qs(std::string(metricDescription(m))));
            setCellValue(mRubricTable, r, kRubricUnit, qs(std::string(metricUnit(m))), false);
            setCellValue(mRubricTable, r, kRubricWeight, item.weight, true);
            setCellValue(mRubricTable, r, kRubricFull, item.fullMarks, true);
            setCellValue(mRubricTable, r, kRubricZero, item.zeroMarks, true);
            for (int c = 0; c < kRubricColumns; ++c) {
                QTableWidgetItem* it = mRubricTable->item(r, c);
                QFont font = it->font();
                if (font.italic() != !line) {
                    font.setItalic(!line);
                    it->setFont(font);
                }
                const QVariant colour = line ? QVariant() : QVariant(QBrush(kDefaultRubricText));
                if (it->data(Qt::ForegroundRole) != colour) it->setData(Qt::ForegroundRole, colour);
            }
        }
        fitTableHeight(mRubricTable, int(metrics.size()), 20);
        mRubricTotalLabel->setText(tr("Weights total %1; the score is 100 × Σ wᵢsᵢ / Σ wᵢ.").arg(locale().toString(totalWeight, 'g', 6)));

        // The selection follows the document (an undone add removes the selected row).
        if (mSelected >= itemCount() || exerciseKind(e.type).editing().items.single) mSelected = -1;
        if (mSelected >= 0) page().table->selectRow(mSelected);
        else page().table->clearSelection();
    }
    // An undone type change or removal may leave a mode that no longer fits (adding path points
    // to a press-targets exercise, moving a point that is gone): it ends.
    setPlacing(mPlacing);
    refresh();
}

void ExerciseEditorPanel::showItems(const Exercise& e) {
    const ExerciseEditing& editing = exerciseKind(e.type).editing();
    const PlacedItems& items = editing.items;
    KindPage& p = page();
    const int count = int(items.count(e));
    p.table->setRowCount(count);
    for (int r = 0; r < count; ++r) {
        const std::size_t i = std::size_t(r);
        QString number = QString::number(r + 1);
        // A path says where it starts and ends.
        if (items.ordered && count > 1 && items.numbers.empty())
            number += r == 0 ? tr(" (start)") : r + 1 == count ? tr(" (end)") : QString();
        setCellValue(p.table, r, kItemNumber, number, false);
        const SurfacePoint& at = items.point(e, i);
        if (at.vertex) setCellValue(p.table, r, kItemVertex, int(*at.vertex), true);
        else
            setCellValue(p.table, r, kItemVertex,
                         tr("(%1, %2, %3) mm").arg(at.pointMm.x).arg(at.pointMm.y).arg(at.pointMm.z), false);
        for (std::size_t c = 0; c < items.numbers.size(); ++c)
            setCellValue(p.table, r, kItemNumbers + int(c), items.numbers[c].get(e, i), true);
    }
    fitTableHeight(p.table, count, 8);
    for (std::size_t i = 0; i < editing.numbers.size(); ++i) setSpin(p.numbers[i], editing.numbers[i].get(e, 0));
}

void ExerciseEditorPanel::pushEdit(const Exercise& after, const QString& text, int field) {
    if (sameExercise(after, exercise())) return;
    showMessage(QString(), false);
    // Typing "1.5" or holding an arrow is one step, until the field loses focus.
    const int mergeKey = field < 0 ? ExerciseEditCommand::kNoMerge : field + kMergeFields * (mMergeEpoch % 64);
    mUndoStack->push(new ExerciseEditCommand(exercise(), after, text, mergeKey,
                                             [this](const Exercise& exercise) { showExercise(exercise); }));
}

void ExerciseEditorPanel::onFieldEdited(int field) {
    if (mShowing) return;
    Exercise e = exercise();
    QString what;
    switch (Field(field)) {
        case kName:
            setExerciseText(e, textLanguage().toStdString(), &ExerciseTextDef::name, ss(mNameEdit->text()));
            what = tr("name");
            break;
        case kDescription:
            setExerciseText(e, textLanguage().toStdString(), &ExerciseTextDef::description,
                            ss(mDescriptionEdit->toPlainText()));
            what = tr("description");
            break;
        case kTimeLimit: e.timeLimitS = mTimeLimitSpin->value(); what = tr("time limit"); break;
        case kDisplacementLimit: e.displacementLimitMm = mDisplacementSpin->value(); what = tr("damage limit"); break;
        case kExcessiveForce:
            e.excessiveForceN = mExcessiveSpin->value();
            what = tr("excessive force");
            break;
        case kNeedsError:
            if (!e.needs) return;
            e.needs->maxErrorFraction = mNeedsErrorSpin->value() / 100.0;
            what = tr("max error");
            break;
        case kNeedsBudget:
            if (!e.needs) return;
            e.needs->budgetUs = mNeedsBudgetSpin->value();
            what = tr("tick budget");
            break;
        case kMeshScale:
            e.meshUnit = MeshUnit{"", mMeshScaleSpin->value()};
            what = tr("mesh unit");
            break;
        case kSectionNumber:
        case kMergeFields: break;
    }
    if (field >= kSectionNumber) {
        // The kind's section number: its label names it.
        const auto& numbers = exerciseKind(e.type).editing().numbers;
        const std::size_t i = std::size_t(field - kSectionNumber);
        if (i >= numbers.size()) return;
        numbers[i].set(e, 0, page().numbers[i]->value());
        what = exerciseText(ViewText{numbers[i].label}).remove(QLatin1Char(':'));
    }
    pushEdit(e, tr("Change %1").arg(what), field);
}

void ExerciseEditorPanel::commitMeshUnit(int index) {
    if (mShowing || index < 0 || index >= kMeshUnitChoices) return;
    Exercise e = exercise();
    // "scale…" starts from the factor the exercise has (10 for cm), for the user to change.
    e.meshUnit = index == kScaleChoice ? MeshUnit{"", exercise().meshUnit.mmPerUnit} : namedMeshUnit(index);
    mMeshScaleSpin->setVisible(index == kScaleChoice);
    pushEdit(e, tr("Change %1").arg(tr("mesh unit")), -1);
}

void ExerciseEditorPanel::onItemCellChanged(int row, int column) {
    if (mShowing || row < 0 || row >= itemCount()) return;
    const PlacedItems& items = exerciseKind(exercise().type).editing().items;
    QTableWidget* table = page().table;
    Exercise e = exercise();
    const QVariant value = table->item(row, column)->data(Qt::EditRole);
    bool ok = false;
    const double v = value.toDouble(&ok);
    if (!ok) {
        showExercise(exercise());  // not a number: show what the exercise holds
        return;
    }
    if (column == kItemVertex) {
        if (v < 0) return showExercise(exercise());
        items.setPoint(e, std::size_t(row), SurfacePoint{std::uint32_t(v), glm::vec3(0.0f)});
    } else if (column >= kItemNumbers && column < kItemNumbers + int(items.numbers.size())) {
        items.numbers[std::size_t(column - kItemNumbers)].set(e, std::size_t(row), v);
    } else {
        return;
    }
    const QString header = table->horizontalHeaderItem(column) ? table->horizontalHeaderItem(column)->text()
                                                               : QString();
    pushEdit(e, tr("Change %1's %2").arg(exerciseText(ViewText{items.itemName}.whole(row + 1)), header));
}

void ExerciseEditorPanel::onRubricCellChanged(int row, int column) {
    if (mShowing || column < kRubricWeight) return;
    QTableWidgetItem* nameItem = mRubricTable->item(row, kRubricMetric);
    if (!nameItem) return;
    const Metric m = Metric(nameItem->data(Qt::UserRole).toInt());
    bool ok = false;
    const double v = mRubricTable->item(row, column)->data(Qt::EditRole).toDouble(&ok);
    if (!ok) return showExercise(exercise());
    Exercise e = exercise();
    // An edited line is set in the exercise whole: its other values are the defaults it showed.
    RubricItem line = e.rubric[std::size_t(m)] ? *e.rubric[std::size_t(m)] : defaultRubricItem(e, m);
    if (column == kRubricWeight) line.weight = v;
    else if (column == kRubricFull) line.fullMarks = v;
    else line.zeroMarks = v;
    e.rubric[std::size_t(m)] = line;
    pushEdit(e, tr("Change the rubric's %1").arg(qs(std::string(metricName(m)))));
}

void ExerciseEditorPanel::resetRubric() {
    Exercise e = exercise();
    e.rubric = {};
    pushEdit(e, tr("Reset the rubric"));
}

void ExerciseEditorPanel::commitPath(bool mesh, const QString& text) {
    if (mShowing) return;
    Exercise e = exercise();
    (mesh ? e.meshPath : e.tissuePresetPath) = ss(text.trimmed());
    pushEdit(e, mesh ? tr("Change the mesh") : tr("Change the tissue preset"));
}

void ExerciseEditorPanel::changeType(ExerciseType type) {
    if (type == exercise().type) return;
    setPlacing(Placing::None);
    Exercise e = exercise();
    e.type = type;
    // Rubric lines of metrics the new type does not measure would make the file invalid.
    for (std::size_t i = 0; i < kMetricCount; ++i)
        if (!exerciseKind(type).measures(Metric(i))) e.rubric[i].reset();
    mSelected = -1;
    pushEdit(e, tr("Change the type to %1").arg(typeText(type).toLower()));
}

void ExerciseEditorPanel::setSelectedIndex(int index) {
    const bool single = exerciseKind(exercise().type).editing().items.single;
    index = !single && index >= 0 && index < itemCount() ? index : -1;
    if (index == mSelected) return;
    mSelected = index;
    {
        const Guard guard(mShowing);
        if (index < 0) page().table->clearSelection();
        else page().table->selectRow(index);
    }
    if (mPlacing == Placing::MoveSelected && index < 0 && !single) setPlacing(Placing::None);
    refresh();
}

void ExerciseEditorPanel::removeSelected() {
    const PlacedItems& items = exerciseKind(exercise().type).editing().items;
    const int i = mSelected;
    if (items.single || i < 0 || i >= itemCount()) return;
    Exercise e = exercise();
    items.erase(e, std::size_t(i));
    mSelected = std::min(i, int(items.count(e)) - 1);
    pushEdit(e, tr("Remove %1").arg(exerciseText(ViewText{items.itemName}.whole(i + 1))));
}

void ExerciseEditorPanel::moveSelected(int delta) {
    const PlacedItems& items = exerciseKind(exercise().type).editing().items;
    const int i = mSelected, j = mSelected + delta;
    if (items.single || !items.ordered || i < 0 || j < 0 || j >= itemCount()) return;
    Exercise e = exercise();
    items.swap(e, std::size_t(i), std::size_t(j));
    mSelected = j;
    const QString item = exerciseText(ViewText{items.itemName}.whole(i + 1));
    pushEdit(e, delta < 0 ? tr("Move %1 up").arg(item) : tr("Move %1 down").arg(item));
}

// ---- Placing by clicking ----------------------------------------------------------------------------

void ExerciseEditorPanel::setPlacing(Placing placing) {
    // Add only where items are added; Move only with an item selected (a single item: always).
    const PlacedItems& items = exerciseKind(exercise().type).editing().items;
    const bool fits = placing == Placing::None || (placing == Placing::AddItem && !items.single) ||
                      (placing == Placing::MoveSelected && (items.single || mSelected >= 0));
    if (!fits) placing = Placing::None;
    const bool wasOn = mPlacing != Placing::None;
    mPlacing = placing;
    updatePlacingUi();
    if (wasOn != (placing != Placing::None)) emit placingChanged(placing != Placing::None);
}

void ExerciseEditorPanel::updatePlacingUi() {
    const Guard guard(mShowing);
    for (KindPage& p : mPages) {
        const bool current = p.kind->type() == exercise().type;
        p.add->setChecked(current && mPlacing == Placing::AddItem);
        p.move->setChecked(current && mPlacing == Placing::MoveSelected);
    }
    mStopPlacingAction->setEnabled(mPlacing != Placing::None);
    const PlacedItems& items = exerciseKind(exercise().type).editing().items;
    QString hint;
    switch (mPlacing) {
        case Placing::None: break;
        case Placing::AddItem:
            hint = tr("Click the tissue to place %1, and more after it; Esc to stop.")
                       .arg(exerciseText(ViewText{items.itemName}.whole(itemCount() + 1)));
            break;
        case Placing::MoveSelected: hint = tr("Click the mesh where the point goes; Esc cancels."); break;
    }
    if (!hint.isEmpty() && !drawnMeshMatches())
        hint = tr("The viewport does not show this exercise's mesh: press Show this mesh first.");
    mPlacingLabel->setText(hint);
    mPlacingLabel->setVisible(!hint.isEmpty());
}

std::optional<std::uint32_t> ExerciseEditorPanel::fileVertex(VertexId engineVertex) {
    if (!drawnMeshMatches()) {
        showMessage(tr("That click was on another mesh than the exercise's: press Show this mesh first."), true);
        return std::nullopt;
    }
    const TissueMesh& drawn = *mDocument->drawnMesh();
    if (engineVertex >= drawn.vertexCount()) {
        showMessage(tr("Vertex %1 is not on the drawn mesh.").arg(engineVertex), true);
        return std::nullopt;
    }
    // The viewport picks in the engine's order; the file stores the mesh file's own numbering.
    const auto& original = drawn.originalIndex();
    return original.empty() ? engineVertex : original[engineVertex];
}

void ExerciseEditorPanel::vertexPicked(VertexId engineVertex) {
    if (mPlacing == Placing::None) return;
    const auto vertex = fileVertex(engineVertex);
    if (!vertex) return;
    const SurfacePoint at{*vertex, glm::vec3(0.0f)};
    const PlacedItems& items = exerciseKind(exercise().type).editing().items;
    Exercise e = exercise();
    if (mPlacing == Placing::AddItem) {
        // The new item takes the last one's numbers (items of one exercise are usually alike); the
        // first gets a force window its tissue reaches at a third to two thirds of the deepest
        // touch (docs/scoring.md, "Reachable targets").
        const bool first = items.count(e) == 0;
        items.append(e, at);
        if (first && items.takeReachableWindow)
            if (const auto presses = mDocument->pressesOnDrawnMesh(engineVertex))
                if (const auto window = comfortableWindow(presses->forcesN, touchReach()))
                    items.takeReachableWindow(e, window->minN, window->maxN);
        mSelected = int(items.count(e)) - 1;
        pushEdit(e, tr("Add %1").arg(exerciseText(ViewText{items.itemName}.whole(mSelected + 1))));
        return;
    }
    // Move: the selected item, or the single one.
    const int i = items.single ? 0 : mSelected;
    if (i < 0 || i >= itemCount()) return;
    items.setPoint(e, std::size_t(i), at);
    setPlacing(Placing::None);
    pushEdit(e, tr("Move %1").arg(exerciseText(ViewText{items.itemName}.whole(i + 1))));
}

// ---- Problems, markers, preview ------------------------------------------------------------------

QStringList ExerciseEditorPanel::blockingProblems() const { return mBlocking; }

void ExerciseEditorPanel::refresh() {
    const Exercise& e = exercise();
    const ExerciseProblems found = mDocument->examine();
    QStringList blocking;
    for (const std::string& problem : found.invalid) blocking << qs(problem);
    if (found.meshNotFound)
        blocking << tr("mesh: '%1' is not found beside the exercise file or under resources/").arg(qs(e.meshPath));
    if (found.presetNotFound)
        blocking << tr("tissue_preset: '%1' is not found beside the exercise file or under resources/")
                        .arg(qs(e.tissuePresetPath));
    if (!found.meshError.empty()) blocking << tr("mesh: %1").arg(qs(found.meshError));
    if (!found.placementError.empty()) blocking << qs(found.placementError);
    mBlocking = blocking;
    mProblems = blocking;
    const QString meshFile = qs(mDocument->meshFile());
    if (!meshFile.isEmpty() && !drawnMeshMatches()) {
        const std::shared_ptr<const TissueMesh>& drawnMesh = mDocument->drawnMesh();
        const QString drawnPath = qs(mDocument->drawnMeshPath());
        const QString drawn = drawnMesh ? QFileInfo(drawnPath).fileName() : tr("no mesh");
        const bool otherUnit = drawnMesh &&
                               QFileInfo(drawnPath).canonicalFilePath() == QFileInfo(meshFile).canonicalFilePath();
        if (otherUnit)
            mProblems << tr("mesh_unit: the viewport shows %1 read in %2, this exercise reads it in %3: press Show "
                            "this mesh to place points by clicking")
                             .arg(drawn, qs(drawnMesh->report().unit.description()),
                                  qs(exercise().meshUnit.description()));
        else
            mProblems << tr("mesh: the viewport shows %1, not this exercise's %2: press Show this mesh to place points "
                            "by clicking")
                             .arg(drawn, QFileInfo(meshFile).fileName());
    }
    const std::shared_ptr<const ExerciseGeometry>& geometry = mDocument->geometry();
    checkReach();

    // The markers, on the drawn mesh only (picks and markers are in its numbering).
    ExerciseMarkers markers;
    const PlacedItems& items = exerciseKind(e.type).editing().items;
    if (drawnMeshMatches()) {
        const TissueMesh& drawn = *mDocument->drawnMesh();
        if (geometry) {
            markers = exerciseMarkers(*geometry, MarkerAudience::Instructor, nullptr, items.single ? -1 : mSelected);
        } else {
            // Items that cannot be placed as a whole yet (a path of one point, or all on one
            // vertex) are still shown, so the instructor sees where the next click continues.
            const bool path = items.ordered && items.numbers.empty();
            for (std::size_t i = 0; i < items.count(e); ++i) {
                const VertexId v = ExerciseGeometry::snap(items.point(e, i), drawn);
                if (v == kNoVertex) continue;
                ExerciseMarker m;
                m.kind = ExerciseMarker::Kind::PathPoint;
                m.positionMm = drawn.restPositionsMm()[v];
                m.normal = drawn.restNormals().size() > v ? drawn.restNormals()[v] : glm::vec3(0.0f);
                m.label = path && i == 0 ? QStringLiteral("start") : QString();
                m.selected = int(i) == mSelected;
                markers.markers.push_back(m);
                if (path) markers.pathMm.push_back(m.positionMm);
            }
        }
    }
    mMarkers = markers;

    showProblems(meshFile);
    updatePlacingUi();
    updateTitle();
    emit markersChanged(mMarkers);
}

void ExerciseEditorPanel::showProblems(const QString& meshFile) {
    // The list under the form, the fields and cells the problems name, and what can be pressed.
    const Exercise& e = exercise();
    const Guard guard(mShowing);
    QStringList lines;
    for (const QString& p : mProblems) lines << QStringLiteral("• ") + p.toHtmlEscaped();
    mProblemsLabel->setText(lines.join(QStringLiteral("<br>")));
    mProblemsLabel->setVisible(!mProblems.isEmpty());
    lines.clear();
    for (const QString& w : mWarnings) lines << QStringLiteral("⚠ ") + w.toHtmlEscaped();
    mWarningsLabel->setText(lines.join(QStringLiteral("<br>")));
    mWarningsLabel->setVisible(!mWarnings.isEmpty());
    QSet<QString> keys, warned;
    for (const QString& p : mProblems) keys.insert(problemKey(p));
    for (const QString& w : mWarnings) warned.insert(problemKey(w));
    const std::pair<QWidget*, const char*> fields[] = {{mNameEdit, "name"},
                                                       {mMeshCombo, "mesh"},
                                                       {mMeshUnitCombo, "mesh_unit"},
                                                       {mMeshScaleSpin, "mesh_unit"},
                                                       {mPresetCombo, "tissue_preset"},
                                                       {mTimeLimitSpin, "time_limit_s"},
                                                       {mDisplacementSpin, "damage.displacement_limit_mm"},
                                                       {mExcessiveSpin, "force.excessive_n"},
                                                       {mNeedsErrorSpin, "needs.max_error"},
                                                       {mNeedsBudgetSpin, "needs.budget_us"}};
    std::vector<std::pair<QWidget*, const char*>> marked(std::begin(fields), std::end(fields));
    const ExerciseEditing& editing = exerciseKind(e.type).editing();
    for (std::size_t i = 0; i < editing.numbers.size(); ++i)
        marked.emplace_back(page().numbers[i], editing.numbers[i].key);
    for (const auto& [widget, key] : marked) {
        const bool invalid = keys.contains(QLatin1String(key));
        if (widget->property("invalid").toBool() != invalid) {
            widget->setProperty("invalid", invalid);
            widget->style()->unpolish(widget);
            widget->style()->polish(widget);
        }
    }
    // The item cells: "<list>[i].<key>" marks a cell, "<list>[i]" (or a single item's key) its vertex.
    const PlacedItems& items = editing.items;
    QTableWidget* table = page().table;
    for (int r = 0; r < table->rowCount(); ++r)
        for (int c = kItemVertex; c < table->columnCount(); ++c) {
            const QString key = items.single ? QLatin1String(items.listKey)
                                             : QStringLiteral("%1[%2]").arg(QLatin1String(items.listKey)).arg(r);
            const QString cellKey = c == kItemVertex
                                        ? key + QStringLiteral(".vertex")
                                        : key + QLatin1Char('.') +
                                              QLatin1String(items.numbers[std::size_t(c - kItemNumbers)].key);
            const bool invalid = keys.contains(cellKey) || (c == kItemVertex && keys.contains(key));
            const QVariant background = invalid                    ? QVariant(QBrush(kInvalidCell))
                                        : warned.contains(cellKey) ? QVariant(QBrush(kWarningCell))
                                                                   : QVariant();
            if (QTableWidgetItem* it = table->item(r, c); it && it->data(Qt::BackgroundRole) != background)
                it->setData(Qt::BackgroundRole, background);
        }
    for (int r = 0; r < mRubricTable->rowCount(); ++r)
        for (int c = kRubricWeight; c < kRubricColumns; ++c) {
            QTableWidgetItem* it = mRubricTable->item(r, c);
            if (!it) continue;
            const QString key = QStringLiteral("rubric.") + mRubricTable->item(r, kRubricMetric)->text();
            const bool invalid = keys.contains(key + QLatin1Char('.') + QLatin1String(kRubricKeys[c])) ||
                                 keys.contains(key);
            const QVariant background = invalid ? QVariant(QBrush(kInvalidCell)) : QVariant();
            if (it->data(Qt::BackgroundRole) != background) it->setData(Qt::BackgroundRole, background);
        }

    const bool hasSelection = mSelected >= 0;
    const KindPage& p = page();
    p.remove->setEnabled(hasSelection);
    p.move->setEnabled(hasSelection || items.single);
    p.up->setEnabled(mSelected > 0);
    p.down->setEnabled(hasSelection && mSelected + 1 < itemCount());
    mPreviewAction->setEnabled(mBlocking.isEmpty());
    mPreviewButton->setEnabled(mBlocking.isEmpty());
    mShowMeshButton->setEnabled(!meshFile.isEmpty() && !drawnMeshMatches());
    mMeshStateLabel->setText(meshFile.isEmpty()   ? tr("Not found.")
                             : drawnMeshMatches() ? tr("Drawn in the viewport.")
                                                  : tr("Not drawn in the viewport."));
}

TouchReach ExerciseEditorPanel::touchReach() {
    return TouchReach{Viewport::kMaxTouchDepthMm, Viewport::kTouchDepthStepMm, Viewport::kDefaultTouchDepthMm};
}

void ExerciseEditorPanel::checkReach() {
    // The findings of the exercise as it was when the check began come back on the GUI thread;
    // only the latest check's are shown.
    // The worker calls back on its thread; the destructor stops it before this panel goes, and
    // Qt drops a call still queued for a panel that is gone.
    const std::uint64_t generation = mDocument->checkReach([this](ReachCheckResult result) {
        QMetaObject::invokeMethod(
            this, [this, result = std::move(result)]() mutable { showReach(std::move(result)); }, Qt::QueuedConnection);
    });
    mChecking = generation != 0;
    // Nothing to check (no mesh, or points not placed): no warnings. Otherwise the last ones stay
    // until the new ones come, and "Checking…" shows only when a check takes long enough to be
    // noticed (a vertex or tissue probed for the first time): most edits are answered from the
    // probe's cache at once, and a line that flickers on every keystroke would be noise.
    if (!mChecking) {
        mWarnings.clear();
        mCheckingTimer->stop();
        mCheckingLabel->setVisible(false);
    } else if (!mCheckingTimer->isActive() && !mCheckingLabel->isVisible()) {
        mCheckingTimer->start();
    }
}

void ExerciseEditorPanel::showReach(ReachCheckResult result) {
    if (result.generation != mDocument->latestCheck()) return;  // a later check is running
    mWarnings.clear();
    for (const ReachFinding& f : result.findings) {
        const QString warning = reachText(f, *result.geometry);
        // An item with a problem (a window upside down) is named by the problem alone.
        const QString target = problemKey(warning).section(QLatin1Char('.'), 0, 1);
        const bool named = std::any_of(mBlocking.begin(), mBlocking.end(),
                                       [&](const QString& p) { return problemKey(p).startsWith(target); });
        if (!named) mWarnings << warning;
    }
    mChecking = false;
    mCheckingTimer->stop();
    mCheckingLabel->setVisible(false);
    showProblems(qs(mDocument->meshFile()));
    emit reachChecked();
}

bool ExerciseEditorPanel::reachChecking() const { return mChecking; }

QString ExerciseEditorPanel::reachText(const ReachFinding& f, const ExerciseGeometry& geometry) const {
    using Kind = ReachFinding::Kind;
    const QLocale l = locale();
    const auto n = [&l](double v) { return l.toString(v, 'g', 3); };
    const Exercise& e = geometry.exercise();
    const QString instead = f.suggested
                                ? tr(" (%1–%2 N is met pressing at least two wheel steps past the default touch)")
                                      .arg(n(f.suggested->minN), n(f.suggested->maxN))
                                : QString();
    QStringList points;
    for (const std::size_t i : f.points) points << QString::number(i + 1);
    const QString lumpKey = QStringLiteral("detect_lumps.lumps[%1].depth_mm").arg(f.item);
    switch (f.kind) {
        case Kind::Unknown: {
            const QString why = qs(f.why);
            switch (f.subject) {
                case ReachFinding::Subject::Targets:
                    return tr("tissue_preset: whether the targets can be reached with the mouse is not known: %1")
                        .arg(why);
                case ReachFinding::Subject::Band:
                    return tr("tissue_preset: whether the band can be reached with the mouse is not known: %1")
                        .arg(why);
                case ReachFinding::Subject::Lumps:
                    return tr("tissue_preset: whether the lumps can be felt is not known: %1").arg(why);
                case ReachFinding::Subject::Coverage:
                    return tr("tissue_preset: whether the mouse presses hard enough to examine is not known: %1")
                        .arg(why);
            }
            return {};
        }
        case Kind::TargetBetweenSteps: {
            const PressTarget& def = geometry.targets()[f.item].def;
            return tr("%1: target %2 cannot be held with the mouse: its window %3–%4 N lies between %5 N at %6 mm and "
                      "%7 N at %8 mm deep (one turn of the wheel apart). Widen the window to take in one of them.")
                .arg(QStringLiteral("press_targets.targets[%1].force_min_n").arg(f.item))
                .arg(f.item + 1)
                .arg(n(def.forceMinN), n(def.forceMaxN), n(*f.target.belowForceN), n(*f.target.belowDepthMm),
                     n(*f.target.aboveForceN), n(*f.target.aboveDepthMm));
        }
        case Kind::TargetTooSoft:
            return tr("%1: target %2 cannot be reached with the mouse: pressing %3 mm deep (the deepest) gives %4 N, below "
                      "its window's %5 N. Lower the window to at most %4 N%6, or choose a stiffer tissue preset.")
                .arg(QStringLiteral("press_targets.targets[%1].force_min_n").arg(f.item))
                .arg(f.item + 1)
                .arg(n(f.target.maxDepthMm), n(f.target.maxForceN), n(geometry.targets()[f.item].def.forceMinN),
                     instead);
        case Kind::BandTooSoft:
            return tr("trace.force_min_n: the band cannot be reached with the mouse at path point %1: pressing %2 mm "
                      "deep (the deepest) gives as little as %3 N there, below the band's %4 N. Lower the band to at "
                      "most %3 N%5, or choose a stiffer tissue preset.")
                .arg(points.join(QStringLiteral(", ")), n(f.target.maxDepthMm), n(f.leastN), n(e.trace.forceMinN),
                     instead);
        case Kind::BandBetweenSteps:
            return tr("trace.force_min_n: the band %1–%2 N lies between the forces of two turns of the wheel at path "
                      "point %3: widen it.")
                .arg(n(e.trace.forceMinN), n(e.trace.forceMaxN), points.join(QStringLiteral(", ")));
        case Kind::LumpNeverEngaged:
            return tr("%1: lump %2 cannot be felt with the mouse: the surface above it does not sink to its top (%3 mm "
                      "under it) however deep the mouse presses. Make it shallower, or choose a softer tissue preset.")
                .arg(lumpKey)
                .arg(f.item + 1)
                .arg(n(geometry.lumps()[f.item].def.depthMm));
        case Kind::LumpTooDeep:
            return tr("%1: lump %2 cannot be felt with the mouse: its top lies %3 mm under the surface; the "
                      "surface sinks that far under a press %4 mm deep, and the lump is felt a wheel step (%5 mm) "
                      "deeper, but the mouse presses at most %6 mm deep. Make it at most %7 mm deep, or train this "
                      "one with a device.")
                .arg(lumpKey)
                .arg(f.item + 1)
                .arg(n(geometry.lumps()[f.item].def.depthMm), n(f.lump.engageDepthMm),
                     n(f.lump.feelDepthMm - f.lump.engageDepthMm), n(f.lump.mouseDeepestMm), n(f.lump.deepestFeltMm));
        case Kind::LumpExcessive:
            return tr("%1: feeling lump %2 takes about %3 N, at or above the excessive force %4 N: the trainee who "
                      "finds it is marked down for pressing too hard. Make it shallower, or raise the excessive force.")
                .arg(lumpKey)
                .arg(f.item + 1)
                .arg(n(*f.lump.forceN), n(f.excessiveN));
        case Kind::LumpBeyondDevice:
            return tr("%1: feeling lump %2 takes about %3 N, more than a desktop device renders (%4 N). Make it "
                      "shallower, or choose a softer tissue preset.")
                .arg(lumpKey)
                .arg(f.item + 1)
                .arg(n(*f.lump.forceN), n(f.deviceMaxN));
        case Kind::CoverageTooSoft:
            return tr("coverage.min_force_n: the mouse cannot examine this tissue: pressing %1 mm deep (the deepest) gives "
                      "%2 N over most of the surface, below the examining force %3 N, so nothing the trainee does counts as "
                      "examined. Lower it to %4 N (what the mouse's default press gives), or choose a stiffer tissue preset.")
                .arg(n(touchReach().maxDepthMm), n(f.examine.deepestN), n(e.coverage.minForceN),
                     n(f.examine.defaultPressN));
    }
    return {};
}

void ExerciseEditorPanel::updateTitle() {
    const QString file = mPath.isEmpty() ? tr("not saved yet") : QFileInfo(mPath).fileName();
    mTitleLabel->setText(tr("%1 — %2%3")
                             .arg(qs(exercise().name).isEmpty() ? tr("(unnamed)") : qs(exercise().name), file,
                                  isModified() ? tr(" (modified)") : QString()));
    mTitleLabel->setToolTip(mPath.isEmpty() ? QString() : QDir::toNativeSeparators(mPath));
}

void ExerciseEditorPanel::showMessage(const QString& text, bool error) {
    mMessageLabel->setText(text);
    mMessageLabel->setProperty("error", error);
    mMessageLabel->style()->unpolish(mMessageLabel);
    mMessageLabel->style()->polish(mMessageLabel);
    mMessageLabel->setVisible(!text.isEmpty());
}

bool ExerciseEditorPanel::preview() {
    if (!mBlocking.isEmpty()) {
        showMessage(tr("Cannot try it: the exercise has problems (listed above)."), true);
        return false;
    }
    setPlacing(Placing::None);
    emit previewRequested(exercise());
    return true;
}

}  // namespace palpate
