#pragma once
// File > Import Mesh… (docs/meshes.md, "Importing a mesh"): a mesh from another tool, previewed as
// importMesh (engine/meshimport/MeshImport.h) sees it with the options chosen here (the file's
// unit, repair, remeshing), then written as a Palpate mesh in mm. The preview runs on a worker
// thread (a repair or a remesh of a large mesh takes seconds) and is re-run, debounced, whenever an
// option changes; Cancel stops it through importMesh's progress callback.

#include "engine/meshimport/MeshImport.h"

#include <QDialog>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <thread>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTextBrowser;

namespace palpate {

class MeshImportDialog final : public QDialog {
    Q_OBJECT
public:
    /// How long the options must rest before the preview re-runs (typing a scale, say).
    static constexpr int kDebounceMs = 300;

    explicit MeshImportDialog(QWidget* parent = nullptr);
    /// Cancels a preview in progress and waits for its thread.
    ~MeshImportDialog() override;

    /// The file to import; previews it (first in mm, then in the unit suggested, if any).
    void setInputPath(const QString& path);
    QString inputPath() const;
    /// The unit the file is read in (the combo box; a factor is "Scale…" and its spin box).
    void setUnit(const MeshUnit& unit);
    MeshUnit unit() const;
    /// What the preview and Import run with.
    MeshImportDef options() const;

    /// A preview is running or waiting for its debounce.
    bool previewBusy() const;
    /// A preview's worker is running (past the debounce).
    bool previewRunning() const { return mJob != nullptr; }
    /// Tests: processes events until the preview settles (or `timeoutMs`); false on timeout.
    bool waitForPreview(int timeoutMs = 60000);
    /// The last finished preview (null before the first).
    const MeshImportResult* result() const { return mResult.get(); }
    /// The unit suggested for this file and why (from its first preview), if any.
    const std::optional<UnitSuggestion>& suggestion() const { return mSuggestion; }
    /// The preview's size line ("152 × 98 × 80 mm · file in cm"), problems and roundness, as shown.
    QString sizeText() const;
    QString previewText() const;
    QString reasonText() const;
    bool importEnabled() const;

    /// NAME-imported.off beside the input.
    QString defaultOutputPath() const;
    /// Writes the previewed mesh to `outputPath` (atomically) and emits imported(). Refuses the
    /// input itself, a preview that is not finished or has no mesh. "" or the error (also shown).
    QString importTo(const QString& outputPath);

signals:
    /// A mesh was written to `outputPath` (in mm): the window opens it.
    void imported(const QString& outputPath);

protected:
    /// Shown again after a close that cancelled a preview: previews again.
    void showEvent(QShowEvent* event) override;

private:
    struct Job;
    void buildUi();
    /// The file, its unit, the repair and the remeshing.
    QFormLayout* buildOptionsForm();
    /// The preview: size, counts, the import's report and the ring roundness before and after.
    QGroupBox* buildPreview();
    /// A changed option starts a new preview (after the debounce).
    void connectOptions();
    void browse();
    void chooseOutput();
    void optionsChanged();
    void startPreview();
    void cancelPreview();
    void previewFinished(std::shared_ptr<Job> job);
    void showProgress(double fraction, const QString& stage);
    void showResult();
    void showIdle(const QString& message);
    void updateEnabled();
    void joinWorker();

    QLineEdit* mInput = nullptr;
    QComboBox* mUnitCombo = nullptr;
    QDoubleSpinBox* mScale = nullptr;
    QLabel* mReason = nullptr;
    QCheckBox* mRepair = nullptr;
    QComboBox* mKeep = nullptr;
    QCheckBox* mFillHoles = nullptr;
    QCheckBox* mRemesh = nullptr;
    QDoubleSpinBox* mEdge = nullptr;
    QProgressBar* mProgress = nullptr;
    QLabel* mStage = nullptr;
    QPushButton* mCancel = nullptr;
    QLabel* mSize = nullptr;
    QLabel* mCounts = nullptr;
    QTextBrowser* mReport = nullptr;
    QTableWidget* mRoundness = nullptr;
    QPushButton* mImport = nullptr;

    QTimer mDebounce;
    std::thread mWorker;
    std::shared_ptr<Job> mJob;  // the running preview (null when none)
    bool mRerun = false;        // options changed while it ran: run again when it ends
    std::unique_ptr<MeshImportResult> mResult;
    std::optional<UnitSuggestion> mSuggestion;
    bool mUnitChosen = false;     // the user (or the suggestion) set the unit for this file
    bool mEdgeEdited = false;     // the user set the edge length: no longer the suggested one
    bool mSettingUp = false;      // setting widgets from code: not an option change
    bool mLastCancelled = false;  // the last preview was cancelled (its result has no mesh)
};

}  // namespace palpate
