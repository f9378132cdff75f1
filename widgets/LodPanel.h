#pragma once
// The level-of-detail panel (docs/lod.md): chooses the mesh level and ring count for the
// scene. The scene's needs (accuracy target, tick budget) come from the exercise or preset and can
// be edited here; Plan makes (or reads from the cache beside the mesh) the coarser levels and
// measures every level and ring count on a worker thread, with progress and Cancel; the table shows
// the candidates, which one the planner chose and why, and lets the instructor use another one.
// Editing the targets replans from the measured table at once: planLod is pure, so nothing is
// measured again.

#include "engine/core/TissueMesh.h"
#include "engine/lod/LodMeasure.h"
#include "engine/lod/LodNeeds.h"
#include "engine/lod/LodPlanner.h"
#include "engine/lod/StiffeningChoice.h"
#include "engine/exercise/ExerciseDemands.h"

#include <QElapsedTimer>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <atomic>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QThread;

namespace palpate {

class LodPanel final : public QWidget {
    Q_OBJECT
public:
    explicit LodPanel(QWidget* parent = nullptr);
    /// Cancels a running plan and waits for it (at most one candidate's measurement or a short
    /// stretch of decimation), so the worker never outlives the panel.
    ~LodPanel() override;

    /// The needs the panel starts from when the scene states none (the engine's LodNeeds{}).
    static LodNeeds defaultNeeds();
    /// What a plan measures unless told otherwise: rings 1, 2, 3, 4, 6, median of 3 runs of at
    /// least 5 ms each (a plan on a 1442-vertex sphere takes about a second, on 8664 a few).
    static LodMeasureDef defaultMeasureDefinition();

    /// The mesh the scene uses: its file (the level cache is written next to it as
    /// "<file>.levels/") and, when already loaded, the mesh (else the worker loads the file); and
    /// the needs to meet (from the preset or exercise; nullopt: defaultNeeds()). `needsSource`
    /// says where they came from ("exercise 'Palpate the lump'"), shown above the fields.
    /// The same file and mesh again only updates the needs and keeps the measured table; another
    /// mesh clears it (and cancels a plan running for the old one).
    void setScene(const QString& meshPath, std::shared_ptr<const TissueMesh> mesh, std::optional<LodNeeds> needs,
                  const QString& needsSource = QString());
    QString meshPath() const { return mMeshPath; }

    /// The tissue, tool and timing the next plan measures with (the preset's tissue and tool, its
    /// damping and k_c in `base`). Invalid definitions are refused by the next plan, with the reason.
    void setMeasureDefinition(const LodMeasureDef& def);
    const LodMeasureDef& measureDefinition() const { return mMeasureDef; }
    /// Shorthand: only the tissue and tool of the measure definition.
    void setToolContact(const ToolContact& contact);
    /// The presses the scene asks for (an exercise's, engine/exercise/ExerciseDemands.h); none:
    /// the plan's own press. The next plan judges linear against stiffening tissue at them
    /// (docs/lod.md, "Linear or nonlinear"), and a change re-decides at once when it can.
    void setSceneDemands(std::vector<ExerciseDemand> demands);
    /// The last plan's hyperelastic reference (its curve), when it was solved.
    const std::optional<StiffeningCalibration>& stiffeningReference() const { return mStiffeningReference; }
    /// Linear or stiffening tissue for the current needs and demands (nullopt before a plan).
    const std::optional<StiffeningChoice>& stiffeningChoice() const { return mStiffeningChoice; }

    /// Starts loadOrGenerateLevels + measureLodCandidates on a worker thread; the progress bar,
    /// its text and Cancel follow it. Does nothing (false) while a plan for this scene runs,
    /// without a mesh file, with invalid needs or an invalid measure definition (the reason is
    /// shown). While a run for a previous scene winds down, starts as soon as it has (true).
    bool plan();
    /// Asks a running plan to stop; what was measured until then is kept and planned.
    void cancel();
    bool busy() const { return mThread != nullptr; }

    /// The fields (max error as a fraction, budget in µs); validated live.
    const LodNeeds& needs() const { return mNeeds; }
    /// Sets the fields (and replans from the table).
    void setNeeds(const LodNeeds& needs);
    /// "" when the fields are usable, else the problems, each naming its field.
    QStringList needsProblems() const;

    /// The measured candidates (measureLodCandidates' order: level by level, rings ascending).
    const std::vector<LodCandidate>& candidates() const { return mCandidates; }
    /// The plan for the candidates and the current needs (its error says why there is none).
    const LodPlan& currentPlan() const { return mPlan; }
    /// The candidate the scene should use: the row the instructor selected (an override) if any,
    /// else the planner's choice; nullopt when neither exists.
    std::optional<std::size_t> selectedCandidate() const;
    /// Whether selectedCandidate() is the instructor's override rather than the planner's choice.
    bool isOverride() const;
    /// Selects a table row (the instructor's override); nullopt clears the selection.
    void selectCandidate(std::optional<std::size_t> candidateIndex);

    /// The level's mesh file for a candidate: "<mesh>.levels/level<k>.obj" in the cache folder,
    /// "" for level 0 (the source itself) or an index out of range.
    QString levelMeshPath(std::size_t candidateIndex) const;

    /// Where the levels of the last plan came from: the cache, or generated (and why).
    bool levelsFromCache() const { return mLevelsFromCache; }
    /// Whether the last plan was cancelled (its table, if any, is partial).
    bool lastPlanCancelled() const { return mLastCancelled; }
    /// The line under the progress bar: the run's progress, its outcome or the last problem.
    QString statusText() const;

signals:
    /// A plan ended with its candidates and the plan for them; also after Cancel with the
    /// candidates measured until then (lastPlanCancelled() says so).
    void planned();
    /// currentPlan() changed: after a plan, or at once when the targets were edited.
    void planChanged();
    /// A plan could not be made: the mesh could not be loaded or decimated, a bad definition.
    void planFailed(const QString& error);
    /// The running plan's progress (0..1) and what it is doing, on the panel's thread.
    void progressChanged(double fraction, const QString& text);
    /// "Use": the window loads `levelMeshPath` ("" : the source mesh) and sets the ring count.
    /// `overridden`: the instructor's choice, not the planner's.
    void useRequested(const QString& levelMeshPath, int rings, bool overridden);
    /// "Store targets in preset": the window writes the needs into the current preset.
    void storeNeedsRequested(const palpate::LodNeeds& needs);
    /// "Undo use": the window goes back to the mesh and the tissue from before the first Use.
    void undoUseRequested();

public slots:
    /// "Use chosen": emits useRequested for the planner's choice.
    void useChosen();
    /// "Use selected (override)": emits useRequested for the selected row.
    void useSelected();
    /// "Store targets in preset": emits storeNeedsRequested while the fields are valid.
    void storeNeeds();

public:
    /// The window says whether a Use can be undone, and what it changed (shown under the buttons).
    void setUseUndoable(bool undoable, const QString& changed = {});

protected:
    void changeEvent(QEvent* event) override;

private:
    struct RunResult;

    /// Targets, progress and candidates in the scroll area.
    void layOutWidgets();
    /// What the panel says for a stage of loadOrGenerateLevels (making `coarse` coarser levels).
    static QString levelStageText(const std::string& stage, std::size_t coarse);
    void retranslateUi();
    void onNeedsEdited();
    /// Fills the two fields without reacting to it (the caller replans once).
    void setNeedsFields(const LodNeeds& needs);
    void replan();
    /// The depths of the scene's demands on the reference curve (forces turned into depths).
    std::vector<SceneDepth> sceneDepths() const;
    void fillTable();
    void updateVerdicts();
    void updateSummary();
    void updateButtons();
    void updateNeedsSource();
    void setStatus(const QString& text, bool problem = false);
    void onProgress(unsigned generation, double fraction, const QString& text);
    void onFinished(const std::shared_ptr<RunResult>& result);
    void emitUse(std::size_t candidateIndex, bool overridden);
    QString candidateText(const LodCandidate& c) const;
    /// "1 ring", "3 rings".
    static QString ringsText(int rings);

    // Fields and buttons.
    QGroupBox* mTargetsBox = nullptr;
    QGroupBox* mCandidatesBox = nullptr;
    QLabel* mNeedsSourceLabel = nullptr;
    QLabel* mErrorLabel = nullptr;
    QLabel* mBudgetLabel = nullptr;
    QDoubleSpinBox* mErrorSpin = nullptr;   ///< max error in % of the peak displacement
    QDoubleSpinBox* mBudgetSpin = nullptr;  ///< tick budget in µs
    QLabel* mNeedsProblemLabel = nullptr;
    QPushButton* mPlanButton = nullptr;
    QPushButton* mStoreButton = nullptr;
    QProgressBar* mProgress = nullptr;
    QPushButton* mCancelButton = nullptr;
    QLabel* mStatusLabel = nullptr;
    QLabel* mLevelsLabel = nullptr;
    QTableWidget* mTable = nullptr;
    QLabel* mSummaryLabel = nullptr;
    QLabel* mReasonLabel = nullptr;
    QPushButton* mUseChosenButton = nullptr;
    QPushButton* mUseSelectedButton = nullptr;
    QPushButton* mUndoUseButton = nullptr;
    QLabel* mUsedLabel = nullptr;  ///< what the last Use changed

    // The scene.
    QString mMeshPath;
    std::shared_ptr<const TissueMesh> mMesh;
    std::optional<LodNeeds> mSceneNeeds;
    QString mSceneNeedsSource;
    LodNeeds mNeeds;
    LodNeeds mNeedsAsSet;  ///< the fields as setScene filled them: differing means edited here
    LodMeasureDef mMeasureDef;

    // The measured table and the plan for it.
    std::vector<LodCandidate> mCandidates;
    std::vector<ExerciseDemand> mDemands;
    std::optional<StiffeningCalibration> mStiffeningReference;  ///< knots fitted to the plan's |m1|
    std::optional<StiffeningChoice> mStiffeningChoice;
    QString mCandidatesMeshPath;  ///< the mesh file the table was measured on (its cache folder)
    LodPlan mPlan;
    bool mLevelsFromCache = false;
    bool mLastCancelled = false;
    QString mLevelsText;          ///< where the levels came from (untranslated parts from the engine)
    bool mLevelsProblem = false;

    // The worker.
    QThread* mThread = nullptr;
    std::atomic<bool> mCancel{false};
    /// Incremented when the scene changes: a run started for an older scene is joined and dropped.
    unsigned mSceneGeneration = 0;
    unsigned mRunGeneration = 0;
    bool mPlanPending = false;  ///< Plan pressed while a dropped run was still winding down
    QElapsedTimer mRunClock;
    bool mUpdatingFields = false;
};

}  // namespace palpate
