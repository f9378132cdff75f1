#pragma once
// The Charts dock's feel chart (report/FeelChart.h): every model's force step against its tick
// cost, from a feel bench CSV (palpate-cli bench feel --csv; the committed docs/bench/feel.csv is
// shown when the dock is first seen, without measuring again: the bench runs the real haptic loop
// beside busy processes, which is the command line's job, not the window's).

#include "engine/bench/FeelBench.h"

#include <QString>
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;

namespace palpate {

class FeelChart;

class FeelPanel final : public QWidget {
    Q_OBJECT
public:
    explicit FeelPanel(QWidget* parent = nullptr);

    FeelChart* chart() const { return mChart; }
    const std::vector<FeelRow>& rows() const;

    /// Reads a feel bench CSV. On failure the chart keeps what it showed and the error names the
    /// file, line and column.
    bool loadCsv(const QString& path, QString* error = nullptr);
    void setDefaultCsv(const QString& path) { mDefaultCsv = path; }
    /// Loads the default CSV the first time this is called (when the panel can first be seen).
    void loadDefaultCsvOnce();
    /// The line under the chart: what is shown, or the last problem.
    QString statusText() const;

public slots:
    void openCsvDialog();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void setStatus(const QString& text, bool problem = false);
    QString summaryText() const;

    FeelChart* mChart = nullptr;
    QLabel* mLegendLabel = nullptr;
    QLabel* mAxisLabel = nullptr;
    QComboBox* mAxisCombo = nullptr;
    QPushButton* mOpenButton = nullptr;
    QLabel* mStatusLabel = nullptr;
    QString mDefaultCsv;
    QString mShownPath;
    bool mDefaultTried = false;
    QString mLastDirectory;
};

}  // namespace palpate
