#pragma once
// The Charts dock's content: the speed-vs-accuracy chart with the configuration in use highlighted,
// a sweep that runs off the GUI thread (progress, cancel) and the sweep CSV, so that a committed
// sweep (docs/bench/sweep.csv) is shown without measuring again. Measuring a sweep takes minutes;
// the window stays responsive and the haptic loop is not touched (the sweep builds its own models).
// On a second tab, the feel chart (FeelPanel: force step against tick cost, from the feel bench's
// CSV, docs/bench/feel.csv); on a third, the stiffening chart (StiffeningPanel: the hyperelastic
// reference's force against depth beside the linear and the knotted model).

#include "engine/models/slopering/SlopeRingMethod.h"
#include "engine/scene/TissuePreset.h"
#include "engine/accuracy/AccuracySweep.h"

#include <QElapsedTimer>
#include <QString>
#include <QWidget>

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QThread;

namespace palpate {

struct OrganSweepDef;
class FeelPanel;
class SpeedAccuracyChart;
class StiffeningPanel;

class ChartsPanel final : public QWidget {
    Q_OBJECT
public:
    explicit ChartsPanel(QWidget* parent = nullptr);
    /// Cancels a running sweep and waits for it (at most one model measurement).
    ~ChartsPanel() override;

    SpeedAccuracyChart* chart() const { return mChart; }
    /// The feel chart on the second tab (its own CSV and default file).
    FeelPanel* feelPanel() const { return mFeelPanel; }
    /// The stiffening chart on the third tab (the tissue in use, solved when asked).
    StiffeningPanel* stiffeningPanel() const { return mStiffeningPanel; }
    /// The three tabs: the sweep's chart (0), the feel chart (1), the stiffening chart (2).
    QTabWidget* tabs() const { return mTabs; }
    const std::vector<SweepPoint>& points() const;

    /// The configuration in use: highlighted on the chart (its series on `meshVertices` vertices),
    /// and what a sweep started here is calibrated with (the tissue, the tool, damping and k_c).
    void setCurrentConfiguration(const TissuePreset& applied, const ToolContact& contact, std::size_t meshVertices);

    /// What Run sweep starts: the full sweep, or with Quick the sphere at 1442 and 3970 vertices
    /// with up to 4 rings; calibrated for the configuration in use.
    SweepDef sweepDefinition() const;
    /// Starts `def` on a worker thread; progress and the points come back by queued calls. Its
    /// progress and cancel members are the panel's own. False (nothing started) while one runs.
    bool startSweep(const SweepDef& def);
    /// The same for the sweep against the organ's FEM (docs/accuracy.md, "The organ's own shape").
    bool startOrganSweep(const OrganSweepDef& def);
    bool isRunning() const { return mThread != nullptr; }

    /// Reads a sweep CSV (and its tissue from FILE.json next to it, when there is one). On failure
    /// the chart keeps what it showed and the error names the file, line and column.
    bool loadCsv(const QString& path, QString* error = nullptr);
    /// Writes the points as CSV, and FILE.json with the tissue when this panel measured them.
    bool saveCsv(const QString& path, QString* error = nullptr);
    /// Loaded when the panel is first seen (in a dock: its tab in front), if it exists and nothing is shown yet.
    void setDefaultCsv(const QString& path) { mDefaultCsv = path; }
    /// Loads the default CSV (and the feel panel's) the first time this is called (when the panel
    /// can first be seen).
    void loadDefaultCsvOnce();

    /// The line under the chart: what is shown, the run's progress or the last problem.
    QString statusText() const;

signals:
    /// A run ended: all points measured, or cancelled (the points measured until then).
    void sweepFinished(bool cancelled, int pointCount);
    /// A run stopped on an error (a bad definition, a mesh that could not be generated).
    void sweepFailed(const QString& error);

public slots:
    /// The Run sweep button: startSweep(sweepDefinition()), or startOrganSweep when the reference
    /// box says organ FEM (Quick: the stomach at 1442 vertices).
    void runSweep();
    /// Asks a running sweep to stop after the model it is measuring.
    void cancelSweep();
    void openCsvDialog();
    void saveCsvDialog();

protected:
    void showEvent(QShowEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    /// "1 point", "12 points" (no plural translation is loaded for English).
    static QString pointsText(int count);
    /// "Stomach", or "Stomach, thin site" for a point of the organ sweep.
    static QString shapeItemText(GeneratedShape shape, const std::string& site);
    void showPoints(std::vector<SweepPoint> points, const std::optional<ToolContact>& contact);
    void updateShapeCombo();
    void updateHighlight();
    void updateButtons();
    void setStatus(const QString& text, bool problem = false);
    void onProgress(double fraction, const QString& line);
    /// Runs `run` on `requested` (with the panel's progress and cancel) on a worker thread.
    bool startWorker(const SweepDef& requested, std::function<SweepResult(const SweepDef&)> run);
    void onFinished(const SweepResult& result, const QString& error);

    SpeedAccuracyChart* mChart = nullptr;
    FeelPanel* mFeelPanel = nullptr;
    StiffeningPanel* mStiffeningPanel = nullptr;
    QTabWidget* mTabs = nullptr;
    QPushButton* mRunButton = nullptr;
    QCheckBox* mQuickCheck = nullptr;
    QComboBox* mReferenceCombo = nullptr;
    QPushButton* mCancelButton = nullptr;
    QPushButton* mOpenButton = nullptr;
    QPushButton* mSaveButton = nullptr;
    QLabel* mShapeLabel = nullptr;
    QComboBox* mShapeCombo = nullptr;
    QProgressBar* mProgress = nullptr;
    QLabel* mStatusLabel = nullptr;
    QLabel* mCurrentLabel = nullptr;
    QLabel* mLegendLabel = nullptr;

    TissuePreset mApplied;
    ToolContact mContact;
    std::size_t mMeshVertices = 0;

    QThread* mThread = nullptr;
    std::atomic<bool> mCancel{false};
    SweepDef mRunningDef;  ///< the definition of the run in progress or of the points shown
    bool mShownFromRun = false;
    std::optional<ToolContact> mShownContact;
    QElapsedTimer mRunClock;
    QString mDefaultCsv;
    bool mDefaultTried = false;
    bool mWatchingDock = false;
    QString mLastDirectory;
};

}  // namespace palpate
