#pragma once
// The score card a trainee sees when an exercise ends: the score out of 100, who and what, the
// breakdown (each metric's value, sub-score, weight and points) and any warnings. It only shows;
// the buttons ask the window to export the PDF report or to open the trainee's history.

#include "engine/exercise/ScoreReport.h"

#include <QString>
#include <QStringList>
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace palpate {

class ScoreCard final : public QWidget {
    Q_OBJECT
public:
    explicit ScoreCard(QWidget* parent = nullptr);

    void setReport(const ScoreReport& report, const QString& traineeName);
    void clear();
    bool hasReport() const { return mHasReport; }
    const ScoreReport& report() const { return mReport; }

    /// The texts shown, for tests and the accessibility tree.
    QString scoreText() const;
    /// "Ada: Press three targets (completed)", the exercise named in the user's language.
    QString titleText() const;
    QTableWidget* breakdownTable() const { return mTable; }
    QPushButton* exportPdfButton() const { return mExportPdf; }
    QPushButton* historyButton() const { return mHistory; }
    /// The palpation lines shown (detection, coverage, force by phase, feedback); "" for others.
    QString palpationText() const;

signals:
    void exportPdfRequested();
    void historyRequested();

private:
    /// The table as wide as its longest metric word and its value columns need.
    void fitNameColumn();

    ScoreReport mReport;
    bool mHasReport = false;
    QLabel* mScore = nullptr;
    QLabel* mTitle = nullptr;
    QLabel* mPalpation = nullptr;
    QLabel* mWarnings = nullptr;
    QTableWidget* mTable = nullptr;
    QPushButton* mExportPdf = nullptr;
    QPushButton* mHistory = nullptr;
};

}  // namespace palpate
