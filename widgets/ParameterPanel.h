#pragma once
// The parameters panel: every value of a tissue preset an instructor tunes (model, rings, slopes as
// magnitudes in mm/N, springs, contact, octree, haptic rate), validated live with the engine's own
// validators, with the slope model's loop gain and stability margin, undo/redo through a
// QUndoStack, and preset files. It only edits a TissuePreset: the main window decides what Apply
// does (e.g. HapticLoop::setModelParams). A plain QWidget, meant for a QDockWidget.
// The Tissue group turns elasticity into slopes (docs/calibration.md): Young's modulus, Poisson's ratio and
// the tool radius, the shipped tissue presets, and Calibrate slopes for the current mesh with the
// error the calibrated model leaves against the flat punch.

#include "engine/core/Rings.h"
#include "engine/core/TissueMesh.h"
#include "engine/scene/TissuePreset.h"
#include "engine/accuracy/Calibration.h"
#include "engine/accuracy/StiffeningCalibration.h"
#include "engine/stability/StabilityMargin.h"

#include <QString>
#include <QStringList>
#include <QWidget>

#include <array>
#include <functional>
#include <optional>
#include <vector>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGraphicsOpacityEffect;
class QGroupBox;
class QLabel;
class QPushButton;
class QScrollArea;
class QSequentialAnimationGroup;
class QSpinBox;
class QUndoStack;

namespace palpate {

struct PanelField;

class ParameterPanel final : public QWidget {
    Q_OBJECT
public:
    /// The paper's slope range is (0, 1) mm/N; above it a slope needs a raised slope limit.
    static constexpr double kPaperSlopeMaxMmPerN = 1.0;

    /// Returns the mesh Calibrate slopes works on, or null when there is none. Called for each
    /// calibration and each stability margin; the panel never keeps the pointer.
    using MeshProvider = std::function<const TissueMesh*()>;
    /// Asks the user to confirm (title, text); true to go ahead. The default is a modal
    /// QMessageBox (Yes / No, No the default); tests may answer that box or replace the function.
    using ConfirmFunction = std::function<bool(const QString& title, const QString& text)>;

    explicit ParameterPanel(QWidget* parent = nullptr);
    ~ParameterPanel() override;

    /// The preset the fields show (name, description and tissue properties carried through).
    TissuePreset preset() const;
    /// Shows `preset` as a new baseline that is also what runs: no undo entry, and the undo history
    /// is cleared (its steps belong to the preset that was shown before).
    void setPreset(const TissuePreset& preset);

    /// Stiffening knots from the Charts dock (StiffeningPanel) into the shown preset's slope-ring
    /// parameters, as one undoable step ("Apply stiffening knots"), then Apply as the button does.
    /// The slopes, rings and everything else stay. "" or why not (the fields are not valid).
    QString applyStiffeningKnots(const StiffeningCalibration& calibration);

    /// The main window's answer to applyRequested once the haptic loop runs `running`: fields equal
    /// to it lose their "changed" mark, and "Applied to the running tissue at HH:MM:SS" shows for a
    /// few seconds. The fields and the undo history stay as they are (docs/user-guide.md, Parameters).
    void showApplied(const TissuePreset& running);
    /// What the haptic loop runs, as the panel was last told (setPreset or showApplied).
    const TissuePreset& runningPreset() const { return mRunning; }
    /// True when a field differs from what runs: the "Not applied" bar is shown and each such field
    /// and its label carry the `modified` property.
    bool hasUnappliedChanges() const { return !mUnapplied.isEmpty(); }
    /// The fields that differ from what runs, as their rows name them.
    const QStringList& unappliedFields() const { return mUnapplied; }

    /// True when the fields pass every check (what enables Apply).
    bool isValid() const { return mValid; }
    /// The problems shown under the fields, one per entry (empty when valid).
    const QStringList& problems() const { return mProblems; }

    QUndoStack* undoStack() const { return mUndoStack; }
    /// Undo/Redo created from the stack (Ctrl+Z, Ctrl+Shift+Z), active while the focus is in the
    /// panel; a main window that adds them to its Edit menu may widen their shortcut context.
    QAction* undoAction() const { return mUndoAction; }
    QAction* redoAction() const { return mRedoAction; }
    /// "Open preset…" / "Save preset…": the file dialogs, then loadPresetFile / savePresetFile.
    QAction* openPresetAction() const { return mOpenAction; }
    QAction* savePresetAction() const { return mSaveAction; }

    /// Reads a preset file into the fields as one undoable step. On failure (the error names the
    /// file and the key) the fields stay as they were, the error is shown under the fields and
    /// false is returned. No dialog.
    bool loadPresetFile(const QString& path, QString* error = nullptr);
    /// Writes the fields' preset (refused while invalid: the file could not be read back). No dialog.
    bool savePresetFile(const QString& path, QString* error = nullptr);

    void setMeshProvider(MeshProvider provider);
    /// Replaces how Apply asks for confirmation of a set beyond its stability margin (null: the default box).
    void setConfirmFunction(ConfirmFunction confirm);
    /// The stability margin of the fields' set at the fields' haptic rate (engine/stability/
    /// StabilityMargin.h), for every model: the smaller of the model's own bound (the slope-ring
    /// methods and volumetric-rings: 1 - alpha (1 + g) / 2) and the passivity of what it renders
    /// against the device; nullopt when it needs the mesh (mass-spring) and the mesh provider gives
    /// none. Kept while the set and the mesh stay the same (a mass-spring margin measures the model).
    std::optional<StabilityMargin> stabilityMargin() const;
    /// Recomputes the shown margin (call when the mesh provider's mesh changed: a mass-spring
    /// margin depends on it). Records no undo step.
    void refreshStabilityMargin() {
        mMarginOf.reset();
        validate();
    }
    /// Fills the tissue preset combo from the *.json presets in `directory` (name, source as tooltip).
    void setTissuePresetDirectory(const QString& directory);
    /// The tissue and tool the fields show (E in N/mm^2 as the engine wants it).
    ToolContact toolContact() const;
    /// The tissue and tool of `preset`: its own, or the defaults the fields show for a preset without one.
    static ToolContact toolContactOf(const TissuePreset& preset);
    /// Calibrate slopes: slopes, slope limit and spring k for the ring count at the current mesh's
    /// default target vertex (calibrateSlopesFromPunch) as one undoable step, and the error the
    /// calibrated model leaves against the flat punch shown under the button. False (fields
    /// unchanged, the reason shown and returned) without a mesh or with an invalid tissue.
    bool calibrateSlopes(QString* error = nullptr);

signals:
    /// The Apply button, with the fields' preset; only ever emitted with a valid preset, and for a
    /// set beyond its stability margin only after the user confirmed it.
    void applyRequested(const TissuePreset& preset);
    /// The fields went from valid to invalid or back.
    void validityChanged(bool valid);

public slots:
    /// Emits applyRequested if the fields are valid and, beyond the stability margin (a set the
    /// validators allow: any model beyond its passivity; mass-spring beyond its step bound), the
    /// user confirms.
    void apply();
    void openPresetDialog();
    void savePresetDialog();
    /// Sets the fields back to what runs, as one undoable step.
    void revertToRunning();

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// What an edit changed; the undo step's merge key and its text: the model, the haptic rate,
    /// or kFieldEdit0 + the index of the field in mFields.
    enum Edit : int { kModelEdit, kRateEdit, kFieldEdit0 };

    void buildUi();
    /// The fields, in groups, in the scroll area (mScroll).
    void buildFields();
    /// Under the fields: the feedback, the preset files, undo and redo, Apply and the unapplied bar.
    void buildFooter();
    /// Every field: an edit records an undo step and revalidates.
    void connectEdits();
    void retranslateUi();
    QString slopeLabel(int ring) const;
    QString fieldName(int edit) const;
    /// Creates the field's widget (spin box or combo) in `parent`, named after its section and key.
    QWidget* createFieldWidget(PanelField& field, QWidget* parent);
    /// The bound field a problem of `section` names (and its entry), or null.
    std::vector<const PanelField*> fieldsNamedBy(const std::string& section, const Problem& problem) const;
    void watchEdits(QWidget* spin);
    void onEdited(int edit);
    /// Sets every field from `preset` without recording a step (undo/redo, loads, setPreset).
    void showPreset(const TissuePreset& preset);
    TissuePreset presetFromFields() const;
    void updateSlopeRows();
    /// Shows the slope rows or the chosen registry model's own fields, by the combo's model.
    void updateModelRows();
    void validate();
    /// The stability label: the slope-ring loop gain and every model's stability margin
    /// (docs/stability.md). The fields that make a slope-ring set unstable (to mark invalid).
    QList<QWidget*> showStability(const TissuePreset& p);
    void markField(QWidget* field, const char* property, bool on);
    /// Marks the fields (and their labels) that differ from mRunning, and shows or hides the bar.
    void updateUnappliedMarks();
    /// The label of `field`'s row, or null.
    QLabel* rowLabelOf(QWidget* field) const;
    /// The tissue the fields hold, or the shown preset's when they still show it (its source kept).
    /// The tissue the tissue fields show, with this source.
    TissueProperties tissueInFields(const std::string& source) const;
    /// True when the tissue fields show `tissue` (each as its spin box rounds it).
    bool tissueFieldsShow(const TissueProperties& tissue) const;
    std::optional<TissueProperties> tissueFromFields() const;
    /// Problems of E, nu and the tool radius, each naming the field; the fields are added to `invalid`.
    QStringList tissueProblems(QList<QWidget*>* invalid = nullptr) const;
    void syncTissueCombo();
    void updateCalibrationLabel();

    // Fields. mFields: every field of the engine's tables the panel edits (base/params/
    // FieldTable.h), each with its widget; the pointers below are some of those widgets.
    std::vector<PanelField> mFields;
    QComboBox* mModelCombo = nullptr;
    QDoubleSpinBox* mRateSpin = nullptr;
    QSpinBox* mRingSpin = nullptr;
    std::array<QDoubleSpinBox*, kMaxRings + 1> mSlopeSpins{};
    std::array<QLabel*, kMaxRings + 1> mSlopeLabels{};
    QDoubleSpinBox* mContactSpin = nullptr;
    QDoubleSpinBox* mRelaxationSpin = nullptr;
    QDoubleSpinBox* mYoungsSpin = nullptr;
    QDoubleSpinBox* mPoissonSpin = nullptr;
    QDoubleSpinBox* mToolRadiusSpin = nullptr;
    QComboBox* mTissueCombo = nullptr;
    QPushButton* mCalibrateButton = nullptr;
    QLabel* mCalibrationLabel = nullptr;
    /// The registry models' own parameters (mass-spring, radius of influence, FFD): one form whose
    /// rows are those of the chosen model.
    QGroupBox* mModelParamsGroup = nullptr;
    QFormLayout* mModelParamsForm = nullptr;

    // Layout pieces whose text is translated.
    QScrollArea* mScroll = nullptr;
    QLabel* mTitleLabel = nullptr;
    QGroupBox* mModelGroup = nullptr;
    QGroupBox* mTissueGroup = nullptr;
    QFormLayout* mTissueForm = nullptr;
    QGroupBox* mSlopeGroup = nullptr;
    QGroupBox* mSpringGroup = nullptr;
    QGroupBox* mOctreeGroup = nullptr;
    QFormLayout* mModelForm = nullptr;
    QFormLayout* mSlopeForm = nullptr;
    QFormLayout* mSpringForm = nullptr;
    QFormLayout* mOctreeForm = nullptr;

    // Feedback and buttons.
    QLabel* mStabilityLabel = nullptr;
    QLabel* mMessageLabel = nullptr;
    QLabel* mNoteLabel = nullptr;
    QPushButton* mOpenButton = nullptr;
    QPushButton* mSaveButton = nullptr;
    QPushButton* mApplyButton = nullptr;
    /// "Not applied — Apply (Ctrl+Return) / Revert", shown while a field differs from what runs.
    QWidget* mUnappliedBar = nullptr;
    QLabel* mUnappliedLabel = nullptr;
    QPushButton* mRevertButton = nullptr;
    /// "Applied to the running tissue at HH:MM:SS", faded out a few seconds after an Apply.
    QLabel* mAppliedLabel = nullptr;
    QGraphicsOpacityEffect* mAppliedOpacity = nullptr;
    QSequentialAnimationGroup* mAppliedFade = nullptr;

    QUndoStack* mUndoStack = nullptr;
    QAction* mUndoAction = nullptr;
    QAction* mRedoAction = nullptr;
    QAction* mOpenAction = nullptr;
    QAction* mSaveAction = nullptr;

    /// What the fields show; the `before` of the next edit's undo step.
    TissuePreset mShown;
    /// What the haptic loop runs (setPreset, showApplied): the fields that differ are marked.
    TissuePreset mRunning;
    QStringList mUnapplied;
    bool mShowing = false;  ///< fields being set by showPreset: their signals are not edits
    bool mValid = false;
    QStringList mProblems;
    QStringList mFileErrors;  ///< the last failed load/save; cleared by the next edit or file success
    QString mFileNote;        ///< the last successful load/save
    QString mLastDirectory;
    QString mPresetFile;  ///< the file the shown preset was last loaded from or saved to

    MeshProvider mMeshProvider;
    ConfirmFunction mConfirm;
    /// The last margin stabilityMargin() computed, for the set and mesh it was computed for.
    mutable std::optional<TissuePreset> mMarginOf;
    mutable const TissueMesh* mMarginMesh = nullptr;
    mutable std::optional<StabilityMargin> mMargin;
    /// The last calibration: what it set, and its result text (error and notes).
    std::optional<SlopeRingParams> mCalibratedParams;
    QString mCalibrationText;
};

}  // namespace palpate
