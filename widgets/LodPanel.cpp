#include "widgets/LodPanel.h"

#include "results/HandOff.h"

#include "engine/lod/LevelCache.h"
#include "engine/lod/MeshLevels.h"

#include <QAbstractItemView>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QStyle>
#include <QTableWidget>
#include <QThread>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <exception>
#include <set>
#include <stdexcept>

namespace palpate {

namespace {

constexpr int kProgressSteps = 1000;
/// The progress bar's share of making (or reading) the levels; measuring takes the rest. Reading
/// from the cache is quick, generating about as long as measuring on the meshes we ship.
constexpr double kLevelsShare = 0.3;

/// Whether a candidate meets each target is shown in its error and tick cells (a mark and the
/// colour) rather than in columns of their own: eight columns do not fit a dock 380 px wide.
enum Column { kLevelColumn, kVerticesColumn, kRingsColumn, kErrorColumn, kTickColumn, kVerdictColumn, kColumnCount };

const QColor kChosenBackground(0xd4, 0xf0, 0xd8);
const QColor kClosestBackground(0xff, 0xec, 0xb8);
const QColor kYesColour(0x1b, 0x7a, 0x2e);
const QColor kNoColour(0xc6, 0x28, 0x28);

/// Invalid fields are framed red, as in the Parameters panel.
const char* const kStyleSheet = R"(
QAbstractSpinBox[invalid="true"] { border: 2px solid #d32f2f; border-radius: 3px; background-color: #fff0f0; }
QAbstractSpinBox[invalid="true"]::up-button, QAbstractSpinBox[invalid="true"]::down-button { width: 16px; }
QLabel#lodNeedsProblemLabel { color: #c62828; }
)";

void markInvalid(QWidget* field, bool invalid) {
    if (field->property("invalid").toBool() == invalid) return;
    field->setProperty("invalid", invalid);
    field->style()->unpolish(field);
    field->style()->polish(field);
}

bool sameNeeds(const LodNeeds& a, const LodNeeds& b) {
    return a.maxErrorFraction == b.maxErrorFraction && a.budgetUs == b.budgetUs;
}

}  // namespace

/// What the worker hands back (by a queued call, so it is read on the panel's thread only).
struct LodPanel::RunResult {
    unsigned generation = 0;
    QString meshPath;
    QString error;  ///< "" or why no plan could be made (the engine's words)
    bool fromCache = false;
    QString cacheWhy;  ///< when generated: why the cache was not used
    QString cacheDir;
    QString writeError;
    QStringList notes;
    std::vector<std::size_t> levelVertices;
    bool levelsCancelled = false;
    std::vector<LodCandidate> candidates;
    std::size_t plannedCandidates = 0;
    bool measureCancelled = false;
    std::optional<StiffeningCalibration> stiffening;  ///< the hyperelastic punch, knots fitted
    QString stiffeningError;
};

QString LodPanel::ringsText(int rings) {
    // No English plural translation is loaded, so the singular has its own string.
    return rings == 1 ? tr("1 ring") : tr("%1 rings").arg(rings);
}

LodNeeds LodPanel::defaultNeeds() { return LodNeeds{}; }

LodMeasureDef LodPanel::defaultMeasureDefinition() {
    LodMeasureDef def;
    // The CLI's full run times each candidate as Table 1 does (median of 5 runs of 20 ms); the
    // planner uses the tick only for feasibility and the structural order for the choice
    // (docs/lod.md §5), so a shorter median is enough here and keeps the wait to seconds.
    def.ringCounts = {1, 2, 3, 4, 6};
    def.timing = {3, 5.0};
    return def;
}

LodPanel::LodPanel(QWidget* parent) : QWidget(parent), mNeeds(defaultNeeds()), mNeedsAsSet(defaultNeeds()),
                                      mMeasureDef(defaultMeasureDefinition()) {
    setObjectName(QStringLiteral("lodPanel"));
    setStyleSheet(QLatin1String(kStyleSheet));

    // Targets.
    mNeedsSourceLabel = new QLabel(this);
    mNeedsSourceLabel->setObjectName(QStringLiteral("lodNeedsSourceLabel"));
    mNeedsSourceLabel->setWordWrap(true);
    mErrorSpin = new QDoubleSpinBox(this);
    mErrorSpin->setObjectName(QStringLiteral("lodMaxErrorSpin"));
    // Wide ranges on purpose: a value outside (0, limit] is shown and named, not silently clamped.
    mErrorSpin->setDecimals(2);
    mErrorSpin->setRange(-1000.0, 100000.0);
    mErrorSpin->setSingleStep(1.0);
    mErrorSpin->setAlignment(Qt::AlignRight);
    mErrorSpin->setAccelerated(true);
    mBudgetSpin = new QDoubleSpinBox(this);
    mBudgetSpin->setObjectName(QStringLiteral("lodBudgetSpin"));
    mBudgetSpin->setDecimals(3);
    mBudgetSpin->setRange(-1.0e6, 1.0e7);
    mBudgetSpin->setSingleStep(10.0);
    mBudgetSpin->setAlignment(Qt::AlignRight);
    mBudgetSpin->setAccelerated(true);
    mErrorLabel = new QLabel(this);
    mErrorLabel->setBuddy(mErrorSpin);
    mBudgetLabel = new QLabel(this);
    mBudgetLabel->setBuddy(mBudgetSpin);
    mNeedsProblemLabel = new QLabel(this);
    mNeedsProblemLabel->setObjectName(QStringLiteral("lodNeedsProblemLabel"));
    mNeedsProblemLabel->setWordWrap(true);
    mNeedsProblemLabel->setVisible(false);
    mPlanButton = new QPushButton(this);
    mPlanButton->setObjectName(QStringLiteral("lodPlanButton"));
    mStoreButton = new QPushButton(this);
    mStoreButton->setObjectName(QStringLiteral("lodStoreNeedsButton"));

    // Progress.
    mProgress = new QProgressBar(this);
    mProgress->setObjectName(QStringLiteral("lodProgress"));
    mProgress->setRange(0, kProgressSteps);
    mProgress->setValue(0);
    mCancelButton = new QPushButton(this);
    mCancelButton->setObjectName(QStringLiteral("lodCancelButton"));
    mStatusLabel = new QLabel(this);
    mStatusLabel->setObjectName(QStringLiteral("lodStatusLabel"));
    mStatusLabel->setWordWrap(true);
    mStatusLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Engine messages hold paths without spaces: let them wrap anywhere rather than widen the dock.
    mStatusLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);

    // Candidates.
    mLevelsLabel = new QLabel(this);
    mLevelsLabel->setObjectName(QStringLiteral("lodLevelsLabel"));
    mLevelsLabel->setWordWrap(true);
    mLevelsLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mTable = new QTableWidget(0, kColumnCount, this);
    mTable->setObjectName(QStringLiteral("lodCandidateTable"));
    mTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    mTable->setSelectionMode(QAbstractItemView::SingleSelection);
    mTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    mTable->setAlternatingRowColors(false);  // the chosen and closest rows have their own colour
    mTable->verticalHeader()->setVisible(false);
    mTable->verticalHeader()->setDefaultSectionSize(mTable->fontMetrics().height() + 6);
    mTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // The verdict takes what is left: its words are short, and a dock 380 px wide has no room to spare.
    mTable->horizontalHeader()->setSectionResizeMode(kVerdictColumn, QHeaderView::Stretch);
    mTable->horizontalHeader()->setMinimumSectionSize(24);
    mTable->setHorizontalScrollMode(QAbstractItemView::ScrollPerPixel);
    mTable->setWordWrap(false);
    mTable->setMinimumHeight(8 * (mTable->fontMetrics().height() + 6));
    mSummaryLabel = new QLabel(this);
    mSummaryLabel->setObjectName(QStringLiteral("lodSummaryLabel"));
    mSummaryLabel->setWordWrap(true);
    mSummaryLabel->setTextFormat(Qt::RichText);
    mReasonLabel = new QLabel(this);
    mReasonLabel->setObjectName(QStringLiteral("lodReasonLabel"));
    mReasonLabel->setWordWrap(true);
    mReasonLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mReasonLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mUseChosenButton = new QPushButton(this);
    mUseChosenButton->setObjectName(QStringLiteral("lodUseChosenButton"));
    mUseSelectedButton = new QPushButton(this);
    mUseSelectedButton->setObjectName(QStringLiteral("lodUseSelectedButton"));
    mUndoUseButton = new QPushButton(this);
    mUndoUseButton->setObjectName(QStringLiteral("lodUndoUseButton"));
    mUndoUseButton->setEnabled(false);
    mUsedLabel = new QLabel(this);
    mUsedLabel->setObjectName(QStringLiteral("lodUsedLabel"));
    mUsedLabel->setWordWrap(true);
    mUsedLabel->setVisible(false);

    layOutWidgets();

    connect(mErrorSpin, &QDoubleSpinBox::valueChanged, this, &LodPanel::onNeedsEdited);
    connect(mBudgetSpin, &QDoubleSpinBox::valueChanged, this, &LodPanel::onNeedsEdited);
    connect(mPlanButton, &QPushButton::clicked, this, [this] { plan(); });
    connect(mCancelButton, &QPushButton::clicked, this, &LodPanel::cancel);
    connect(mStoreButton, &QPushButton::clicked, this, &LodPanel::storeNeeds);
    connect(mUseChosenButton, &QPushButton::clicked, this, &LodPanel::useChosen);
    connect(mUseSelectedButton, &QPushButton::clicked, this, &LodPanel::useSelected);
    connect(mUndoUseButton, &QPushButton::clicked, this, &LodPanel::undoUseRequested);
    connect(mTable, &QTableWidget::itemSelectionChanged, this, [this] {
        updateVerdicts();
        updateSummary();
        updateButtons();
    });

    setNeedsFields(mNeeds);
    retranslateUi();
    onNeedsEdited();
}

void LodPanel::layOutWidgets() {
    auto* needsForm = new QFormLayout;
    needsForm->addRow(mErrorLabel, mErrorSpin);
    needsForm->addRow(mBudgetLabel, mBudgetSpin);
    auto* needsButtons = new QHBoxLayout;
    needsButtons->addWidget(mPlanButton);
    needsButtons->addWidget(mStoreButton);
    needsButtons->addStretch(1);
    mTargetsBox = new QGroupBox(this);
    auto* targets = new QVBoxLayout(mTargetsBox);
    targets->addWidget(mNeedsSourceLabel);
    targets->addLayout(needsForm);
    targets->addWidget(mNeedsProblemLabel);
    targets->addLayout(needsButtons);

    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(mProgress, 1);
    progressRow->addWidget(mCancelButton);

    auto* useButtons = new QHBoxLayout;
    useButtons->addWidget(mUseChosenButton);
    useButtons->addWidget(mUseSelectedButton);
    useButtons->addWidget(mUndoUseButton);
    useButtons->addStretch(1);
    mCandidatesBox = new QGroupBox(this);
    auto* candidatesLayout = new QVBoxLayout(mCandidatesBox);
    candidatesLayout->setContentsMargins(6, 6, 6, 6);  // the table needs the width
    candidatesLayout->addWidget(mLevelsLabel);
    candidatesLayout->addWidget(mTable, 1);
    candidatesLayout->addWidget(mSummaryLabel);
    candidatesLayout->addWidget(mReasonLabel);
    candidatesLayout->addLayout(useButtons);
    candidatesLayout->addWidget(mUsedLabel);

    // The content scrolls when the dock is shorter than the fields and a few rows of the table.
    auto* content = new QWidget;
    content->setObjectName(QStringLiteral("lodPanelContent"));
    auto* layout = new QVBoxLayout(content);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(mTargetsBox);
    layout->addLayout(progressRow);
    layout->addWidget(mStatusLabel);
    layout->addWidget(mCandidatesBox, 1);
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("lodScrollArea"));
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(content);
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(scroll);
}

LodPanel::~LodPanel() {
    if (mThread) {
        mCancel.store(true);
        mThread->wait();  // its queued calls to this panel are dropped with the panel
        delete mThread;
        mThread = nullptr;
    }
}

void LodPanel::retranslateUi() {
    mTargetsBox->setTitle(tr("Targets"));
    mCandidatesBox->setTitle(tr("Levels and rings"));
    mErrorLabel->setText(tr("Max &error:"));
    mErrorSpin->setSuffix(tr(" %"));
    mErrorSpin->setToolTip(tr("The displacement error allowed: RMS over the loaded region divided by the peak "
                              "displacement, measured on the displayed (source) surface. 10 % is 0.1."));
    mBudgetLabel->setText(tr("Tick &budget:"));
    mBudgetSpin->setSuffix(tr(" µs"));
    mBudgetSpin->setToolTip(tr("The time one haptic tick may take on this machine, in microseconds "
                               "(a 1 kHz loop has 1000 µs per tick for everything)."));
    mPlanButton->setText(tr("&Plan"));
    mPlanButton->setToolTip(tr("Make (or read from the cache next to the mesh) the coarser levels, measure every "
                               "level and ring count on this machine and choose."));
    mStoreButton->setText(tr("&Store targets in preset"));
    mStoreButton->setToolTip(tr("Write these targets into the current tissue preset as its \"needs\"."));
    mCancelButton->setText(tr("&Cancel"));
    mCancelButton->setToolTip(tr("Stop after the candidate being measured; what was measured so far is planned."));
    mUseChosenButton->setText(tr("&Use chosen"));
    mUseChosenButton->setToolTip(tr("Load the planner's choice: its level's mesh and ring count."));
    mUseSelectedButton->setText(tr("Use selected (&override)"));
    mUndoUseButton->setText(tr("U&ndo use"));
    mUndoUseButton->setToolTip(tr("Back to the mesh, rings and tissue from before the first Use."));
    mUseSelectedButton->setToolTip(tr("Load the row selected in the table instead of the planner's choice."));
    mTable->setAccessibleName(tr("Candidates"));
    mTable->setHorizontalHeaderLabels(
        {tr("Level"), tr("Vertices"), tr("Rings"), tr("Error %"), tr("Tick µs"), tr("Verdict")});
    const QString headerTips[kColumnCount] = {
        tr("0 is the mesh itself; each further level keeps about half the vertices of the one before."),
        tr("Vertices of the level's mesh."),
        tr("Rings of neighbours the slope-ring model moves around the touched vertex."),
        tr("Displacement error against the flat-punch reference on the displayed surface (RMS / peak, in %); "
           "\u2713 within the max error, \u2717 above it."),
        tr("Median time of one haptic tick on this machine, in microseconds; \u2713 within the budget, \u2717 over it."),
        tr("The planner's choice, the closest when nothing fits, or your override.")};
    for (int c = 0; c < kColumnCount; ++c)
        if (QTableWidgetItem* header = mTable->horizontalHeaderItem(c)) header->setToolTip(headerTips[c]);
    updateNeedsSource();
    onNeedsEdited();  // the problem texts and the table's words are translated too
    if (mStatusLabel->text().isEmpty()) setStatus(QString());
}

void LodPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslateUi();
    QWidget::changeEvent(event);
}

// ---------------------------------------------------------------------------------------------
// Scene and needs

void LodPanel::setScene(const QString& meshPath, std::shared_ptr<const TissueMesh> mesh, std::optional<LodNeeds> needs,
                        const QString& needsSource) {
    const bool sameMesh = meshPath == mMeshPath && mesh == mMesh;
    if (!sameMesh) {
        // Another mesh: the table, the plan and any run for the old mesh are of no use any more.
        ++mSceneGeneration;
        if (mThread) mCancel.store(true);
        mPlanPending = false;
        mMeshPath = meshPath;
        mMesh = std::move(mesh);
        mCandidates.clear();
        mStiffeningReference.reset();
        mCandidatesMeshPath.clear();
        mLevelsText.clear();
        mLevelsProblem = false;
        mLevelsFromCache = false;
        mLastCancelled = false;
        mProgress->setValue(0);
        fillTable();
        setStatus(QString());
    }
    mSceneNeeds = needs;
    mSceneNeedsSource = needsSource;
    setNeedsFields(needs.value_or(defaultNeeds()));
    mNeedsAsSet = mNeeds;
    onNeedsEdited();
}

void LodPanel::setNeeds(const LodNeeds& needs) {
    setNeedsFields(needs);
    onNeedsEdited();
}

void LodPanel::setNeedsFields(const LodNeeds& needs) {
    mUpdatingFields = true;
    mErrorSpin->setValue(needs.maxErrorFraction * 100.0);
    mBudgetSpin->setValue(needs.budgetUs);
    mUpdatingFields = false;
    mNeeds = {mErrorSpin->value() / 100.0, mBudgetSpin->value()};
}

void LodPanel::setMeasureDefinition(const LodMeasureDef& def) { mMeasureDef = def; }

void LodPanel::setToolContact(const ToolContact& contact) {
    const bool same = sameToolContact(contact, mMeasureDef.contact);
    mMeasureDef.contact = contact;
    if (!same && mStiffeningReference) {
        mStiffeningReference.reset();  // solved for another tissue
        replan();
    }
}

void LodPanel::setSceneDemands(std::vector<ExerciseDemand> demands) {
    mDemands = std::move(demands);
    replan();
}

std::vector<SceneDepth> LodPanel::sceneDepths() const {
    std::vector<SceneDepth> depths;
    const double m1 = punchFirstSlopeMmPerN(mMeasureDef.contact);
    for (const ExerciseDemand& d : mDemands)
        depths.push_back({d.what, d.depthMm > 0.0 || !mStiffeningReference
                                      ? d.depthMm
                                      : curveDepthAtForceMm(mStiffeningReference->curve, d.forceN, m1)});
    if (depths.empty()) depths.push_back({tr("the plan's press").toStdString(), mMeasureDef.press.toolDepthMm});
    return depths;
}

QStringList LodPanel::needsProblems() const {
    // validateLodNeeds is the one check (files, the CLI and here agree); the words are the panel's,
    // naming the field as it is labelled and in its unit (%, µs).
    QStringList problems;
    const QLocale locale;
    for (const std::string& problem : messagesOf(validateLodNeeds(mNeeds, ""))) {
        if (problem.rfind("max_error", 0) == 0) {
            const double percent = mNeeds.maxErrorFraction * 100.0;
            problems << (percent > 0.0 && std::isfinite(percent)
                             ? tr("Max error: %1 % is absurd (at most %2 %).")
                                   .arg(locale.toString(percent, 'g', 6), locale.toString(kMaxLodErrorFraction * 100.0, 'g', 6))
                             : tr("Max error: must be above 0 % (it is %1 %).").arg(locale.toString(percent, 'g', 6)));
        } else if (problem.rfind("budget_us", 0) == 0) {
            problems << (mNeeds.budgetUs > 0.0 && std::isfinite(mNeeds.budgetUs)
                             ? tr("Tick budget: %1 µs is absurd (at most %2 µs).")
                                   .arg(locale.toString(mNeeds.budgetUs, 'g', 7), locale.toString(kMaxLodBudgetUs, 'g', 7))
                             : tr("Tick budget: must be above 0 µs (it is %1 µs).")
                                   .arg(locale.toString(mNeeds.budgetUs, 'g', 7)));
        } else {
            problems << QString::fromStdString(problem);
        }
    }
    return problems;
}

void LodPanel::onNeedsEdited() {
    if (mUpdatingFields) return;
    mNeeds = {mErrorSpin->value() / 100.0, mBudgetSpin->value()};
    const QStringList problems = needsProblems();
    bool errorBad = false, budgetBad = false;
    for (const std::string& problem : messagesOf(validateLodNeeds(mNeeds, ""))) {
        errorBad = errorBad || problem.rfind("max_error", 0) == 0;
        budgetBad = budgetBad || problem.rfind("budget_us", 0) == 0;
    }
    markInvalid(mErrorSpin, errorBad);
    markInvalid(mBudgetSpin, budgetBad);
    mNeedsProblemLabel->setText(problems.join(QLatin1Char('\n')));
    mNeedsProblemLabel->setVisible(!problems.isEmpty());
    updateNeedsSource();
    replan();
}

void LodPanel::updateNeedsSource() {
    QString text;
    if (mMeshPath.isEmpty())
        text = tr("No scene yet.");
    else if (!sameNeeds(mNeeds, mNeedsAsSet))
        text = mSceneNeeds ? tr("Targets edited here (the scene's were %1 % and %2 µs). Store them in the preset to "
                                "keep them.")
                                 .arg(QLocale().toString(mSceneNeeds->maxErrorFraction * 100.0, 'g', 6),
                                      QLocale().toString(mSceneNeeds->budgetUs, 'g', 7))
                           : tr("Targets edited here. Store them in the preset to keep them.");
    else if (mSceneNeeds)
        text = mSceneNeedsSource.isEmpty() ? tr("Targets from the scene.") : tr("Targets from %1.").arg(mSceneNeedsSource);
    else
        text = tr("The scene states no targets: these are the panel's defaults.");
    mNeedsSourceLabel->setText(text);
}

// ---------------------------------------------------------------------------------------------
// The run

namespace {

/// The hyperelastic punch of `def`'s contact as deep as `demands` ask, its knots fitted: the
/// reference for linear or stiffening tissue (docs/lod.md, "Linear or nonlinear"). Throws what the
/// calibration throws.
StiffeningCalibration pressHyperelasticReference(const LodMeasureDef& def, const std::vector<ExerciseDemand>& demands) {
    StiffeningCalibrationDef stiff;
    stiff.material = hyperelasticMaterialOf(def.contact);
    stiff.toolRadiusMm = def.contact.toolRadiusMm;
    // Coarser than the CLI's (a/h = 4): a plan in the window stays seconds; the
    // ratio cancels most of the mesh's error either way.
    stiff.aOverH = 3;
    stiff.maxStepOverRadius = 0.05;
    const double m1 = punchFirstSlopeMmPerN(def.contact);
    setStiffeningDepths(stiff, stiffeningReferenceDepthOverRadius(deepestDemandMm(demands, m1, def.press.toolDepthMm),
                                                                  stiff.toolRadiusMm));
    return knotsFromCurve(calibrateStiffening(stiff).curve, m1);
}

}  // namespace

QString LodPanel::levelStageText(const std::string& stage, std::size_t coarse) {
    // The engine's stage words are mapped to the panel's; anything else is shown as is.
    const QString s = QString::fromStdString(stage);
    if (s == QLatin1String("decimating"))
        return coarse == 1 ? tr("Generating 1 coarser level: decimating")
                           : tr("Generating %1 coarser levels: decimating").arg(coarse);
    if (s.startsWith(QLatin1String("mapping level ")))
        return tr("Generating levels %1/%2: mapping to the mesh").arg(s.mid(14)).arg(coarse);
    if (s.startsWith(QLatin1String("reading level "))) return tr("Reading cached level %1").arg(s.mid(14));
    if (s == QLatin1String("done")) return tr("Levels ready");
    return s;
}

bool LodPanel::plan() {
    if (mThread) {
        // A run for an older scene is still winding down: start as soon as it has.
        if (mRunGeneration != mSceneGeneration) {
            mPlanPending = true;
            return true;
        }
        return false;
    }
    if (mMeshPath.isEmpty()) {
        setStatus(tr("No mesh file: the levels are cached next to the scene's mesh file."), true);
        return false;
    }
    if (const QStringList problems = needsProblems(); !problems.isEmpty()) {
        setStatus(tr("Fix the targets first: %1").arg(problems.join(QLatin1Char(' '))), true);
        return false;
    }
    if (const std::string e = joinedMessages(validateLodMeasureDef(mMeasureDef)); !e.empty()) {
        const QString error = QString::fromStdString(e);
        setStatus(tr("Cannot measure: %1").arg(error), true);
        emit planFailed(error);
        return false;
    }

    mCancel.store(false);
    mPlanPending = false;
    mRunGeneration = mSceneGeneration;
    const unsigned generation = mRunGeneration;
    const std::string path = mMeshPath.toStdString();
    const std::shared_ptr<const TissueMesh> mesh = mMesh;
    const LodMeasureDef def = mMeasureDef;
    const std::atomic<bool>* cancelFlag = &mCancel;

    const std::vector<ExerciseDemand> demands = mDemands;
    mThread = QThread::create([this, generation, path, mesh, def, cancelFlag, demands] {
        auto result = std::make_shared<RunResult>();
        result->generation = generation;
        result->meshPath = QString::fromStdString(path);
        // Progress goes to the panel's thread as queued calls; the decimater reports often, so only
        // a new text or a step of 0.5 % is posted (the event queue stays short).
        int lastStep = -1;
        QString lastText;
        auto post = [&](double fraction, const QString& text) {
            const int step = int(std::clamp(fraction, 0.0, 1.0) * kProgressSteps + 0.5);
            if (text == lastText && step - lastStep < kProgressSteps / 200) return;
            lastStep = step;
            lastText = text;
            handOffTo(this,
                      [this, generation, step, text] { onProgress(generation, double(step) / kProgressSteps, text); });
        };
        try {
            std::shared_ptr<const TissueMesh> source = mesh;
            if (!source) {
                post(0.0, tr("Loading the mesh…"));
                auto loaded = TissueMesh::load(path);
                if (!loaded.mesh) throw std::runtime_error(loaded.error());
                source = std::make_shared<const TissueMesh>(std::move(*loaded.mesh));
            }
            const LevelDef options;
            const std::size_t coarse = levelTargets(source->vertexCount(), options).size();
            post(0.0, tr("Looking for cached levels…"));
            LevelCacheResult levels = loadOrGenerateLevels(
                path, *source, options,
                [&](double f, const std::string& stage) { post(kLevelsShare * f, levelStageText(stage, coarse)); },
                cancelFlag, true);
            result->fromCache = levels.fromCache;
            result->cacheDir = QString::fromStdString(levelCacheDir(path));
            // "generated (why)": the why is what the panel shows; the folder by its name only.
            QString why = QString::fromStdString(levels.cacheStatus);
            if (why.startsWith(QLatin1String("generated (")) && why.endsWith(QLatin1Char(')'))) why = why.mid(11).chopped(1);
            why.replace(result->cacheDir, QFileInfo(result->cacheDir).fileName());
            result->cacheWhy = why;
            result->writeError = QString::fromStdString(levels.writeError);
            for (const std::string& note : levels.levels.notes) result->notes << QString::fromStdString(note);
            for (const MeshLevel& level : levels.levels.levels) result->levelVertices.push_back(level.mesh.vertexCount());
            result->levelsCancelled = levels.levels.cancelled || cancelFlag->load();
            if (!result->levelsCancelled) {
                // Which candidate comes next (the engine reports after each one): level by level,
                // ring counts ascending, as measureLodCandidates measures them.
                const std::set<int> ringSet(def.ringCounts.begin(), def.ringCounts.end());
                const std::vector<int> rings(ringSet.begin(), ringSet.end());
                const std::size_t total = levels.levels.levels.size() * rings.size();
                result->plannedCandidates = total;
                auto measuringText = [&](std::size_t done) {
                    const std::size_t L = done / rings.size();
                    const int r = rings[done % rings.size()];
                    return tr("Measuring level %1 (%2 vertices), %3: %4 of %5")
                        .arg(L)
                        .arg(levels.levels.levels[L].mesh.vertexCount())
                        .arg(ringsText(r))
                        .arg(done + 1)
                        .arg(total);
                };
                post(kLevelsShare, measuringText(0));
                LodMeasurement measured = measureLodCandidates(
                    levels.levels, def,
                    [&](double f, const std::string&) {
                        const auto done = std::size_t(f * double(total) + 0.5);
                        post(kLevelsShare + (1.0 - kLevelsShare) * f,
                             done < total ? measuringText(done) : tr("Measured %1 candidates").arg(total));
                    },
                    cancelFlag);
                result->candidates = std::move(measured.candidates);
                result->measureCancelled = measured.cancelled;
            }
            // Linear or stiffening tissue (docs/lod.md, "Linear or nonlinear").
            if (!cancelFlag->load()) {
                post(1.0, tr("Pressing the hyperelastic reference for linear or stiffening tissue…"));
                try {
                    result->stiffening = pressHyperelasticReference(def, demands);
                } catch (const std::exception& e) {
                    result->stiffeningError = QString::fromStdString(e.what());
                }
            }
        } catch (const std::exception& e) {
            result->error = QString::fromStdString(e.what());
        } catch (...) {
            result->error = tr("unknown error");
        }
        // Its last act: the panel joins the thread when it runs this.
        handOffTo(this, [this, result] { onFinished(result); });
    });
    mThread->setObjectName(QStringLiteral("lod plan"));
    mRunClock.start();
    mProgress->setValue(0);
    mLastCancelled = false;
    setStatus(tr("Planning started…"));
    mThread->start(QThread::LowPriority);  // the haptic thread and the GUI come first
    updateButtons();
    return true;
}

void LodPanel::cancel() {
    if (!mThread || mCancel.load()) return;
    mCancel.store(true);
    setStatus(tr("Cancelling: the candidate being measured finishes first…"));
    updateButtons();
}

void LodPanel::onProgress(unsigned generation, double fraction, const QString& text) {
    if (!mThread || generation != mSceneGeneration) return;
    mProgress->setValue(int(fraction * kProgressSteps + 0.5));
    if (!mCancel.load()) setStatus(text);
    emit progressChanged(fraction, text);
}

void LodPanel::onFinished(const std::shared_ptr<RunResult>& result) {
    if (mThread) {
        mThread->wait();  // it posted this as its last act
        delete mThread;
        mThread = nullptr;
    }
    if (result->generation != mSceneGeneration) {
        // A run for a mesh the scene no longer uses: dropped.
        if (mPlanPending) plan();
        updateButtons();
        return;
    }
    const double seconds = double(mRunClock.elapsed()) / 1000.0;
    const QLocale locale;
    if (!result->error.isEmpty()) {
        mProgress->setValue(0);
        setStatus(tr("Plan failed: %1").arg(result->error), true);
        updateButtons();
        emit planFailed(result->error);
        return;
    }

    // Where the levels came from.
    QStringList counts;
    for (std::size_t v : result->levelVertices) counts << locale.toString(qulonglong(v));
    QString levels;
    if (result->levelsCancelled)
        levels = tr("The levels were not finished (cancelled); nothing was cached.");
    else if (result->fromCache)
        levels = tr("Levels (%1 vertices) read from the cache %2 next to the mesh.")
                     .arg(counts.join(QStringLiteral(", ")), QFileInfo(result->cacheDir).fileName());
    else
        levels = tr("Levels (%1 vertices) generated: %2.").arg(counts.join(QStringLiteral(", ")), result->cacheWhy);
    for (const QString& note : result->notes) levels += QLatin1Char(' ') + note + QLatin1Char('.');
    mLevelsProblem = !result->writeError.isEmpty();
    if (mLevelsProblem)
        levels += QLatin1Char(' ') + tr("The cache could not be written (%1): the levels other than 0 cannot be used.")
                                         .arg(result->writeError);
    mLevelsText = levels;
    mLevelsFromCache = result->fromCache;

    const bool cancelled = result->levelsCancelled || result->measureCancelled;
    mLastCancelled = cancelled;
    const std::size_t measured = result->candidates.size();
    if (!cancelled) {
        mProgress->setValue(kProgressSteps);
        const auto usable = std::size_t(std::count_if(result->candidates.begin(), result->candidates.end(),
                                                      [](const LodCandidate& c) { return c.note.empty(); }));
        setStatus(usable == measured ? tr("Planned in %1 s: %2 candidates measured on this machine.")
                                           .arg(locale.toString(seconds, 'f', 1))
                                           .arg(measured)
                                     : tr("Planned in %1 s: %2 of %3 candidates could be measured on this machine.")
                                           .arg(locale.toString(seconds, 'f', 1))
                                           .arg(usable)
                                           .arg(measured));
    } else if (result->levelsCancelled) {
        setStatus(mCandidates.empty() ? tr("Cancelled while making the levels; nothing was measured.")
                                      : tr("Cancelled while making the levels; the table shows the previous plan."));
    } else if (measured > 0) {
        setStatus(tr("Cancelled after %1 of %2 candidates: the table is partial and the plan is made from them only.")
                      .arg(measured)
                      .arg(result->plannedCandidates));
    } else {
        setStatus(mCandidates.empty() ? tr("Cancelled before the first candidate; nothing was measured.")
                                      : tr("Cancelled before the first candidate; the table shows the previous plan."));
    }
    if (measured > 0 || !cancelled) {
        mCandidates = std::move(result->candidates);
        mCandidatesMeshPath = result->meshPath;
        fillTable();
    }
    if (result->stiffening) mStiffeningReference = std::move(result->stiffening);
    if (!result->stiffeningError.isEmpty())
        mLevelsText += QStringLiteral(" ") + tr("The hyperelastic reference failed: %1").arg(result->stiffeningError);
    mLevelsLabel->setText(mLevelsText);
    mLevelsLabel->setStyleSheet(mLevelsProblem ? QStringLiteral("color: #c62828;") : QString());
    replan();
    updateButtons();
    emit planned();
}

// ---------------------------------------------------------------------------------------------
// Plan, table and choice

void LodPanel::replan() {
    mPlan = planLod(mCandidates, mNeeds);
    mStiffeningChoice.reset();
    if (mStiffeningReference && validateLodNeeds(mNeeds).empty()) {
        SlopeRingParams knotted;
        knotted.slopeMagnitudeMmPerN[0] = punchFirstSlopeMmPerN(mMeasureDef.contact);
        applyStiffening(*mStiffeningReference, knotted);
        mStiffeningChoice = chooseStiffening(*mStiffeningReference, knotted, sceneDepths(), mNeeds);
    }
    updateVerdicts();
    updateSummary();
    updateButtons();
    emit planChanged();
}

void LodPanel::fillTable() {
    const QSignalBlocker block(mTable);  // a refill is not the instructor selecting a row
    mTable->clearSelection();
    mTable->setRowCount(int(mCandidates.size()));
    const QLocale locale;
    for (int row = 0; row < int(mCandidates.size()); ++row) {
        const LodCandidate& c = mCandidates[std::size_t(row)];
        auto cell = [&](int column, const QString& text) {
            auto* item = new QTableWidgetItem(text);
            item->setTextAlignment(column == kVerdictColumn ? Qt::Alignment(Qt::AlignLeft | Qt::AlignVCenter)
                                                            : Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
            item->setToolTip(c.note.empty() ? candidateText(c)
                                            : tr("Not measured: %1").arg(QString::fromStdString(c.note)));
            mTable->setItem(row, column, item);
            return item;
        };
        cell(kLevelColumn, QString::number(c.level))->setData(Qt::UserRole, row);
        cell(kVerticesColumn, locale.toString(qulonglong(c.vertices)));
        cell(kRingsColumn, QString::number(c.rings));
        cell(kErrorColumn, QString());  // the value and its mark: updateVerdicts (they follow the targets)
        cell(kTickColumn, QString());
        cell(kVerdictColumn, QString());
    }
    mTable->setEnabled(!mCandidates.empty());
}

void LodPanel::updateVerdicts() {
    const QSignalBlocker block(mTable);
    const std::optional<std::size_t> selected = [&]() -> std::optional<std::size_t> {
        const QModelIndexList rows = mTable->selectionModel()->selectedRows();
        if (rows.isEmpty()) return std::nullopt;
        return std::size_t(rows.front().row());
    }();
    const bool validNeeds = mPlan.error.empty() || mCandidates.empty();
    for (int row = 0; row < mTable->rowCount() && row < int(mCandidates.size()); ++row) {
        const LodCandidate& c = mCandidates[std::size_t(row)];
        const auto i = std::size_t(row);
        const bool chosen = mPlan.chosen == i, closest = mPlan.closest == i;
        const bool override = selected == i && !chosen;
        // The value, then ✓ or ✗ against the target (none while the targets are invalid).
        auto mark = [&](int column, double value, int decimals, bool ok) {
            QTableWidgetItem* item = mTable->item(row, column);
            if (!std::isfinite(value)) {
                item->setText(tr("n/a"));
                item->setForeground(QBrush());
                return;
            }
            const QString number = QLocale().toString(value, 'f', decimals);
            if (!validNeeds) {
                item->setText(number);
                item->setForeground(QBrush());
                return;
            }
            item->setText(number + (ok ? QStringLiteral(" \u2713") : QStringLiteral(" \u2717")));
            item->setForeground(ok ? kYesColour : kNoColour);
        };
        mark(kErrorColumn, c.errorFraction * 100.0, 1, meetsError(c, mNeeds));
        mark(kTickColumn, c.tickUs, 3, meetsBudget(c, mNeeds));
        // One short word (the column is narrow): the closest row keeps its colour when it is the override.
        QString verdict;
        if (chosen) verdict = tr("chosen");
        else if (override) verdict = tr("override");
        else if (closest) verdict = tr("closest");
        if (!c.note.empty() && verdict.isEmpty()) verdict = tr("n/a");  // the row's tooltip says why
        mTable->item(row, kVerdictColumn)->setText(verdict);
        const QBrush background = chosen ? QBrush(kChosenBackground) : closest ? QBrush(kClosestBackground) : QBrush();
        for (int column = 0; column < kColumnCount; ++column) {
            QTableWidgetItem* item = mTable->item(row, column);
            item->setBackground(background);
            QFont font = item->font();
            font.setBold(chosen || closest);
            item->setFont(font);
        }
    }
    if (mPlan.chosen) mTable->scrollToItem(mTable->item(int(*mPlan.chosen), 0));
    else if (mPlan.closest) mTable->scrollToItem(mTable->item(int(*mPlan.closest), 0));
}

QString LodPanel::candidateText(const LodCandidate& c) const {
    const QLocale locale;
    return tr("level %1 (%2 vertices), %3: error %4 %, tick %5 µs")
        .arg(c.level)
        .arg(locale.toString(qulonglong(c.vertices)))
        .arg(ringsText(c.rings))
        .arg(std::isfinite(c.errorFraction) ? locale.toString(c.errorFraction * 100.0, 'f', 1) : tr("n/a"))
        .arg(std::isfinite(c.tickUs) ? locale.toString(c.tickUs, 'f', 3) : tr("n/a"));
}

void LodPanel::updateSummary() {
    QString summary;
    if (mCandidates.empty()) {
        summary = mMeshPath.isEmpty() ? tr("No scene mesh.")
                                      : tr("Nothing measured yet: Plan measures the levels on this machine.");
    } else if (!mPlan.error.empty()) {
        summary = tr("<b>No plan:</b> the targets are invalid.");
    } else if (mPlan.chosen) {
        summary = tr("<b>Chosen:</b> %1.").arg(candidateText(mCandidates[*mPlan.chosen]).toHtmlEscaped());
    } else if (mPlan.closest) {
        summary = tr("<b>Nothing meets both targets.</b> Closest: %1.")
                      .arg(candidateText(mCandidates[*mPlan.closest]).toHtmlEscaped());
    } else {
        summary = tr("<b>Nothing meets both targets</b> and no candidate could be measured.");
    }
    if (const auto unmeasured = std::count_if(mCandidates.begin(), mCandidates.end(),
                                              [](const LodCandidate& c) { return !c.note.empty(); });
        unmeasured > 0)
        summary += QStringLiteral("<br>") + tr("%1 of %2 candidates could not be measured (n/a): the row's tooltip "
                                               "says why.")
                                                .arg(unmeasured)
                                                .arg(mCandidates.size());
    if (isOverride())
        summary += QStringLiteral("<br>") +
                   tr("<b>Override:</b> %1.").arg(candidateText(mCandidates[*selectedCandidate()]).toHtmlEscaped());
    mSummaryLabel->setText(summary);
    // The planner's reason, in its own words: what it chose and what the cheaper candidates lack.
    // Invalid targets are named by the problem line under the fields, not here again.
    const QString reason =
        QString::fromStdString(mCandidates.empty() || !mPlan.error.empty() ? std::string() : mPlan.reason);
    QString why = reason.isEmpty() ? QString() : tr("Why: %1").arg(reason);
    if (!why.isEmpty() && mStiffeningChoice)
        why += QStringLiteral("\n") + tr("Tissue: %1").arg(QString::fromStdString(
                                          mStiffeningChoice->error.empty() ? mStiffeningChoice->reason : mStiffeningChoice->error));
    mReasonLabel->setText(why);
    mReasonLabel->setVisible(!why.isEmpty());
    mLevelsLabel->setText(mLevelsText);
    mLevelsLabel->setVisible(!mLevelsText.isEmpty());
}

std::optional<std::size_t> LodPanel::selectedCandidate() const {
    const QModelIndexList rows = mTable->selectionModel()->selectedRows();
    if (!rows.isEmpty() && rows.front().row() < int(mCandidates.size())) return std::size_t(rows.front().row());
    return mPlan.chosen;
}

bool LodPanel::isOverride() const {
    const QModelIndexList rows = mTable->selectionModel()->selectedRows();
    return !rows.isEmpty() && rows.front().row() < int(mCandidates.size()) &&
           mPlan.chosen != std::size_t(rows.front().row());
}

void LodPanel::selectCandidate(std::optional<std::size_t> candidateIndex) {
    if (!candidateIndex || *candidateIndex >= mCandidates.size()) {
        mTable->clearSelection();
        return;
    }
    mTable->selectRow(int(*candidateIndex));
}

QString LodPanel::levelMeshPath(std::size_t candidateIndex) const {
    if (candidateIndex >= mCandidates.size() || mCandidates[candidateIndex].level == 0) return {};
    // LevelCache.cpp writes level k as "level<k>.obj" in levelCacheDir (docs/lod.md §3); the test
    // reloads the file and checks its vertex count, so a change of that naming is caught.
    const QString dir = QString::fromStdString(levelCacheDir(mCandidatesMeshPath.toStdString()));
    return QDir(dir).filePath(QStringLiteral("level%1.obj").arg(mCandidates[candidateIndex].level));
}

void LodPanel::useChosen() {
    if (mThread || !mPlan.chosen) return;
    emitUse(*mPlan.chosen, false);
}

void LodPanel::useSelected() {
    if (mThread) return;
    const QModelIndexList rows = mTable->selectionModel()->selectedRows();
    if (rows.isEmpty() || rows.front().row() >= int(mCandidates.size())) return;
    const auto i = std::size_t(rows.front().row());
    emitUse(i, mPlan.chosen != i);
}

void LodPanel::emitUse(std::size_t candidateIndex, bool overridden) {
    const LodCandidate& c = mCandidates[candidateIndex];
    const QString path = levelMeshPath(candidateIndex);
    if (!path.isEmpty() && !QFileInfo::exists(path)) {
        setStatus(tr("The level's mesh file %1 is missing (was the cache written or removed?); plan again.").arg(path),
                  true);
        return;
    }
    setStatus(overridden ? tr("Using %1 (override).").arg(candidateText(c)) : tr("Using %1.").arg(candidateText(c)));
    emit useRequested(path, c.rings, overridden);
}

void LodPanel::setUseUndoable(bool undoable, const QString& changed) {
    mUndoUseButton->setEnabled(undoable);
    mUsedLabel->setText(changed);
    mUsedLabel->setVisible(!changed.isEmpty());
}

void LodPanel::storeNeeds() {
    if (!needsProblems().isEmpty()) return;
    emit storeNeedsRequested(mNeeds);
}

void LodPanel::updateButtons() {
    const bool running = busy();
    const bool needsOk = needsProblems().isEmpty();
    const QModelIndexList rows = mTable->selectionModel()->selectedRows();
    const bool rowSelected = !rows.isEmpty() && rows.front().row() < int(mCandidates.size());
    mPlanButton->setEnabled(!running && needsOk && !mMeshPath.isEmpty());
    mStoreButton->setEnabled(needsOk);
    mCancelButton->setEnabled(running && !mCancel.load());
    mUseChosenButton->setEnabled(!running && mPlan.chosen.has_value());
    mUseSelectedButton->setEnabled(!running && rowSelected && isOverride());
    mTable->setEnabled(!running && !mCandidates.empty());
    // The bar and Cancel appear with the first run and then keep showing how the last one ended.
    const bool progressShown = running || mProgress->value() > 0;
    mProgress->setVisible(progressShown);
    mCancelButton->setVisible(progressShown);
}

void LodPanel::setStatus(const QString& text, bool problem) {
    QString shown = text;
    if (shown.isEmpty())
        shown = mMeshPath.isEmpty() ? tr("No scene mesh yet.") : tr("Ready: Plan measures the levels of %1.")
                                                                      .arg(QFileInfo(mMeshPath).fileName());
    mStatusLabel->setText(shown);
    mStatusLabel->setStyleSheet(problem ? QStringLiteral("color: #c62828;") : QString());
}

QString LodPanel::statusText() const { return mStatusLabel->text(); }

}  // namespace palpate
