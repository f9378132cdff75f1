#pragma once
// The Charts dock's stiffening chart (docs/calibration.md, "Knots from the hyperelastic reference"):
// for the tissue in use, the hyperelastic reference's force against depth beside the linear
// slope-ring model and the model with stiffening knots (those calibrated now, and the preset's own
// when it has any), so the gap a deep press leaves can be read off. The reference is a few seconds
// of FEM, solved off the GUI thread when asked.

#include "engine/accuracy/Calibration.h"
#include "engine/accuracy/StiffeningCalibration.h"

#include <QString>
#include <QStringList>
#include <QWidget>

#include <memory>
#include <optional>

class QChartView;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QThread;

namespace palpate {

class StiffeningPanel final : public QWidget {
    Q_OBJECT
public:
    explicit StiffeningPanel(QWidget* parent = nullptr);
    /// Waits for a running solve (a few seconds at most).
    ~StiffeningPanel() override;

    /// The tissue in use and the slope-ring parameters it runs with (their |m1| and knots).
    /// A new tissue clears the curve: it was solved for another one.
    void setTissue(const ToolContact& contact, const SlopeRingParams& params);
    /// Starts the hyperelastic punch to the depth in the spin box; false while one runs or for a
    /// tissue the calibration refuses (the status says why).
    bool compute();
    bool isRunning() const { return mThread != nullptr; }

    QChartView* chartView() const { return mView; }
    /// The series drawn now, by name (for tests).
    QStringList seriesNames() const;
    const std::optional<StiffeningCalibration>& reference() const { return mReference; }
    QString statusText() const;

signals:
    /// A solve ended (with a curve or with the error in the status).
    void computed(bool ok);
    /// "Apply knots": the computed knots should go into the tissue in use (the main window puts
    /// them into the Parameters panel as one undoable step and applies it).
    void applyKnotsRequested(const StiffeningCalibration& calibration);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void rebuild();
    void setStatus(const QString& text, bool problem = false);
    void onFinished(const std::shared_ptr<StiffeningCalibration>& result, const QString& error);

    QChartView* mView = nullptr;
    QLabel* mDepthLabel = nullptr;
    QDoubleSpinBox* mDepthSpin = nullptr;
    QPushButton* mComputeButton = nullptr;
    QPushButton* mApplyButton = nullptr;
    /// Apply knots is on while a completed curve with knots is shown and nothing runs.
    void updateApplyButton();
    QProgressBar* mBusy = nullptr;
    QLabel* mStatusLabel = nullptr;
    ToolContact mContact;
    SlopeRingParams mParams;
    std::optional<StiffeningCalibration> mReference;  ///< the knots fitted to mParams' |m1|, with the curve
    QThread* mThread = nullptr;
};

}  // namespace palpate
