#include "widgets/ScoreCard.h"

#include "report/MetricText.h"
#include "report/PalpationSummaryText.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace palpate {

ScoreCard::ScoreCard(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    mTitle = new QLabel(this);
    mTitle->setWordWrap(true);
    mScore = new QLabel(this);
    QFont big = mScore->font();
    big.setPointSizeF(big.pointSizeF() * 2.6);
    big.setBold(true);
    mScore->setFont(big);
    mScore->setAlignment(Qt::AlignCenter);
    // "Stopped: 34.5 points so far, not a score" in a large font is wider than the dock: it wraps
    // rather than widen the window past the screen.
    mScore->setWordWrap(true);
    mScore->setAccessibleName(tr("Score"));
    mTable = new QTableWidget(0, 4, this);
    mTable->setHorizontalHeaderLabels({tr("Metric"), tr("Value"), tr("Sub-score"), tr("Points")});
    mTable->verticalHeader()->hide();
    mTable->verticalHeader()->setDefaultSectionSize(mTable->fontMetrics().height() + 6);
    // A long metric name wraps onto a second line in a narrow dock instead of being cut off: rows
    // take the height their names need at the column's width.
    mTable->setWordWrap(true);
    mTable->setTextElideMode(Qt::ElideNone);
    mTable->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // A column's new width (the dock resized) does not re-measure the rows by itself.
    connect(mTable->horizontalHeader(), &QHeaderView::sectionResized, mTable, [this](int column) {
        if (column == 0) mTable->resizeRowsToContents();
    });
    mTable->setMinimumHeight(8 * (mTable->fontMetrics().height() + 6));
    mTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    mTable->setSelectionMode(QAbstractItemView::NoSelection);
    mTable->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    for (int c = 1; c < 4; ++c) mTable->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    mPalpation = new QLabel(this);
    mPalpation->setObjectName(QStringLiteral("palpationSummary"));
    mPalpation->setWordWrap(true);
    mWarnings = new QLabel(this);
    mWarnings->setWordWrap(true);
    mWarnings->setStyleSheet(QStringLiteral("color: #c07000"));
    auto* buttons = new QHBoxLayout();
    mExportPdf = new QPushButton(tr("Export PDF…"), this);
    mHistory = new QPushButton(tr("History…"), this);
    buttons->addWidget(mExportPdf);
    buttons->addWidget(mHistory);
    buttons->addStretch();
    layout->addWidget(mTitle);
    layout->addWidget(mScore);
    layout->addWidget(mPalpation);
    layout->addWidget(mTable, 1);
    layout->addWidget(mWarnings);
    layout->addLayout(buttons);
    connect(mExportPdf, &QPushButton::clicked, this, &ScoreCard::exportPdfRequested);
    connect(mHistory, &QPushButton::clicked, this, &ScoreCard::historyRequested);
    clear();
}

void ScoreCard::clear() {
    mHasReport = false;
    mReport = ScoreReport{};
    mTitle->setText(tr("No score yet: run an exercise."));
    mScore->setText(QStringLiteral("–"));
    mTable->setRowCount(0);
    mPalpation->clear();
    mPalpation->hide();
    mWarnings->clear();
    mWarnings->hide();
    mExportPdf->setEnabled(false);
}

QString ScoreCard::titleText() const { return mTitle->text(); }

QString ScoreCard::scoreText() const { return mScore->text(); }

QString ScoreCard::palpationText() const { return mPalpation->text(); }

void ScoreCard::fitNameColumn() {
    // The name column never narrower than its longest word (wrapping cannot split a word), the
    // others as wide as their contents: the table asks for that much width, the dock gives it.
    const QFontMetrics metrics = mTable->fontMetrics();
    const int cellMarginPx = 2 * (mTable->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, mTable) + 1) + 4;
    int wordPx = metrics.horizontalAdvance(mTable->horizontalHeaderItem(0)->text());
    for (int row = 0; row < mTable->rowCount(); ++row)
        for (const QString& word : mTable->item(row, 0)->text().split(QLatin1Char(' '), Qt::SkipEmptyParts))
            wordPx = std::max(wordPx, metrics.horizontalAdvance(word));
    mTable->resizeColumnsToContents();
    int widthPx = wordPx + cellMarginPx + 2 * mTable->frameWidth();
    for (int c = 1; c < mTable->columnCount(); ++c) widthPx += mTable->horizontalHeader()->sectionSize(c);
    mTable->setMinimumWidth(widthPx);
    mTable->resizeRowsToContents();
}

void ScoreCard::setReport(const ScoreReport& report, const QString& traineeName) {
    mReport = report;
    mHasReport = true;
    const QString exercise = QString::fromStdString(report.exerciseName);
    QString state = report.guidance.completed ? tr("completed")
                    : report.guidance.timeUp  ? tr("time up")
                                              : tr("stopped");
    mTitle->setText(traineeName.isEmpty() ? tr("%1 (%2)").arg(exercise, state)
                                          : tr("%1: %2 (%3)").arg(traineeName, exercise, state));
    // A stopped session has no score (History and the results leave it out too): what it earned
    // so far is said as that.
    const bool stopped = !report.guidance.completed && !report.guidance.timeUp;
    mScore->setText(stopped
                        ? tr("Stopped: %1 points so far, not a score").arg(palpate::scoreText(report.score, locale()))
                        : tr("%1 / 100").arg(palpate::scoreText(report.score, locale())));
    mTable->setRowCount(int(report.metrics.size()));
    for (int row = 0; row < int(report.metrics.size()); ++row) {
        const MetricResult& line = report.metrics[std::size_t(row)];
        auto* name = new QTableWidgetItem(metricNameText(line.metric));
        name->setToolTip(metricNameText(line.metric) + QStringLiteral(": ") + metricDescriptionText(line.metric));
        mTable->setItem(row, 0, name);
        mTable->setItem(row, 1, new QTableWidgetItem(line.measured ? localMetricValueText(line.metric, line.value) : QStringLiteral("-")));
        mTable->setItem(row, 2,
                        new QTableWidgetItem(line.weight > 0.0 ? QStringLiteral("%1 %").arg(
                                                                     locale().toString(100.0 * line.subScore, 'f', 0))
                                                               : tr("not scored")));
        mTable->setItem(row, 3, new QTableWidgetItem(palpate::scoreText(line.contribution, locale())));
        for (int c = 1; c < 4; ++c) mTable->item(row, c)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    fitNameColumn();
    QStringList palpation = palpationSummaryLines(report);
    if (const QString work = workDoneText(report.workDone); !work.isEmpty()) palpation.prepend(work);
    mPalpation->setText(palpation.join(QLatin1Char('\n')));
    mPalpation->setVisible(!palpation.isEmpty());
    QStringList warnings;
    for (const auto& w : report.warnings) warnings << QString::fromStdString(w);
    mWarnings->setText(warnings.join(QLatin1Char('\n')));
    mWarnings->setVisible(!warnings.isEmpty());
    mExportPdf->setEnabled(true);
}

}  // namespace palpate
