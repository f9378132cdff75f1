#pragma once
// The parameters panel: every value of a tissue preset an instructor tunes (model, rings, slopes as
// magnitudes in mm/N, springs, contact, octree, haptic rate), validated live with the engine's own
// validators, with the slope model's loop gain and stability margin, undo/redo through a
// QUndoStack, and preset files. It only edits a TissuePreset: the main window decides what Apply
// does (e.g. HapticLoop::setParams). A plain QWidget, meant for a QDockWidget.

#include "engine/Rings.h"
#include "engine/TissuePreset.h"

#include <QString>
#include <QStringList>
#include <QWidget>

#include <array>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QPushButton;
class QScrollArea;
class QSpinBox;
class QUndoStack;

namespace palpate {

class ParameterPanel final : public QWidget {
    Q_OBJECT
public:
    /// The haptic rate a preset may ask for (HapticLoopDef's range).
    static constexpr double kMinRateHz = 10.0;
    static constexpr double kMaxRateHz = 10000.0;
    /// The paper's slope range is (0, 1) mm/N; above it a slope needs a raised slope limit.
    static constexpr double kPaperSlopeMaxMmPerN = 1.0;

    explicit ParameterPanel(QWidget* parent = nullptr);
    ~ParameterPanel() override;

    /// The preset the fields show (name, description and tissue properties carried through).
    TissuePreset preset() const;
    /// Shows `preset` as a new baseline: no undo entry, and the undo history is cleared (its steps
    /// belong to the preset that was shown before).
    void setPreset(const TissuePreset& preset);

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

signals:
    /// The Apply button, with the fields' preset; only ever emitted with a valid preset.
    void applyRequested(const TissuePreset& preset);
    /// The fields went from valid to invalid or back.
    void validityChanged(bool valid);

public slots:
    /// Emits applyRequested if the fields are valid.
    void apply();
    void openPresetDialog();
    void savePresetDialog();

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// What an edit changed; the undo step's merge key and its text.
    enum Field : int {
        kModel,
        kRingCount,
        kSlopeLimit,
        kSpringStiffness,
        kDampingRatio,
        kContactStiffness,
        kForceRelaxation,
        kVertexMass,
        kOctreeDepth,
        kLeafCapacity,
        kHapticRate,
        kSlope0,  // kSlope0 + r: the slope of ring r (r = 0: the touched vertex)
    };

    void buildUi();
    void retranslateUi();
    QString slopeLabel(int ring) const;
    QString fieldName(int field) const;
    void watchEdits(QWidget* spin);
    void onEdited(int field);
    /// Sets every field from `preset` without recording a step (undo/redo, loads, setPreset).
    void showPreset(const TissuePreset& preset);
    TissuePreset presetFromFields() const;
    void updateSlopeRows();
    void validate();
    void markField(QWidget* field, const char* property, bool on);

    // Fields.
    QComboBox* mModelCombo = nullptr;
    QDoubleSpinBox* mRateSpin = nullptr;
    QSpinBox* mRingSpin = nullptr;
    std::array<QDoubleSpinBox*, kMaxRings + 1> mSlopeSpins{};
    std::array<QLabel*, kMaxRings + 1> mSlopeLabels{};
    QDoubleSpinBox* mSlopeLimitSpin = nullptr;
    QDoubleSpinBox* mSpringSpin = nullptr;
    QDoubleSpinBox* mDampingSpin = nullptr;
    QDoubleSpinBox* mContactSpin = nullptr;
    QDoubleSpinBox* mRelaxationSpin = nullptr;
    QDoubleSpinBox* mMassSpin = nullptr;
    QSpinBox* mDepthSpin = nullptr;
    QSpinBox* mLeafSpin = nullptr;

    // Layout pieces whose text is translated.
    QScrollArea* mScroll = nullptr;
    QLabel* mTitleLabel = nullptr;
    QGroupBox* mModelGroup = nullptr;
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

    QUndoStack* mUndoStack = nullptr;
    QAction* mUndoAction = nullptr;
    QAction* mRedoAction = nullptr;
    QAction* mOpenAction = nullptr;
    QAction* mSaveAction = nullptr;

    /// What the fields show; the `before` of the next edit's undo step.
    TissuePreset mShown;
    bool mShowing = false;  ///< fields being set by showPreset: their signals are not edits
    bool mValid = false;
    QStringList mProblems;
    QStringList mFileErrors;  ///< the last failed load/save; cleared by the next edit or file success
    QString mFileNote;        ///< the last successful load/save
    QString mLastDirectory;
};

}  // namespace palpate
