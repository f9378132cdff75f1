#include "widgets/ExerciseEditorPanel.h"

#include "widgets/ExerciseText.h"

#include "widgets/SaveFileChoice.h"
#include "widgets/GuardedLoad.h"
#include "widgets/ScrollWheelGuard.h"

#include "widgets/ExerciseEditCommands.h"
#include "widgets/Viewport.h"

#include "engine/exercise/ExerciseGeometry.h"
#include "engine/scene/TissuePreset.h"
#include "engine/scoring/TargetReachability.h"
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

constexpr ExerciseType kTypes[] = {ExerciseType::PressTargets, ExerciseType::FindLump, ExerciseType::Trace};
int typeIndex(ExerciseType type) { return int(std::find(std::begin(kTypes), std::end(kTypes), type) - std::begin(kTypes)); }

/// Files the shipped resources are found by (their folder is resources/).
constexpr const char* kResourceAnchors[] = {"meshes/stomach_3970.off", "meshes/sphere_1442.off",
                                            "presets/tissues/phantom_gel.json"};
constexpr const char* kDefaultMesh = "meshes/stomach_3970.off";
/// The new exercise's tissue: the stomach wall on the default stomach, else the gel phantom.
constexpr const char* kDefaultPresets[] = {"presets/tissues/stomach_wall.json", "presets/tissues/phantom_gel.json"};

/// Press-target table columns.
enum TargetColumn { kTargetNumber, kTargetVertex, kTargetForceMin, kTargetForceMax, kTargetHold, kTargetTolerance, kTargetColumns };
/// The JSON key each column edits (problems naming it mark the cell).
constexpr const char* kTargetKeys[] = {"", "vertex", "force_min_n", "force_max_n", "hold_s", "tolerance_mm"};
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
QLabel#messageLabel[error="true"] { color: #c62828; }
QLabel#messageLabel[error="false"] { color: #2e7d32; }
QLabel#placingLabel { background-color: #e3f2fd; border: 1px solid #90caf9; border-radius: 3px; padding: 3px; }
QLabel#exerciseTitleLabel { font-weight: bold; }
)";

const QColor kInvalidCell(255, 224, 224);
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
    : QWidget(parent), mFindResource(std::move(findResource)) {
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
    // The stack is a child: it is deleted after this body and emits cleanChanged on its way out,
    // when the members the slot touches are already gone.
    mUndoStack->disconnect(this);
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
    for (int i = 0; i < 3; ++i) {
        mNewActions[i] = new QAction(this);
        mNewActions[i]->setObjectName(QStringLiteral("newExerciseAction%1").arg(i));
        const ExerciseType type = kTypes[i];
        connect(mNewActions[i], &QAction::triggered, this, [this, type] {
            if (confirmDiscard()) newExercise(type);
        });
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
    for (int i = 0; i < 3; ++i) mTypeCombo->addItem(QString());
    exerciseForm->addRow(rowLabel(QT_TR_NOOP("Type:")), mTypeCombo);
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
        if (index >= 0 && index < 3) changeType(kTypes[index]);
    });
    connect(mNameEdit, &QLineEdit::textEdited, this, [this] { onFieldEdited(kName); });
    connect(mDescriptionEdit, &QPlainTextEdit::textChanged, this, [this] { onFieldEdited(kDescription); });
    const std::pair<QDoubleSpinBox*, Field> spins[] = {
        {mTimeLimitSpin, kTimeLimit},         {mDisplacementSpin, kDisplacementLimit}, {mExcessiveSpin, kExcessiveForce},
        {mLumpRadiusSpin, kLumpRadius},       {mLumpStiffnessSpin, kLumpStiffness},    {mTraceMinSpin, kTraceForceMin},
        {mTraceMaxSpin, kTraceForceMax},      {mTraceToleranceSpin, kTraceTolerance},  {mNeedsErrorSpin, kNeedsError},
        {mNeedsBudgetSpin, kNeedsBudget},     {mMeshScaleSpin, kMeshScale}};
    for (const auto& [spin, field] : spins) {
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, field = field] { onFieldEdited(field); });
        // Leaving the field ends its step: a later edit of it is a step of its own.
        connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { ++mMergeEpoch; });
    }
    connect(mNameEdit, &QLineEdit::editingFinished, this, [this] { ++mMergeEpoch; });
    connect(mNeedsCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (mShowing) return;
        Exercise e = mExercise;
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
        const QString path = resolved(mExercise, mExercise.meshPath);
        if (path.isEmpty()) showMessage(tr("The mesh '%1' cannot be found.").arg(qs(mExercise.meshPath)), true);
        else emit meshRequested(path);
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
    // Tool buttons: push buttons' minimum widths would not fit five in a narrow dock.
    auto listButtons = [this](QWidget* page, QToolButton*& add, QToolButton*& move, QToolButton*& remove,
                              QToolButton*& up, QToolButton*& down, const char* prefix) {
        auto* row = new QHBoxLayout;
        row->setSpacing(4);
        add = new QToolButton(page);
        add->setObjectName(QLatin1String(prefix) + QStringLiteral("AddButton"));
        add->setCheckable(true);
        move = new QToolButton(page);
        move->setObjectName(QLatin1String(prefix) + QStringLiteral("MoveButton"));
        move->setCheckable(true);
        remove = new QToolButton(page);
        remove->setObjectName(QLatin1String(prefix) + QStringLiteral("RemoveButton"));
        up = new QToolButton(page);
        up->setObjectName(QLatin1String(prefix) + QStringLiteral("UpButton"));
        up->setArrowType(Qt::UpArrow);
        down = new QToolButton(page);
        down->setObjectName(QLatin1String(prefix) + QStringLiteral("DownButton"));
        down->setArrowType(Qt::DownArrow);
        row->addWidget(add);
        row->addWidget(move);
        row->addWidget(remove);
        row->addStretch(1);
        row->addWidget(up);
        row->addWidget(down);
        connect(remove, &QToolButton::clicked, this, &ExerciseEditorPanel::removeSelected);
        connect(up, &QToolButton::clicked, this, [this] { moveSelected(-1); });
        connect(down, &QToolButton::clicked, this, [this] { moveSelected(+1); });
        return row;
    };

    // Press targets: the table, edited in place.
    auto* targetsPage = new QWidget(mTypePages);
    targetsPage->setObjectName(QStringLiteral("pressTargetsPage"));
    auto* targetsLayout = new QVBoxLayout(targetsPage);
    targetsLayout->setContentsMargins(0, 0, 0, 0);
    mTargetTable = new QTableWidget(0, kTargetColumns, targetsPage);
    mTargetTable->setObjectName(QStringLiteral("targetTable"));
    mTargetTable->verticalHeader()->setVisible(false);
    mTargetTable->verticalHeader()->setDefaultSectionSize(mTargetTable->fontMetrics().height() + 8);
    mTargetTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    mTargetTable->setSelectionMode(QAbstractItemView::SingleSelection);
    mTargetTable->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                                  QAbstractItemView::AnyKeyPressed);
    mTargetTable->setItemDelegateForColumn(kTargetVertex, new NumberDelegate(mTargetTable, 0, 0x7fffffff, 0));
    mTargetTable->setItemDelegateForColumn(kTargetForceMin, new NumberDelegate(mTargetTable, 0.0, 1000.0, 3));
    mTargetTable->setItemDelegateForColumn(kTargetForceMax, new NumberDelegate(mTargetTable, 0.0, 1000.0, 3));
    mTargetTable->setItemDelegateForColumn(kTargetHold, new NumberDelegate(mTargetTable, 0.0, 600.0, 3));
    mTargetTable->setItemDelegateForColumn(kTargetTolerance, new NumberDelegate(mTargetTable, 0.0, 1000.0, 3));
    mTargetTable->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    mTargetTable->horizontalHeader()->setSectionResizeMode(kTargetNumber, QHeaderView::ResizeToContents);
    mTargetTable->horizontalHeader()->setMinimumSectionSize(24);
    for (QAction* action : {mRemoveAction, mMoveUpAction, mMoveDownAction}) mTargetTable->addAction(action);
    mRemoveAction->setShortcutContext(Qt::WidgetShortcut);
    mMoveUpAction->setShortcutContext(Qt::WidgetShortcut);
    mMoveDownAction->setShortcutContext(Qt::WidgetShortcut);
    targetsLayout->addWidget(mTargetTable);
    targetsLayout->addLayout(listButtons(targetsPage, mAddTargetButton, mMoveTargetButton, mRemoveTargetButton,
                                         mTargetUpButton, mTargetDownButton, "target"));
    connect(mTargetTable, &QTableWidget::cellChanged, this, &ExerciseEditorPanel::onTargetCellChanged);
    connect(mTargetTable, &QTableWidget::itemSelectionChanged, this, [this] {
        if (mShowing) return;
        const auto rows = mTargetTable->selectionModel()->selectedRows();
        setSelectedIndex(rows.isEmpty() ? -1 : rows.front().row());
    });
    connect(mAddTargetButton, &QToolButton::clicked, this,
            [this](bool on) { setPlacing(on ? Placing::AddTarget : Placing::None); });
    connect(mMoveTargetButton, &QToolButton::clicked, this,
            [this](bool on) { setPlacing(on ? Placing::MoveSelected : Placing::None); });
    mTypePages->addWidget(targetsPage);

    // Find the lump: the inclusion.
    auto* lumpPage = new QWidget(mTypePages);
    lumpPage->setObjectName(QStringLiteral("findLumpPage"));
    auto* lumpForm = new QFormLayout(lumpPage);
    lumpForm->setContentsMargins(0, 0, 0, 0);
    lumpForm->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    {
        auto* row = new QWidget(lumpPage);
        auto* layout = new QHBoxLayout(row);
        layout->setContentsMargins(0, 0, 0, 0);
        mLumpCentreLabel = new QLabel(row);
        mLumpCentreLabel->setObjectName(QStringLiteral("lumpCentreLabel"));
        mPlaceLumpButton = new QPushButton(row);
        mPlaceLumpButton->setObjectName(QStringLiteral("placeLumpButton"));
        mPlaceLumpButton->setCheckable(true);
        layout->addWidget(mLumpCentreLabel, 1);
        layout->addWidget(mPlaceLumpButton);
        lumpForm->addRow(rowLabel(QT_TR_NOOP("Centre:")), row);
    }
    mLumpRadiusSpin = doubleSpin(lumpPage, "lumpRadiusSpin", 0.0, 1000.0, 2, 0.5);
    lumpForm->addRow(rowLabel(QT_TR_NOOP("Radius:")), mLumpRadiusSpin);
    mLumpStiffnessSpin = doubleSpin(lumpPage, "lumpStiffnessSpin", 0.0, 1.0, 3, 0.05);
    lumpForm->addRow(rowLabel(QT_TR_NOOP("Stiffness factor:")), mLumpStiffnessSpin);
    connect(mPlaceLumpButton, &QPushButton::clicked, this,
            [this](bool on) { setPlacing(on ? Placing::PlaceInclusion : Placing::None); });
    mTypePages->addWidget(lumpPage);

    // Trace: the path points and the band.
    auto* tracePage = new QWidget(mTypePages);
    tracePage->setObjectName(QStringLiteral("tracePage"));
    auto* traceLayout = new QVBoxLayout(tracePage);
    traceLayout->setContentsMargins(0, 0, 0, 0);
    mPathList = new QListWidget(tracePage);
    mPathList->setObjectName(QStringLiteral("pathList"));
    mPathList->setSelectionMode(QAbstractItemView::SingleSelection);
    mPathList->setFixedHeight(mPathList->fontMetrics().height() * 6 + 12);
    for (QAction* action : {mRemoveAction, mMoveUpAction, mMoveDownAction}) mPathList->addAction(action);
    traceLayout->addWidget(mPathList);
    traceLayout->addLayout(listButtons(tracePage, mAddPointButton, mMovePointButton, mRemovePointButton, mPointUpButton,
                                       mPointDownButton, "pathPoint"));
    auto* traceForm = new QFormLayout;
    traceForm->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    mTraceMinSpin = doubleSpin(tracePage, "traceForceMinSpin", 0.0, 1000.0, 3, 0.05);
    traceForm->addRow(rowLabel(QT_TR_NOOP("Band from:")), mTraceMinSpin);
    mTraceMaxSpin = doubleSpin(tracePage, "traceForceMaxSpin", 0.0, 1000.0, 3, 0.05);
    traceForm->addRow(rowLabel(QT_TR_NOOP("Band to:")), mTraceMaxSpin);
    mTraceToleranceSpin = doubleSpin(tracePage, "traceToleranceSpin", 0.0, 1000.0, 2, 0.5);
    traceForm->addRow(rowLabel(QT_TR_NOOP("Tolerance:")), mTraceToleranceSpin);
    traceLayout->addLayout(traceForm);
    connect(mPathList, &QListWidget::itemSelectionChanged, this, [this] {
        if (mShowing) return;
        const auto rows = mPathList->selectionModel()->selectedRows();
        setSelectedIndex(rows.isEmpty() ? -1 : rows.front().row());
    });
    connect(mAddPointButton, &QToolButton::clicked, this,
            [this](bool on) { setPlacing(on ? Placing::AddPathPoint : Placing::None); });
    connect(mMovePointButton, &QToolButton::clicked, this,
            [this](bool on) { setPlacing(on ? Placing::MoveSelected : Placing::None); });
    mTypePages->addWidget(tracePage);
}

QString ExerciseEditorPanel::typeText(ExerciseType type) const {
    return exerciseText(ViewText{exerciseKind(type).label()});
}

void ExerciseEditorPanel::retranslateUi() {
    for (const auto& [label, text] : mRowLabels) label->setText(tr(text));
    mUndoAction->setText(tr("Undo"));
    mRedoAction->setText(tr("Redo"));
    const QString newTips[] = {tr("A new exercise: press a sequence of surface targets, each with a force window and a hold."),
                               tr("A new exercise: find a hidden stiff inclusion by palpation and mark it."),
                               tr("A new exercise: trace a path on the surface, keeping the force in a band.")};
    for (int i = 0; i < 3; ++i) {
        mNewActions[i]->setText(tr("New: %1").arg(typeText(kTypes[i])));
        mNewActions[i]->setToolTip(newTips[i]);
        mTypeCombo->setItemText(i, typeText(kTypes[i]));
        mTypeCombo->setItemData(i, newTips[i].section(QLatin1String(": "), 1), Qt::ToolTipRole);
    }
    mNewButton->setText(tr("New"));
    mNewButton->setToolTip(tr("A new exercise of a type; asks before unsaved changes are lost."));
    mOpenAction->setText(tr("Open…"));
    mOpenAction->setToolTip(tr("Open an exercise file (Ctrl+O)."));
    mSaveAction->setText(tr("Save"));
    mSaveAction->setToolTip(tr("Save the exercise to its file (Ctrl+S); refused while it has problems."));
    mSaveAsAction->setText(tr("Save As…"));
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
    mNameEdit->setToolTip(tr("The name trainees and score reports see (name)."));
    mNameEdit->setPlaceholderText(tr("Required"));
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

    mTargetTable->setHorizontalHeaderLabels(
        {tr("#"), tr("Vertex"), tr("Fmin N"), tr("Fmax N"), tr("Hold s"), tr("Tol. mm")});
    const QString targetTips[] = {tr("The order the trainee presses them in."),
                                  tr("The target's vertex, in the mesh file's numbering (vertex)."),
                                  tr("The force window's lower end, N (force_min_n)."),
                                  tr("The force window's upper end, N (force_max_n)."),
                                  tr("How long the force must stay in the window without a break, s (hold_s)."),
                                  tr("How close to the target the contact must be, mm (tolerance_mm).")};
    for (int c = 0; c < kTargetColumns; ++c)
        if (QTableWidgetItem* header = mTargetTable->horizontalHeaderItem(c)) header->setToolTip(targetTips[c]);
    mAddTargetButton->setText(tr("Add by clicking"));
    mAddTargetButton->setToolTip(tr("While on, each click on the tissue appends a target there, with the last target's "
                                    "window, hold and tolerance; the first gets a window the tissue reaches with the "
                                    "mouse (Esc stops)."));
    mMoveTargetButton->setText(tr("Move"));
    mMoveTargetButton->setToolTip(tr("The next click on the mesh moves the selected target there."));
    mRemoveTargetButton->setText(tr("Remove"));
    mRemoveTargetButton->setToolTip(tr("Remove the selected target (Delete)."));
    mTargetUpButton->setToolTip(tr("Move the selected target earlier (Ctrl+Up)."));
    mTargetDownButton->setToolTip(tr("Move the selected target later (Ctrl+Down)."));

    mPlaceLumpButton->setText(tr("Place by clicking"));
    mPlaceLumpButton->setToolTip(tr("The next click on the mesh puts the inclusion's centre there."));
    mLumpRadiusSpin->setSuffix(tr(" mm"));
    mLumpRadiusSpin->setToolTip(tr("Vertices this close to the centre are in the inclusion (find_lump.inclusion.radius_mm)."));
    mLumpStiffnessSpin->setToolTip(tr("The inclusion's slopes are multiplied by this, in (0, 1]: smaller is stiffer "
                                      "(find_lump.inclusion.stiffness_factor)."));

    mAddPointButton->setText(tr("Add by clicking"));
    mAddPointButton->setToolTip(tr("While on, each click on the tissue appends a path point there; the first sets a band "
                                   "the tissue reaches with the mouse, if the band is still the default (Esc stops)."));
    mMovePointButton->setText(tr("Move"));
    mMovePointButton->setToolTip(tr("The next click on the mesh moves the selected path point there."));
    mRemovePointButton->setText(tr("Remove"));
    mRemovePointButton->setToolTip(tr("Remove the selected path point (Delete)."));
    mPointUpButton->setToolTip(tr("Move the selected point earlier on the path (Ctrl+Up)."));
    mPointDownButton->setToolTip(tr("Move the selected point later on the path (Ctrl+Down)."));
    mTraceMinSpin->setSuffix(tr(" N"));
    mTraceMinSpin->setToolTip(tr("The force band's lower end (trace.force_min_n)."));
    mTraceMaxSpin->setSuffix(tr(" N"));
    mTraceMaxSpin->setToolTip(tr("The force band's upper end (trace.force_max_n)."));
    mTraceToleranceSpin->setSuffix(tr(" mm"));
    mTraceToleranceSpin->setToolTip(tr("A path point is covered by contact this close to it (trace.tolerance_mm)."));

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
    showExercise(mExercise);
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
    return {mNewActions[0], mNewActions[1], mNewActions[2], mOpenAction,   mSaveAction,
            mSaveAsAction,  mUndoAction,    mRedoAction,    mPreviewAction};
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

const TissueMesh* ExerciseEditorPanel::checkMesh(const QString& meshPath) {
    if (drawnMeshMatches()) return mDrawnMesh.get();
    if (meshPath.isEmpty()) return nullptr;
    const QString key = meshPath + QLatin1Char('\n') + qs(mExercise.meshUnit.text());
    if (key != mCheckMeshPath) {
        // Loaded once per path and unit: the checks run after every edit.
        mCheckMeshPath = key;
        mCheckMesh.reset();
        mCheckMeshError.clear();
        auto loaded = TissueMesh::load(ss(meshPath), mExercise.meshUnit);
        if (loaded.mesh) mCheckMesh = std::make_shared<const TissueMesh>(std::move(*loaded.mesh));
        else mCheckMeshError = qs(loaded.error());
    }
    return mCheckMesh.get();
}

void ExerciseEditorPanel::setDrawnMesh(std::shared_ptr<const TissueMesh> mesh, const QString& path) {
    mDrawnMesh = std::move(mesh);
    mDrawnMeshPath = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
    if (!drawnMeshMatches() && mPlacing != Placing::None) updatePlacingUi();
    refresh();
}

bool ExerciseEditorPanel::drawnMeshMatches() const {
    if (!mDrawnMesh || mDrawnMeshPath.isEmpty()) return false;
    // The same file read in another unit is another size: its points in mm would not be the exercise's.
    if (!(mDrawnMesh->report().unit == mExercise.meshUnit)) return false;
    const QString mine = QFileInfo(resolved(mExercise, mExercise.meshPath)).canonicalFilePath();
    return !mine.isEmpty() && mine == QFileInfo(mDrawnMeshPath).canonicalFilePath();
}

void ExerciseEditorPanel::newExercise(ExerciseType type) {
    Exercise e;
    e.type = type;
    e.name = ss(tr("New exercise: %1").arg(typeText(type).toLower()));
    // The drawn mesh (the instructor places points on what they see), else the default stomach.
    if (mDrawnMesh && !mDrawnMeshPath.isEmpty()) e.meshPath = ss(storablePath(e, mDrawnMeshPath));
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
    if (mDrawnMesh && mDrawnMesh->vertexCount() > 0) {
        const auto& rest = mDrawnMesh->restPositionsMm();
        const auto it = std::max_element(rest.begin(), rest.end(), [](const glm::vec3& a, const glm::vec3& b) { return a.x < b.x; });
        const VertexId v = VertexId(it - rest.begin());
        e.findLump.inclusion.centre.vertex = mDrawnMesh->originalIndex().empty() ? v : mDrawnMesh->originalIndex()[v];
    } else {
        e.findLump.inclusion.centre.vertex = 0;
    }
    setPlacing(Placing::None);
    mPath.clear();
    mSelected = -1;
    mUndoStack->clear();
    showExercise(e);
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
    if (result.exercise->type == ExerciseType::DetectLumps) {
        // Not editable here yet (docs/scoring.md, "detect_lumps"): said, and the file left alone.
        const QString text = tr("%1 is a detect-lumps exercise, which this editor cannot edit yet: edit its file "
                                "(docs/scoring.md lists the keys); trainees can run it.")
                                 .arg(QDir::toNativeSeparators(path));
        showMessage(text, true);
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
    Exercise out = mExercise;
    out.sourcePath = ss(QFileInfo(path).absoluteFilePath());
    const QString meshFile = resolved(mExercise, mExercise.meshPath);
    const QString presetFile = resolved(mExercise, mExercise.tissuePresetPath);
    out.meshPath = ss(storablePath(out, meshFile));
    out.tissuePresetPath = ss(storablePath(out, presetFile));
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
    showMessage(tr("Saved %1.").arg(QDir::toNativeSeparators(mPath)), false);
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
        QString base = qs(mExercise.name).toLower();
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
    QString start = resolved(mExercise, mesh ? mExercise.meshPath : mExercise.tissuePresetPath);
    if (start.isEmpty()) start = mResourceRoot;
    const QString path = mesh ? QFileDialog::getOpenFileName(this, tr("Choose a mesh"), start,
                                                             tr("Meshes (*.off *.obj *.ply *.stl *.om);;All files (*)"))
                              : QFileDialog::getOpenFileName(this, tr("Choose a tissue preset"), start,
                                                             tr("Tissue presets (*.json);;All files (*)"));
    if (!path.isEmpty()) commitPath(mesh, storablePath(mExercise, path));
}

void ExerciseEditorPanel::setDiscardQuestion(DiscardQuestion question) { mDiscardQuestion = std::move(question); }

bool ExerciseEditorPanel::confirmDiscard() {
    if (!isModified()) return true;
    switch (mDiscardQuestion ? mDiscardQuestion(qs(mExercise.name)) : DiscardAnswer::Cancel) {
        case DiscardAnswer::Discard: return true;
        case DiscardAnswer::Save: return save().isEmpty();
        case DiscardAnswer::Cancel: return false;
    }
    return false;
}

bool ExerciseEditorPanel::isModified() const { return !mUndoStack->isClean(); }

// ---- Showing and editing ---------------------------------------------------------------------------

void ExerciseEditorPanel::showExercise(const Exercise& exercise) {
    {
        const Guard guard(mShowing);
        mExercise = exercise;
        const Exercise& e = mExercise;
        mTypeCombo->setCurrentIndex(typeIndex(e.type));
        mTypePages->setCurrentIndex(typeIndex(e.type));
        mTypeGroup->setTitle(typeText(e.type));
        if (mNameEdit->text() != qs(e.name)) mNameEdit->setText(qs(e.name));
        if (mDescriptionEdit->toPlainText() != qs(e.description)) mDescriptionEdit->setPlainText(qs(e.description));
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

        // Press targets.
        const auto& targets = e.pressTargets.targets;
        mTargetTable->setRowCount(int(targets.size()));
        for (int r = 0; r < int(targets.size()); ++r) {
            const PressTarget& t = targets[std::size_t(r)];
            setCellValue(mTargetTable, r, kTargetNumber, QString::number(r + 1), false);
            if (t.at.vertex) setCellValue(mTargetTable, r, kTargetVertex, int(*t.at.vertex), true);
            else
                setCellValue(mTargetTable, r, kTargetVertex,
                             tr("(%1, %2, %3) mm").arg(t.at.pointMm.x).arg(t.at.pointMm.y).arg(t.at.pointMm.z), false);
            setCellValue(mTargetTable, r, kTargetForceMin, t.forceMinN, true);
            setCellValue(mTargetTable, r, kTargetForceMax, t.forceMaxN, true);
            setCellValue(mTargetTable, r, kTargetHold, t.holdS, true);
            setCellValue(mTargetTable, r, kTargetTolerance, t.toleranceMm, true);
        }
        fitTableHeight(mTargetTable, int(targets.size()), 8);

        // Find the lump.
        const InclusionDef& inc = e.findLump.inclusion;
        mLumpCentreLabel->setText(inc.centre.vertex ? tr("vertex %1").arg(*inc.centre.vertex)
                                                    : tr("(%1, %2, %3) mm, snapped to the nearest vertex")
                                                          .arg(inc.centre.pointMm.x)
                                                          .arg(inc.centre.pointMm.y)
                                                          .arg(inc.centre.pointMm.z));
        setSpin(mLumpRadiusSpin, inc.radiusMm);
        setSpin(mLumpStiffnessSpin, inc.stiffnessFactor);

        // Trace.
        const auto& path = e.trace.path;
        while (mPathList->count() > int(path.size())) delete mPathList->takeItem(mPathList->count() - 1);
        while (mPathList->count() < int(path.size())) mPathList->addItem(QString());
        for (int i = 0; i < int(path.size()); ++i) {
            const SurfacePoint& p = path[std::size_t(i)];
            QString text = p.vertex ? tr("%1.  vertex %2").arg(i + 1).arg(*p.vertex)
                                    : tr("%1.  (%2, %3, %4) mm").arg(i + 1).arg(p.pointMm.x).arg(p.pointMm.y).arg(p.pointMm.z);
            if (i == 0) text += tr("  (start)");
            else if (i + 1 == int(path.size())) text += tr("  (end)");
            if (mPathList->item(i)->text() != text) mPathList->item(i)->setText(text);
        }
        setSpin(mTraceMinSpin, e.trace.forceMinN);
        setSpin(mTraceMaxSpin, e.trace.forceMaxN);
        setSpin(mTraceToleranceSpin, e.trace.toleranceMm);

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
        const int count = e.type == ExerciseType::PressTargets ? int(targets.size())
                          : e.type == ExerciseType::Trace      ? int(path.size())
                                                               : 0;
        if (mSelected >= count) mSelected = count - 1;
        if (e.type == ExerciseType::PressTargets) {
            if (mSelected >= 0) mTargetTable->selectRow(mSelected);
            else mTargetTable->clearSelection();
        } else if (e.type == ExerciseType::Trace) {
            if (mSelected >= 0) mPathList->setCurrentRow(mSelected);
            else mPathList->clearSelection();
        }
    }
    // An undone type change or removal may leave a mode that no longer fits (adding path points
    // to a press-targets exercise, moving a point that is gone): it ends.
    setPlacing(mPlacing);
    refresh();
}

void ExerciseEditorPanel::pushEdit(const Exercise& after, const QString& text, int field) {
    if (sameExercise(after, mExercise)) return;
    showMessage(QString(), false);
    // Typing "1.5" or holding an arrow is one step, until the field loses focus.
    const int mergeKey = field < 0 ? ExerciseEditCommand::kNoMerge : field + kFieldCount * (mMergeEpoch % 64);
    mUndoStack->push(new ExerciseEditCommand(mExercise, after, text, mergeKey,
                                             [this](const Exercise& exercise) { showExercise(exercise); }));
}

void ExerciseEditorPanel::onFieldEdited(int field) {
    if (mShowing) return;
    Exercise e = mExercise;
    QString what;
    switch (Field(field)) {
        case kName: e.name = ss(mNameEdit->text()); what = tr("name"); break;
        case kDescription: e.description = ss(mDescriptionEdit->toPlainText()); what = tr("description"); break;
        case kTimeLimit: e.timeLimitS = mTimeLimitSpin->value(); what = tr("time limit"); break;
        case kDisplacementLimit: e.displacementLimitMm = mDisplacementSpin->value(); what = tr("damage limit"); break;
        case kExcessiveForce: e.excessiveForceN = mExcessiveSpin->value(); what = tr("excessive force"); break;
        case kLumpRadius: e.findLump.inclusion.radiusMm = mLumpRadiusSpin->value(); what = tr("inclusion radius"); break;
        case kLumpStiffness:
            e.findLump.inclusion.stiffnessFactor = mLumpStiffnessSpin->value();
            what = tr("stiffness factor");
            break;
        case kTraceForceMin: e.trace.forceMinN = mTraceMinSpin->value(); what = tr("band's lower force"); break;
        case kTraceForceMax: e.trace.forceMaxN = mTraceMaxSpin->value(); what = tr("band's upper force"); break;
        case kTraceTolerance: e.trace.toleranceMm = mTraceToleranceSpin->value(); what = tr("trace tolerance"); break;
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
        case kFieldCount: return;
    }
    pushEdit(e, tr("Change %1").arg(what), field);
}

void ExerciseEditorPanel::commitMeshUnit(int index) {
    if (mShowing || index < 0 || index >= kMeshUnitChoices) return;
    Exercise e = mExercise;
    // "scale…" starts from the factor the exercise has (10 for cm), for the user to change.
    e.meshUnit = index == kScaleChoice ? MeshUnit{"", mExercise.meshUnit.mmPerUnit} : namedMeshUnit(index);
    mMeshScaleSpin->setVisible(index == kScaleChoice);
    pushEdit(e, tr("Change %1").arg(tr("mesh unit")), -1);
}

void ExerciseEditorPanel::onTargetCellChanged(int row, int column) {
    if (mShowing || row < 0 || row >= int(mExercise.pressTargets.targets.size())) return;
    Exercise e = mExercise;
    PressTarget& t = e.pressTargets.targets[std::size_t(row)];
    const QVariant value = mTargetTable->item(row, column)->data(Qt::EditRole);
    bool ok = false;
    const double v = value.toDouble(&ok);
    if (!ok) {
        showExercise(mExercise);  // not a number: show what the exercise holds
        return;
    }
    switch (column) {
        case kTargetVertex:
            if (v < 0) return showExercise(mExercise);
            t.at = SurfacePoint{std::uint32_t(v), glm::vec3(0.0f)};
            break;
        case kTargetForceMin: t.forceMinN = v; break;
        case kTargetForceMax: t.forceMaxN = v; break;
        case kTargetHold: t.holdS = v; break;
        case kTargetTolerance: t.toleranceMm = v; break;
        default: return;
    }
    const QString header = mTargetTable->horizontalHeaderItem(column) ? mTargetTable->horizontalHeaderItem(column)->text() : QString();
    pushEdit(e, tr("Change target %1's %2").arg(row + 1).arg(header));
}

void ExerciseEditorPanel::onRubricCellChanged(int row, int column) {
    if (mShowing || column < kRubricWeight) return;
    QTableWidgetItem* nameItem = mRubricTable->item(row, kRubricMetric);
    if (!nameItem) return;
    const Metric m = Metric(nameItem->data(Qt::UserRole).toInt());
    bool ok = false;
    const double v = mRubricTable->item(row, column)->data(Qt::EditRole).toDouble(&ok);
    if (!ok) return showExercise(mExercise);
    Exercise e = mExercise;
    // An edited line is set in the exercise whole: its other values are the defaults it showed.
    RubricItem line = e.rubric[std::size_t(m)] ? *e.rubric[std::size_t(m)] : defaultRubricItem(e, m);
    if (column == kRubricWeight) line.weight = v;
    else if (column == kRubricFull) line.fullMarks = v;
    else line.zeroMarks = v;
    e.rubric[std::size_t(m)] = line;
    pushEdit(e, tr("Change the rubric's %1").arg(qs(std::string(metricName(m)))));
}

void ExerciseEditorPanel::resetRubric() {
    Exercise e = mExercise;
    e.rubric = {};
    pushEdit(e, tr("Reset the rubric"));
}

void ExerciseEditorPanel::commitPath(bool mesh, const QString& text) {
    if (mShowing) return;
    Exercise e = mExercise;
    (mesh ? e.meshPath : e.tissuePresetPath) = ss(text.trimmed());
    pushEdit(e, mesh ? tr("Change the mesh") : tr("Change the tissue preset"));
}

void ExerciseEditorPanel::changeType(ExerciseType type) {
    if (type == mExercise.type) return;
    setPlacing(Placing::None);
    Exercise e = mExercise;
    e.type = type;
    // Rubric lines of metrics the new type does not measure would make the file invalid.
    for (std::size_t i = 0; i < kMetricCount; ++i)
        if (!exerciseKind(type).measures(Metric(i))) e.rubric[i].reset();
    mSelected = -1;
    pushEdit(e, tr("Change the type to %1").arg(typeText(type).toLower()));
}

void ExerciseEditorPanel::setSelectedIndex(int index) {
    const int count = mExercise.type == ExerciseType::PressTargets ? int(mExercise.pressTargets.targets.size())
                      : mExercise.type == ExerciseType::Trace      ? int(mExercise.trace.path.size())
                                                                   : 0;
    index = index >= 0 && index < count ? index : -1;
    if (index == mSelected) return;
    mSelected = index;
    {
        const Guard guard(mShowing);
        QAbstractItemView* view = mExercise.type == ExerciseType::Trace ? static_cast<QAbstractItemView*>(mPathList)
                                                                        : static_cast<QAbstractItemView*>(mTargetTable);
        if (index < 0) view->clearSelection();
        else if (view == mTargetTable) mTargetTable->selectRow(index);
        else mPathList->setCurrentRow(index);
    }
    if (mPlacing == Placing::MoveSelected && index < 0) setPlacing(Placing::None);
    refresh();
}

void ExerciseEditorPanel::removeSelected() {
    Exercise e = mExercise;
    const int i = mSelected;
    if (e.type == ExerciseType::PressTargets && i >= 0 && i < int(e.pressTargets.targets.size())) {
        e.pressTargets.targets.erase(e.pressTargets.targets.begin() + i);
        mSelected = std::min(i, int(e.pressTargets.targets.size()) - 1);
        pushEdit(e, tr("Remove target %1").arg(i + 1));
    } else if (e.type == ExerciseType::Trace && i >= 0 && i < int(e.trace.path.size())) {
        e.trace.path.erase(e.trace.path.begin() + i);
        mSelected = std::min(i, int(e.trace.path.size()) - 1);
        pushEdit(e, tr("Remove path point %1").arg(i + 1));
    }
}

void ExerciseEditorPanel::moveSelected(int delta) {
    Exercise e = mExercise;
    const int i = mSelected, j = mSelected + delta;
    if (e.type == ExerciseType::PressTargets && i >= 0 && j >= 0 && j < int(e.pressTargets.targets.size())) {
        std::swap(e.pressTargets.targets[std::size_t(i)], e.pressTargets.targets[std::size_t(j)]);
        mSelected = j;
        pushEdit(e, delta < 0 ? tr("Move target %1 up").arg(i + 1) : tr("Move target %1 down").arg(i + 1));
    } else if (e.type == ExerciseType::Trace && i >= 0 && j >= 0 && j < int(e.trace.path.size())) {
        std::swap(e.trace.path[std::size_t(i)], e.trace.path[std::size_t(j)]);
        mSelected = j;
        pushEdit(e, delta < 0 ? tr("Move path point %1 up").arg(i + 1) : tr("Move path point %1 down").arg(i + 1));
    }
}

// ---- Placing by clicking ----------------------------------------------------------------------------

void ExerciseEditorPanel::setPlacing(Placing placing) {
    // A mode only for its type (and Move only with something selected, or the lump).
    const ExerciseType type = mExercise.type;
    const bool fits = placing == Placing::None ||
                      (placing == Placing::AddTarget && type == ExerciseType::PressTargets) ||
                      (placing == Placing::PlaceInclusion && type == ExerciseType::FindLump) ||
                      (placing == Placing::AddPathPoint && type == ExerciseType::Trace) ||
                      (placing == Placing::MoveSelected && (type == ExerciseType::FindLump || mSelected >= 0));
    if (!fits) placing = Placing::None;
    const bool wasOn = mPlacing != Placing::None;
    mPlacing = placing;
    updatePlacingUi();
    if (wasOn != (placing != Placing::None)) emit placingChanged(placing != Placing::None);
}

void ExerciseEditorPanel::updatePlacingUi() {
    const Guard guard(mShowing);
    mAddTargetButton->setChecked(mPlacing == Placing::AddTarget);
    mMoveTargetButton->setChecked(mPlacing == Placing::MoveSelected && mExercise.type == ExerciseType::PressTargets);
    mPlaceLumpButton->setChecked(mPlacing == Placing::PlaceInclusion ||
                                 (mPlacing == Placing::MoveSelected && mExercise.type == ExerciseType::FindLump));
    mAddPointButton->setChecked(mPlacing == Placing::AddPathPoint);
    mMovePointButton->setChecked(mPlacing == Placing::MoveSelected && mExercise.type == ExerciseType::Trace);
    mStopPlacingAction->setEnabled(mPlacing != Placing::None);
    QString hint;
    switch (mPlacing) {
        case Placing::None: break;
        case Placing::AddTarget: hint = tr("Click the tissue to place a target; Esc to stop."); break;
        case Placing::PlaceInclusion: hint = tr("Click the mesh where the lump's centre goes; Esc cancels."); break;
        case Placing::AddPathPoint: hint = tr("Click the tissue to add path points in order; Esc to stop."); break;
        case Placing::MoveSelected: hint = tr("Click the mesh where the selected point goes; Esc cancels."); break;
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
    if (engineVertex >= mDrawnMesh->vertexCount()) {
        showMessage(tr("Vertex %1 is not on the drawn mesh.").arg(engineVertex), true);
        return std::nullopt;
    }
    // The viewport picks in the engine's order; the file stores the mesh file's own numbering.
    const auto& original = mDrawnMesh->originalIndex();
    return original.empty() ? engineVertex : original[engineVertex];
}

void ExerciseEditorPanel::vertexPicked(VertexId engineVertex) {
    if (mPlacing == Placing::None) return;
    const auto vertex = fileVertex(engineVertex);
    if (!vertex) return;
    const SurfacePoint at{*vertex, glm::vec3(0.0f)};
    Exercise e = mExercise;
    switch (mPlacing) {
        case Placing::None: return;
        case Placing::AddTarget: {
            // The new target takes the last one's window, hold and tolerance: targets of one
            // exercise are usually alike. The first gets a window its tissue reaches at a third to
            // two thirds of the deepest touch (docs/scoring.md, "Reachable targets").
            PressTarget t = e.pressTargets.targets.empty() ? PressTarget{} : e.pressTargets.targets.back();
            if (e.pressTargets.targets.empty())
                if (const auto* forces = touchForces(resolved(e, e.meshPath), *mDrawnMesh, engineVertex))
                    if (const auto window = comfortableWindow(*forces, touchReach())) {
                        t.forceMinN = window->minN;
                        t.forceMaxN = window->maxN;
                    }
            t.at = at;
            e.pressTargets.targets.push_back(t);
            mSelected = int(e.pressTargets.targets.size()) - 1;
            pushEdit(e, tr("Add target %1").arg(mSelected + 1));
            return;
        }
        case Placing::AddPathPoint:
            // A path's first point, with the band as a new exercise has it: the band becomes one
            // the tissue reaches there (as a first target's window).
            if (e.trace.path.empty() && e.trace.forceMinN == TraceDef{}.forceMinN &&
                e.trace.forceMaxN == TraceDef{}.forceMaxN)
                if (const auto* forces = touchForces(resolved(e, e.meshPath), *mDrawnMesh, engineVertex))
                    if (const auto window = comfortableWindow(*forces, touchReach())) {
                        e.trace.forceMinN = window->minN;
                        e.trace.forceMaxN = window->maxN;
                    }
            e.trace.path.push_back(at);
            mSelected = int(e.trace.path.size()) - 1;
            pushEdit(e, tr("Add path point %1").arg(mSelected + 1));
            return;
        case Placing::PlaceInclusion:
            e.findLump.inclusion.centre = at;
            setPlacing(Placing::None);
            pushEdit(e, tr("Place the lump"));
            return;
        case Placing::MoveSelected:
            if (e.type == ExerciseType::FindLump) {
                e.findLump.inclusion.centre = at;
            } else if (e.type == ExerciseType::PressTargets && mSelected >= 0 &&
                       mSelected < int(e.pressTargets.targets.size())) {
                e.pressTargets.targets[std::size_t(mSelected)].at = at;
            } else if (e.type == ExerciseType::Trace && mSelected >= 0 && mSelected < int(e.trace.path.size())) {
                e.trace.path[std::size_t(mSelected)] = at;
            }
            setPlacing(Placing::None);
            pushEdit(e, tr("Move point %1").arg(mSelected + 1));
            return;
    }
}

// ---- Problems, markers, preview ------------------------------------------------------------------

QStringList ExerciseEditorPanel::blockingProblems() const { return mBlocking; }

void ExerciseEditorPanel::refresh() {
    const Exercise& e = mExercise;
    QStringList blocking;
    for (const std::string& problem : messagesOf(validateExercise(e))) blocking << qs(problem);
    if (e.needs)
        for (const std::string& problem : messagesOf(validateLodNeeds(*e.needs))) blocking << qs(problem);
    const QString meshFile = resolved(e, e.meshPath);
    if (!e.meshPath.empty() && meshFile.isEmpty())
        blocking << tr("mesh: '%1' is not found beside the exercise file or under resources/").arg(qs(e.meshPath));
    if (!e.tissuePresetPath.empty() && resolved(e, e.tissuePresetPath).isEmpty())
        blocking << tr("tissue_preset: '%1' is not found beside the exercise file or under resources/")
                        .arg(qs(e.tissuePresetPath));

    // Placement: every point must be a vertex of the exercise's mesh (the drawn one, else its file).
    std::shared_ptr<const ExerciseGeometry> geometry;
    std::string placementError;
    const TissueMesh* mesh = checkMesh(meshFile);
    if (!mesh && !meshFile.isEmpty() && !mCheckMeshError.isEmpty()) blocking << tr("mesh: %1").arg(mCheckMeshError);
    if (mesh) {
        geometry = ExerciseGeometry::build(e, *mesh, placementError);
        // A path of fewer than two points is named by validateExercise already.
        const bool shortPath = e.type == ExerciseType::Trace && e.trace.path.size() < 2;
        if (!geometry && !shortPath) blocking << qs(placementError);
    }
    mWarnings.clear();
    if (geometry && mesh && (e.type == ExerciseType::PressTargets || e.type == ExerciseType::Trace))
        for (const QString& warning : reachWarnings(*geometry, meshFile, *mesh)) {
            // A target with a problem (a window upside down) is named by the problem alone.
            const QString target = problemKey(warning).section(QLatin1Char('.'), 0, 1);
            const bool named = std::any_of(blocking.begin(), blocking.end(),
                                           [&](const QString& p) { return problemKey(p).startsWith(target); });
            if (!named) mWarnings << warning;
        }
    mBlocking = blocking;
    mProblems = blocking;
    if (!meshFile.isEmpty() && !drawnMeshMatches()) {
        const QString drawn = mDrawnMesh ? QFileInfo(mDrawnMeshPath).fileName() : tr("no mesh");
        const bool otherUnit = mDrawnMesh && QFileInfo(mDrawnMeshPath).canonicalFilePath() ==
                                                 QFileInfo(meshFile).canonicalFilePath();
        if (otherUnit)
            mProblems << tr("mesh_unit: the viewport shows %1 read in %2, this exercise reads it in %3: press Show "
                            "this mesh to place points by clicking")
                             .arg(drawn, qs(mDrawnMesh->report().unit.description()),
                                  qs(mExercise.meshUnit.description()));
        else
            mProblems << tr("mesh: the viewport shows %1, not this exercise's %2: press Show this mesh to place points "
                            "by clicking")
                             .arg(drawn, QFileInfo(meshFile).fileName());
    }

    // The markers, on the drawn mesh only (picks and markers are in its numbering).
    ExerciseMarkers markers;
    if (drawnMeshMatches()) {
        if (geometry) {
            markers = exerciseMarkers(*geometry, MarkerAudience::Instructor, nullptr,
                                      e.type == ExerciseType::FindLump ? -1 : mSelected);
        } else if (e.type == ExerciseType::Trace) {
            // A path being started (one point, or all on one vertex) has no geometry yet: its
            // points are still shown, so the instructor sees where the next click continues.
            for (std::size_t i = 0; i < e.trace.path.size(); ++i) {
                const VertexId v = ExerciseGeometry::snap(e.trace.path[i], *mDrawnMesh);
                if (v == kNoVertex) continue;
                ExerciseMarker m;
                m.kind = ExerciseMarker::Kind::PathPoint;
                m.positionMm = mDrawnMesh->restPositionsMm()[v];
                m.normal = mDrawnMesh->restNormals().size() > v ? mDrawnMesh->restNormals()[v] : glm::vec3(0.0f);
                m.label = i == 0 ? QStringLiteral("start") : QString();
                m.selected = int(i) == mSelected;
                markers.markers.push_back(m);
                markers.pathMm.push_back(m.positionMm);
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
    const Exercise& e = mExercise;
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
                                                       {mLumpRadiusSpin, "find_lump.inclusion.radius_mm"},
                                                       {mLumpStiffnessSpin, "find_lump.inclusion.stiffness_factor"},
                                                       {mTraceMinSpin, "trace.force_min_n"},
                                                       {mTraceMaxSpin, "trace.force_max_n"},
                                                       {mTraceToleranceSpin, "trace.tolerance_mm"},
                                                       {mNeedsErrorSpin, "needs.max_error"},
                                                       {mNeedsBudgetSpin, "needs.budget_us"}};
    for (const auto& [widget, key] : fields) {
        const bool invalid = keys.contains(QLatin1String(key));
        if (widget->property("invalid").toBool() != invalid) {
            widget->setProperty("invalid", invalid);
            widget->style()->unpolish(widget);
            widget->style()->polish(widget);
        }
    }
    for (int r = 0; r < mTargetTable->rowCount(); ++r)
        for (int c = kTargetVertex; c < kTargetColumns; ++c) {
            const QString key = QStringLiteral("press_targets.targets[%1]").arg(r);
            const QString cellKey = key + QLatin1Char('.') + QLatin1String(kTargetKeys[c]);
            const bool invalid = keys.contains(cellKey) || (c == kTargetVertex && keys.contains(key));
            const QVariant background = invalid                    ? QVariant(QBrush(kInvalidCell))
                                        : warned.contains(cellKey) ? QVariant(QBrush(kWarningCell))
                                                                   : QVariant();
            if (QTableWidgetItem* it = mTargetTable->item(r, c); it && it->data(Qt::BackgroundRole) != background)
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
    for (QWidget* w : {static_cast<QWidget*>(mRemoveTargetButton), static_cast<QWidget*>(mMoveTargetButton),
                       static_cast<QWidget*>(mRemovePointButton), static_cast<QWidget*>(mMovePointButton)})
        w->setEnabled(hasSelection);
    const int count = e.type == ExerciseType::PressTargets ? int(e.pressTargets.targets.size())
                                                           : int(e.trace.path.size());
    for (QToolButton* up : {mTargetUpButton, mPointUpButton}) up->setEnabled(mSelected > 0);
    for (QToolButton* down : {mTargetDownButton, mPointDownButton})
        down->setEnabled(hasSelection && mSelected + 1 < count);
    mPreviewAction->setEnabled(mBlocking.isEmpty());
    mPreviewButton->setEnabled(mBlocking.isEmpty());
    mShowMeshButton->setEnabled(!meshFile.isEmpty() && !drawnMeshMatches());
    mMeshStateLabel->setText(meshFile.isEmpty()   ? tr("Not found.")
                             : drawnMeshMatches() ? tr("Drawn in the viewport.")
                                                  : tr("Not drawn in the viewport."));
}

TouchReach ExerciseEditorPanel::touchReach() { return TouchReach{Viewport::kMaxTouchDepthMm, Viewport::kTouchDepthStepMm}; }

const std::vector<double>* ExerciseEditorPanel::touchForces(const QString& meshFile, const TissueMesh& mesh,
                                                            VertexId vertex) {
    const QString presetFile = resolved(mExercise, mExercise.tissuePresetPath);
    if (meshFile.isEmpty() || presetFile.isEmpty()) return nullptr;  // a problem says so already
    const auto stamp = [](const QString& file) { return QFileInfo(file).lastModified().toString(Qt::ISODateWithMs); };
    const QString key = meshFile + QLatin1Char('\n') + stamp(meshFile) + QLatin1Char('\n') +
                        qs(mExercise.meshUnit.text()) + QLatin1Char('\n') + presetFile + QLatin1Char('\n') +
                        stamp(presetFile);
    if (key != mProbeKey) {
        mProbeKey = key;
        mProbe.reset();
        mProbeForces.clear();
        mReachError.clear();
        const PresetLoadResult loaded = guardedLoad(ss(presetFile), [&] { return loadTissuePreset(ss(presetFile)); });
        std::string error = loaded.errors.empty() ? std::string("not a tissue preset") : loaded.errors.front();
        // Press targets have no physics of their own: the scene is the tissue's as it is.
        if (loaded.preset) mProbe = TouchForceProbe::create(mesh, *loaded.preset, nullptr, touchReach(), error);
        if (!mProbe) mReachError = qs(error);
    }
    if (!mProbe) return nullptr;
    auto it = mProbeForces.find(vertex);
    if (it == mProbeForces.end()) it = mProbeForces.insert(vertex, mProbe->forcesN(vertex));
    return it->empty() ? nullptr : &*it;
}

QStringList ExerciseEditorPanel::reachWarnings(const ExerciseGeometry& geometry, const QString& meshFile,
                                               const TissueMesh& mesh) {
    QStringList out;
    const TouchReach touch = touchReach();
    const QLocale l = locale();
    const auto n = [&l](double v) { return l.toString(v, 'g', 3); };
    if (geometry.exercise().type == ExerciseType::Trace) {
        // The band at every path point, as a target's window (pressed, not slid: a slide at the
        // same depth renders about the same force, plus friction).
        PressTarget band;
        band.forceMinN = geometry.exercise().trace.forceMinN;
        band.forceMaxN = geometry.exercise().trace.forceMaxN;
        QStringList tooSoft, between;
        double leastN = 0.0, deepestMm = 0.0;
        std::optional<ForceWindow> suggested;
        const auto& vertices = geometry.pathVertices();
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            const std::vector<double>* forces = touchForces(meshFile, mesh, vertices[i]);
            if (!forces) {
                if (!mReachError.isEmpty())
                    out << tr("tissue_preset: whether the band can be reached with the mouse is not known: %1").arg(mReachError);
                return out;
            }
            const TargetReach reach = judgeTarget(band, *forces, touch);
            if (reach.reachable) continue;
            if (reach.belowForceN) {
                between << QString::number(i + 1);
                continue;
            }
            if (tooSoft.isEmpty() || reach.maxForceN < leastN) {
                leastN = reach.maxForceN;
                suggested = comfortableWindow(*forces, touch);
            }
            deepestMm = reach.maxDepthMm;
            tooSoft << QString::number(i + 1);
        }
        if (!tooSoft.isEmpty()) {
            const QString instead = suggested ? tr(" (%1–%2 N is met between a third and two thirds of that depth)")
                                                    .arg(n(suggested->minN), n(suggested->maxN))
                                              : QString();
            out << tr("trace.force_min_n: the band cannot be reached with the mouse at path point %1: pressing %2 mm "
                      "deep (the deepest) gives as little as %3 N there, below the band's %4 N. Lower the band to at "
                      "most %3 N%5, or choose a stiffer tissue preset.")
                       .arg(tooSoft.join(QStringLiteral(", ")), n(deepestMm), n(leastN), n(band.forceMinN), instead);
        } else if (!between.isEmpty()) {
            out << tr("trace.force_min_n: the band %1–%2 N lies between the forces of two turns of the wheel at path "
                      "point %3: widen it.")
                       .arg(n(band.forceMinN), n(band.forceMaxN), between.join(QStringLiteral(", ")));
        }
        return out;
    }
    for (std::size_t i = 0; i < geometry.targets().size(); ++i) {
        const ResolvedTarget& target = geometry.targets()[i];
        const std::vector<double>* forces = touchForces(meshFile, mesh, target.vertex);
        if (!forces) {
            if (!mReachError.isEmpty())
                out << tr("tissue_preset: whether the targets can be reached with the mouse is not known: %1").arg(mReachError);
            break;
        }
        const TargetReach reach = judgeTarget(target.def, *forces, touch);
        if (reach.reachable) continue;
        const QString key = QStringLiteral("press_targets.targets[%1].force_min_n").arg(i);
        if (reach.belowForceN) {
            out << tr("%1: target %2 cannot be held with the mouse: its window %3–%4 N lies between %5 N at %6 mm and "
                      "%7 N at %8 mm deep (one turn of the wheel apart). Widen the window to take in one of them.")
                       .arg(key).arg(i + 1)
                       .arg(n(target.def.forceMinN), n(target.def.forceMaxN), n(*reach.belowForceN), n(*reach.belowDepthMm),
                            n(*reach.aboveForceN), n(*reach.aboveDepthMm));
            continue;
        }
        const auto suggested = comfortableWindow(*forces, touch);
        const QString instead = suggested ? tr(" (%1–%2 N is met between a third and two thirds of that depth)")
                                                .arg(n(suggested->minN), n(suggested->maxN))
                                          : QString();
        out << tr("%1: target %2 cannot be reached with the mouse: pressing %3 mm deep (the deepest) gives %4 N, below "
                  "its window's %5 N. Lower the window to at most %4 N%6, or choose a stiffer tissue preset.")
                   .arg(key).arg(i + 1)
                   .arg(n(reach.maxDepthMm), n(reach.maxForceN), n(target.def.forceMinN), instead);
    }
    return out;
}

void ExerciseEditorPanel::updateTitle() {
    const QString file = mPath.isEmpty() ? tr("not saved yet") : QFileInfo(mPath).fileName();
    mTitleLabel->setText(tr("%1 — %2%3").arg(qs(mExercise.name).isEmpty() ? tr("(unnamed)") : qs(mExercise.name), file,
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
    emit previewRequested(mExercise);
    return true;
}

}  // namespace palpate
