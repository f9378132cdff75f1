#pragma once
// A trainee's history: their scores session by session, one line per exercise (Qt Charts), a stopped
// session marked but not scored, and the results as a table below. A result with a recording can be exported as a PDF report or replayed: the
// window re-scores the recording (the same score bit for bit) or opens it in the Recorder.

#include "results/LearningCurveData.h"
#include "results/ResultsDatabase.h"

#include <QHash>
#include <QWidget>

#include <optional>
#include <vector>

class QChart;
class QChartView;
class QComboBox;
class QDialog;
class QLabel;
class QLabel;
class QLineSeries;
class QPushButton;
class QTableWidget;

namespace palpate {

class HistoryPanel final : public QWidget {
    Q_OBJECT
public:
    explicit HistoryPanel(QWidget* parent = nullptr);

    /// Not owned; null shows nothing. Reads the trainees and the selected one's results.
    void setDatabase(ResultsDatabase* database);
    /// Shows this trainee (by id); -1 shows the first one.
    void setTrainee(qint64 traineeId);
    qint64 traineeId() const;
    /// Reads the database again (after a new result).
    void refresh();

    /// The results shown, oldest first.
    const std::vector<ResultRecord>& results() const { return mResults; }
    /// The chart's series (one line per exercise, one dashed mark per stopped session) and the
    /// scored points the lines hold, for tests.
    QChart* chart() const { return mChart; }
    int plottedPointCount() const;
    /// The stopped sessions' marks on the chart (not points of a line).
    int stoppedMarkCount() const { return int(mStoppedSeries.size()); }
    /// The line under the chart: sessions, best and mean of the scored ones, stopped ones.
    QString summaryText() const;
    QTableWidget* table() const { return mTable; }
    QComboBox* traineeBox() const { return mTrainees; }
    /// The result selected in the table (nullopt: none).
    std::optional<ResultRecord> selectedResult() const;
    void selectRow(int row);
    /// The selected result's exercise as a learning curve against the experts' pass marks
    /// (docs/scoring.md, "Proficiency"), in a window; "" or why it cannot be drawn.
    QString showLearningCurve();
    /// The curve window's picture (null before the first curve), for tests.
    QDialog* learningCurveDialog() const { return mCurveDialog; }
    QPushButton* learningCurveButton() const { return mCurve; }

signals:
    void reportRequested(const palpate::ResultRecord& result);
    void replayRequested(const QString& recordingPath);

private:
    void rebuild();
    /// The line under the table: sessions, their dates, the best and the mean per exercise.
    QString sessionsSummary(int sessions) const;
    void updateButtons();
    /// The result's exercise as the user reads it: its file's name in their language when the
    /// file still opens and is that exercise, else the name it is stored under.
    QString shownName(const ResultRecord& r) const;

    ResultsDatabase* mDatabase = nullptr;
    std::vector<ResultRecord> mResults;
    mutable QHash<QString, QString> mShownNames;  ///< exercise file -> shown name ("" none), per rebuild
    QComboBox* mTrainees = nullptr;
    QChart* mChart = nullptr;
    QChartView* mChartView = nullptr;
    QTableWidget* mTable = nullptr;
    QLabel* mSummary = nullptr;
    std::vector<QLineSeries*> mStoppedSeries;  ///< owned by mChart
    QPushButton* mReport = nullptr;
    QPushButton* mReplay = nullptr;
    QPushButton* mCurve = nullptr;
    QDialog* mCurveDialog = nullptr;
    QLabel* mCurveHeading = nullptr;
    QComboBox* mCurveMetric = nullptr;
    QWidget* mCurveChart = nullptr;  ///< the chart shown (replaced when another metric is chosen)
    LearningCurveData mCurveData;    ///< score first, then the exercise's metrics
    void showCurveMetric(int index);
};

}  // namespace palpate
