#pragma once
// The instructor's exercise editor (docs/scoring.md): authors a graded exercise (Exercise.h) in the GUI.
// Common fields (name, description, mesh, tissue preset, limits), one page per type (press
// targets: a table of targets; find the lump: the inclusion; trace: the path points), the rubric
// of the metrics that apply to the type, and the problems of the exercise, live. Each type's page
// is built from its kind's editing descriptor (engine/exercise/ExerciseEditing.h): a table of the
// points it places (targets, the inclusion, path points, lumps) with their numbers, and the
// numbers of its section. Points are placed
// by clicking the drawn mesh: the window forwards the viewport's picks to vertexPicked() while
// placingChanged(true) says the panel wants them. The exercise, its meshes and its checks are an
// ExerciseDocument (Qt-free); this panel shows them. Each press target is checked, live, for whether
// its force window can be reached pressing with the mouse (TargetReachability.h), on the document's
// worker thread: a warning per target that cannot, saying what to change; a first target gets a
// window the tissue reaches. Every edit is one step on
// a QUndoStack (typing into one field merges). Files are the engine's exercise JSON (ExerciseFile.h); saving writes
// mesh and preset paths relative to resources/ when they are under it, as the shipped examples do.
// A plain QWidget, meant for a QDockWidget (about 380 px wide: the form scrolls).

#include "engine/core/TissueMesh.h"
#include "engine/exercise/Exercise.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/scoring/ExerciseDocument.h"
#include "widgets/ExerciseMarkers.h"

#include <QList>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QHBoxLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QPushButton;
class QStackedWidget;
class QTableWidget;
class QTimer;
class QToolButton;
class QUndoStack;

namespace palpate {
class ExerciseKind;
}

namespace palpate {

struct TouchReach;

class ExerciseEditorPanel final : public QWidget {
    Q_OBJECT
public:
    /// What a click on the drawn mesh does.
    enum class Placing {
        None,          ///< nothing: the viewport keeps its clicks
        AddItem,       ///< append an item (target, path point, lump) at the vertex (stays on for more)
        MoveSelected,  ///< the selected item (a single one: it) moves there (one click)
    };
    /// The answer to "discard the unsaved changes?".
    enum class DiscardAnswer { Save, Discard, Cancel };
    /// Asks the user; gets the exercise's name. Tests set one that answers without a dialog.
    using DiscardQuestion = std::function<DiscardAnswer(const QString& exerciseName)>;

    /// `findResource` finds files under resources/ (the app's findResource); the mesh and
    /// preset lists come from the resources/ it finds.
    explicit ExerciseEditorPanel(ResourceFinder findResource, QWidget* parent = nullptr);
    ~ExerciseEditorPanel() override;

    /// The mesh the viewport draws (engine numbering) and its file: picks refer to it. Markers
    /// and placement are only given while it is the exercise's mesh (resolved paths equal);
    /// problems() says so when it is not.
    void setDrawnMesh(std::shared_ptr<const TissueMesh> mesh, const QString& path);
    /// True when the drawn mesh is the exercise's mesh, read in the exercise's unit.
    bool drawnMeshMatches() const;

    /// A new exercise of `type` with sensible defaults on the drawn mesh (else the default
    /// stomach) and a tissue preset; no file, a fresh undo history. Does not ask about unsaved
    /// changes: call confirmDiscard() first (the New actions do).
    void newExercise(ExerciseType type);
    /// Opens an exercise file: "" or the errors, each naming the file and the key (the current
    /// exercise is left untouched then). A fresh undo history. Does not ask (confirmDiscard()).
    QString openExercise(const QString& path);
    /// Saves to `path` (and makes it the current file): "" or why not. Refused while the exercise
    /// has problems a trainee session would fail on; a mesh other than the drawn one is fine.
    QString saveExercise(const QString& path);
    /// Saves to the current file, or asks for one (Save As) when there is none: "" or why not.
    QString save();
    /// Writes the exercise as a bundle (docs/scoring.md, "Exercise bundles"): the saved file with
    /// its mesh, preset and scripted paths. Saves first when there are unsaved changes (asking for
    /// a file when there is none). "" or why not.
    QString exportBundle(const QString& bundlePath);

    /// The exercise being edited; its sourcePath is where its relative paths resolve from (the
    /// file it was opened from or last saved to, empty for a new one).
    const Exercise& exercise() const;
    /// The file Save writes ("" for a new exercise).
    QString currentPath() const { return mPath; }
    /// Unsaved changes (the undo stack is not at its clean state).
    bool isModified() const;
    QUndoStack* undoStack() const { return mUndoStack; }

    void setPlacing(Placing placing);
    Placing placing() const { return mPlacing; }
    /// The item (target, path point, lump) being edited, -1 for none; a single item (the
    /// inclusion) is never selected. Selecting one highlights its marker.
    int selectedIndex() const { return mSelected; }
    void setSelectedIndex(int index);

    /// Problems of the current exercise (validateExercise, files that cannot be found, placement
    /// on the drawn mesh, a drawn mesh that is not the exercise's); empty: valid.
    QStringList problems() const { return mProblems; }
    /// Targets whose force window (or a trace whose band) cannot be reached pressing with the mouse
    /// (touch mode's deepest press, the exercise's tissue and tool), each naming the key and what
    /// to change.
    /// They do not block saving or Try it: a device in the hand may press harder. Checked on a
    /// worker thread after every change (reachChecking() until reachChecked()); until then the
    /// last check's stay.
    QStringList warnings() const { return mWarnings; }
    /// True from a change until its reach check's warnings are shown.
    bool reachChecking() const;
    /// How deep touch mode presses: the viewport's depths.
    static TouchReach touchReach();
    /// The markers the viewport should draw (what markersChanged last sent).
    const ExerciseMarkers& markers() const { return mMarkers; }

    /// Replaces the question asked before unsaved changes are discarded (default: a message box).
    void setDiscardQuestion(DiscardQuestion question);
    /// True when nothing unsaved would be lost, or the user said Discard, or said Save and the
    /// save succeeded. For New/Open and for the window's close.
    bool confirmDiscard();

    /// Actions for the window's menus and toolbars (each also a button of the panel; shortcuts
    /// active while the focus is in the panel: the window may widen their context).
    /// "New: <type>", one per kind (exerciseKinds()).
    QAction* newAction(ExerciseType type) const;
    QAction* openAction() const { return mOpenAction; }      ///< Ctrl+O: asks, then a file dialog
    QAction* saveAction() const { return mSaveAction; }      ///< Ctrl+S
    QAction* saveAsAction() const { return mSaveAsAction; }  ///< Ctrl+Shift+S
    QAction* undoAction() const { return mUndoAction; }      ///< Ctrl+Z
    QAction* redoAction() const { return mRedoAction; }      ///< Ctrl+Shift+Z
    QAction* previewAction() const { return mPreviewAction; }  ///< F5: "Try it"
    /// All of the above, in menu order (the New ones first).
    QList<QAction*> editorActions() const;

public slots:
    /// A click on the drawn mesh (engine numbering), acted on by the placing mode.
    void vertexPicked(VertexId engineVertex);
    /// "Try it": emits previewRequested with the current exercise if it has no problems a session
    /// would fail on; returns whether it did (otherwise the reason is shown).
    bool preview();
    /// File dialogs (then openExercise / saveExercise).
    void openDialog();
    bool saveAsDialog();
    void exportBundleDialog();

signals:
    /// The instructor's markers, after every change (edits, undo, selection, the drawn mesh).
    void markersChanged(const palpate::ExerciseMarkers& markers);
    /// The window sets (true) or clears (false) the viewport's pick handler.
    void placingChanged(bool clickToPlace);
    /// The exercise's mesh should be drawn ("Show this mesh"): its resolved, absolute path.
    void meshRequested(const QString& path);
    /// "Try it": run this exercise as a trainee would, unsaved. Its mesh and preset paths resolve
    /// with resolveExercisePath (its sourcePath, else resources/, else absolute).
    void previewRequested(const palpate::Exercise& exercise);
    void modifiedChanged(bool modified);
    /// The warnings of the latest change are shown (warnings()).
    void reachChecked();

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// Fields whose consecutive edits merge into one undo step.
    enum Field : int {
        kName,
        kDescription,
        kTimeLimit,
        kDisplacementLimit,
        kExcessiveForce,
        kNeedsError,
        kNeedsBudget,
        kMeshScale,
        /// The kind's section numbers: kSectionNumber + their index.
        kSectionNumber,
        /// Merge keys are field + kMergeFields * epoch.
        kMergeFields = 64
    };
    /// One type's page, built from its kind's editing descriptor.
    struct KindPage {
        const ExerciseKind* kind = nullptr;
        QWidget* page = nullptr;
        QTableWidget* table = nullptr;
        QToolButton* add = nullptr;
        QToolButton* move = nullptr;
        QToolButton* remove = nullptr;
        QToolButton* up = nullptr;
        QToolButton* down = nullptr;
        std::vector<QDoubleSpinBox*> numbers;  ///< the section's, in the descriptor's order
        std::vector<QLabel*> numberLabels;
    };

    void buildUi();
    void createActions();
    /// New, Open, Save, Save As, undo and redo.
    QHBoxLayout* buildFileRow();
    void buildExerciseForm(QFormLayout* form);
    void buildSceneForm(QFormLayout* form);
    void buildLimitsForm(QFormLayout* form);
    QGroupBox* buildTypeGroup(QWidget* fields);
    QGroupBox* buildRubricGroup(QWidget* fields);
    /// The placing hint, problems, warnings and messages below the form; returns Try it's row.
    QHBoxLayout* buildFeedback();
    /// Every field's edits become undo steps.
    void connectEdits();
    void retranslateUi();
    void buildTypePages();
    /// Sets every widget from `exercise` without recording a step (undo/redo, open, new).
    void showExercise(const Exercise& exercise);
    /// Records `after` as one undo step named `text` (merging with the last when `field` >= 0
    /// and the user is still in that field) and shows it.
    void pushEdit(const Exercise& after, const QString& text, int field = -1);
    void onFieldEdited(int field);
    void onItemCellChanged(int row, int column);
    /// The page of the exercise's kind.
    KindPage& page();
    const KindPage& page() const;
    /// How many items the exercise has (its kind's).
    int itemCount() const;
    /// Builds one kind's page.
    QWidget* buildKindPage(const ExerciseKind& kind);
    /// Fills the page of the exercise's kind from it.
    void showItems(const Exercise& exercise);
    void onRubricCellChanged(int row, int column);
    void commitPath(bool mesh, const QString& text);
    /// The unit combo's choice: 0..3 a named unit, 4 "scale…" (the spin box's factor).
    void commitMeshUnit(int index);
    void browsePath(bool mesh);
    void changeType(ExerciseType type);
    void removeSelected();
    void moveSelected(int delta);
    void resetRubric();
    /// Recomputes the problems and the markers and shows them (and the title, the buttons).
    void refresh();
    /// Shows mProblems and mWarnings (the lists, and the fields and cells they name) and enables
    /// the buttons that apply.
    void showProblems(const QString& meshFile);
    void updateTitle();
    void updatePlacingUi();
    void showMessage(const QString& text, bool error);
    void fillResourceCombos();
    /// The path to write for a file: relative to resources/ when findResource finds it there
    /// (and nothing beside `exercise`'s file shadows it), else absolute.
    QString storablePath(const Exercise& exercise, const QString& absolutePath) const;
    /// The absolute path of the exercise's mesh or preset, "" when it cannot be found.
    QString resolved(const Exercise& exercise, const std::string& path) const;
    /// Problems a session would fail on (everything in problems() but a different drawn mesh).
    QStringList blockingProblems() const;
    /// The drawn mesh's vertex (file numbering) for a pick, or nullopt with the reason shown.
    std::optional<std::uint32_t> fileVertex(VertexId engineVertex);
    QString typeText(ExerciseType type) const;
    /// Starts checking whether the mouse reaches what the exercise asks (on the document's worker).
    void checkReach();
    /// The findings of a check, in the user's language, unless a later check was started.
    void showReach(ReachCheckResult result);
    QString reachText(const ReachFinding& finding, const ExerciseGeometry& geometry) const;
    /// A label registered for retranslation.
    QLabel* rowLabel(const char* text);

    /// Translatable row labels (QT_TR_NOOP texts), set again on a language change.
    std::vector<std::pair<QLabel*, const char*>> mRowLabels;
    QStringList mWarnings;
    bool mChecking = false;  ///< a reach check runs whose warnings are not shown yet
    ResourceFinder mFindResource;
    QString mResourceRoot;  ///< resources/ as found through mFindResource ("" if not)
    /// The exercise, its drawn and checked meshes, its problems and its reach check.
    std::unique_ptr<ExerciseDocument> mDocument;

    QString mPath;
    Placing mPlacing = Placing::None;
    int mSelected = -1;
    QStringList mProblems;
    QStringList mBlocking;
    ExerciseMarkers mMarkers;
    bool mShowing = false;  ///< widgets being set by showExercise: their signals are not edits
    int mMergeEpoch = 0;    ///< bumped when a field loses focus: the next edit is a new step
    DiscardQuestion mDiscardQuestion;
    QString mLastDirectory;

    QUndoStack* mUndoStack = nullptr;
    std::vector<QAction*> mNewActions;  ///< one per kind, in exerciseKinds() order
    QAction* mOpenAction = nullptr;
    QAction* mSaveAction = nullptr;
    QAction* mSaveAsAction = nullptr;
    QAction* mExportBundleAction = nullptr;
    QAction* mUndoAction = nullptr;
    QAction* mRedoAction = nullptr;
    QAction* mPreviewAction = nullptr;
    QAction* mRemoveAction = nullptr;
    QAction* mMoveUpAction = nullptr;
    QAction* mMoveDownAction = nullptr;
    QAction* mStopPlacingAction = nullptr;

    // Widgets.
    QLabel* mTitleLabel = nullptr;
    QToolButton* mNewButton = nullptr;
    QToolButton* mOpenButton = nullptr;
    QToolButton* mSaveButton = nullptr;
    QToolButton* mSaveAsButton = nullptr;
    QToolButton* mUndoButton = nullptr;
    QToolButton* mRedoButton = nullptr;
    QPushButton* mPreviewButton = nullptr;
    QGroupBox* mExerciseGroup = nullptr;
    QGroupBox* mSceneGroup = nullptr;
    QGroupBox* mLimitsGroup = nullptr;
    QGroupBox* mTypeGroup = nullptr;
    QGroupBox* mRubricGroup = nullptr;
    QComboBox* mTypeCombo = nullptr;
    /// Which language's name and description the two fields edit: "" the exercise's own, else a
    /// code of its translations (docs/scoring.md, "Translations").
    QComboBox* mTextLanguageCombo = nullptr;
    QString textLanguage() const;
    static QString textLanguageName(const QString& code);
    void showExerciseText(const Exercise& e);
    void showTextPlaceholders(const Exercise& e);
    QLineEdit* mNameEdit = nullptr;
    QPlainTextEdit* mDescriptionEdit = nullptr;
    QComboBox* mMeshCombo = nullptr;
    QPushButton* mMeshBrowseButton = nullptr;
    QPushButton* mShowMeshButton = nullptr;
    QLabel* mMeshStateLabel = nullptr;
    /// "mesh_unit" (docs/meshes.md, "Units"): mm, cm, m, in, or "scale…" with mm per file unit.
    QComboBox* mMeshUnitCombo = nullptr;
    QDoubleSpinBox* mMeshScaleSpin = nullptr;
    QComboBox* mPresetCombo = nullptr;
    QPushButton* mPresetBrowseButton = nullptr;
    QDoubleSpinBox* mTimeLimitSpin = nullptr;
    QDoubleSpinBox* mDisplacementSpin = nullptr;
    QDoubleSpinBox* mExcessiveSpin = nullptr;
    /// "needs" (docs/lod.md): whether the exercise states level-of-detail targets, and them.
    QCheckBox* mNeedsCheck = nullptr;
    QDoubleSpinBox* mNeedsErrorSpin = nullptr;
    QDoubleSpinBox* mNeedsBudgetSpin = nullptr;
    /// "show_live_score": checked when the trainee sees the score while the exercise runs.
    QCheckBox* mLiveScoreCheck = nullptr;
    QStackedWidget* mTypePages = nullptr;
    std::vector<KindPage> mPages;  ///< one per kind, in exerciseKinds() order
    // Rubric.
    QTableWidget* mRubricTable = nullptr;
    QPushButton* mResetRubricButton = nullptr;
    QLabel* mRubricTotalLabel = nullptr;
    // Feedback.
    QLabel* mPlacingLabel = nullptr;
    QLabel* mProblemsLabel = nullptr;
    QLabel* mCheckingLabel = nullptr;
    QTimer* mCheckingTimer = nullptr;
    QLabel* mWarningsLabel = nullptr;
    QLabel* mMessageLabel = nullptr;
};

}  // namespace palpate
