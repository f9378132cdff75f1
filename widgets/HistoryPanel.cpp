#include "widgets/HistoryPanel.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDateTimeAxis>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPushButton>
#include <QScatterSeries>
#include <QTableWidget>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

namespace palpate {

HistoryPanel::HistoryPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout();
    top->addWidget(new QLabel(tr("Trainee:"), this));
    mTrainees = new QComboBox(this);
    mTrainees->setAccessibleName(tr("Trainee"));
    top->addWidget(mTrainees, 1);
    layout->addLayout(top);

    mChart = new QChart();
    mChart->legend()->setAlignment(Qt::AlignBottom);
    mChart->setMargins(QMargins(4, 4, 4, 4));
    mChartView = new QChartView(mChart, this);
    mChartView->setRenderHint(QPainter::Antialiasing);
    mChartView->setMinimumHeight(220);
    layout->addWidget(mChartView, 2);

    mSummary = new QLabel(this);
    layout->addWidget(mSummary);
    mTable = new QTableWidget(0, 4, this);
    mTable->setHorizontalHeaderLabels({tr("When"), tr("Exercise"), tr("Score"), tr("Time (s)")});
    mTable->verticalHeader()->hide();
    mTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    mTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    mTable->setSelectionMode(QAbstractItemView::SingleSelection);
    mTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    mTable->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    mTable->verticalHeader()->setDefaultSectionSize(mTable->fontMetrics().height() + 6);
    layout->addWidget(mTable, 1);

    auto* buttons = new QHBoxLayout();
    mReport = new QPushButton(tr("Report PDF…"), this);
    mReport->setToolTip(tr("Re-scores the result's recording and writes its PDF report"));
    mReplay = new QPushButton(tr("Replay"), this);
    mReplay->setToolTip(tr("Opens the result's recording in the Recorder"));
    buttons->addWidget(mReport);
    buttons->addWidget(mReplay);
    buttons->addStretch();
    layout->addLayout(buttons);

    connect(mTrainees, &QComboBox::currentIndexChanged, this, [this] { rebuild(); });
    connect(mTable, &QTableWidget::itemSelectionChanged, this, [this] { updateButtons(); });
    connect(mReport, &QPushButton::clicked, this, [this] {
        if (auto r = selectedResult()) emit reportRequested(*r);
    });
    connect(mReplay, &QPushButton::clicked, this, [this] {
        if (auto r = selectedResult()) emit replayRequested(r->recordingPath);
    });
    updateButtons();
}

void HistoryPanel::setDatabase(ResultsDatabase* database) {
    mDatabase = database;
    refresh();
}

qint64 HistoryPanel::traineeId() const {
    return mTrainees->currentIndex() < 0 ? -1 : mTrainees->currentData().toLongLong();
}

void HistoryPanel::setTrainee(qint64 id) {
    const int index = mTrainees->findData(id);
    if (index >= 0 && index != mTrainees->currentIndex()) mTrainees->setCurrentIndex(index);
    else rebuild();
}

void HistoryPanel::refresh() {
    const qint64 keep = traineeId();
    {
        const QSignalBlocker block(mTrainees);
        mTrainees->clear();
        if (mDatabase && mDatabase->isOpen())
            for (const TraineeRecord& t : mDatabase->trainees()) mTrainees->addItem(t.name, t.id);
        const int index = mTrainees->findData(keep);
        mTrainees->setCurrentIndex(index >= 0 ? index : (mTrainees->count() > 0 ? 0 : -1));
    }
    rebuild();
}

void HistoryPanel::rebuild() {
    mResults.clear();
    const qint64 id = traineeId();
    if (mDatabase && mDatabase->isOpen() && id >= 0) mResults = mDatabase->results(id);

    mChart->removeAllSeries();
    for (QAbstractAxis* axis : mChart->axes()) {
        mChart->removeAxis(axis);
        delete axis;
    }
    auto* timeAxis = new QDateTimeAxis();
    timeAxis->setTickCount(3);
    timeAxis->setTitleText(tr("Date"));
    auto* scoreAxis = new QValueAxis();
    scoreAxis->setRange(0.0, 100.0);
    scoreAxis->setTitleText(tr("Score"));
    scoreAxis->setLabelFormat(QStringLiteral("%.0f"));
    mChart->addAxis(timeAxis, Qt::AlignBottom);
    mChart->addAxis(scoreAxis, Qt::AlignLeft);

    // One line per exercise, in the order exercises first appear.
    std::map<QString, std::pair<QLineSeries*, QScatterSeries*>> byExercise;
    qint64 firstMs = 0, lastMs = 0;
    for (const ResultRecord& r : mResults) {
        auto& pair = byExercise[r.exerciseName];
        if (!pair.first) {
            pair.first = new QLineSeries();
            pair.first->setName(r.exerciseName);
            pair.second = new QScatterSeries();
            pair.second->setMarkerSize(8.0);
            mChart->addSeries(pair.first);
            mChart->addSeries(pair.second);
            for (QAbstractSeries* s : {static_cast<QAbstractSeries*>(pair.first), static_cast<QAbstractSeries*>(pair.second)}) {
                s->attachAxis(timeAxis);
                s->attachAxis(scoreAxis);
            }
            pair.second->setColor(pair.first->color());
            // The dots carry no legend entry of their own: the line's names the exercise.
            for (QLegendMarker* m : mChart->legend()->markers(pair.second)) m->setVisible(false);
        }
        const qint64 ms = r.startedUtc.toMSecsSinceEpoch();
        pair.first->append(double(ms), r.score);
        pair.second->append(double(ms), r.score);
        firstMs = firstMs == 0 ? ms : std::min(firstMs, ms);
        lastMs = std::max(lastMs, ms);
    }
    if (!mResults.empty()) {
        // Some room either side, and at least a day, so a single session is not on the frame's edge.
        const qint64 padMs = std::max<qint64>((lastMs - firstMs) / 20, 12 * 3600 * 1000);
        timeAxis->setRange(QDateTime::fromMSecsSinceEpoch(firstMs - padMs), QDateTime::fromMSecsSinceEpoch(lastMs + padMs));
        timeAxis->setFormat(lastMs - firstMs > 2LL * 24 * 3600 * 1000 ? QStringLiteral("dd MMM") : QStringLiteral("hh:mm"));
    }
    mChart->setTitle(mTrainees->currentIndex() >= 0 ? tr("Scores of %1").arg(mTrainees->currentText()) : tr("No trainee yet"));

    mTable->setRowCount(int(mResults.size()));
    // Newest first in the table: that is what one looks for.
    for (int row = 0; row < int(mResults.size()); ++row) {
        const ResultRecord& r = mResults[mResults.size() - 1 - std::size_t(row)];
        auto* when = new QTableWidgetItem(r.startedUtc.toLocalTime().toString(QStringLiteral("yyyy-MM-dd hh:mm")));
        when->setData(Qt::UserRole, r.id);
        mTable->setItem(row, 0, when);
        mTable->setItem(row, 1, new QTableWidgetItem(r.exerciseName));
        auto* score = new QTableWidgetItem(QString::number(r.score, 'f', 0));
        score->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        mTable->setItem(row, 2, score);
        auto* time = new QTableWidgetItem(QString::number(r.durationS, 'f', 1));
        time->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        mTable->setItem(row, 3, time);
    }
    if (mResults.empty()) {
        mSummary->setText(mTrainees->count() == 0 ? tr("No trainees yet: add one in the Exercise dock.")
                                                  : tr("No results yet."));
    } else {
        double best = 0.0, sum = 0.0;
        for (const auto& r : mResults) best = std::max(best, r.score), sum += r.score;
        mSummary->setText(tr("%n session(s); best %1, mean %2", "", int(mResults.size()))
                              .arg(best, 0, 'f', 0)
                              .arg(sum / double(mResults.size()), 0, 'f', 0));
    }
    updateButtons();
}

int HistoryPanel::plottedPointCount() const {
    int n = 0;
    for (QAbstractSeries* s : mChart->series())
        if (auto* line = qobject_cast<QLineSeries*>(s); line && !qobject_cast<QScatterSeries*>(s)) n += line->count();
    return n;
}

std::optional<ResultRecord> HistoryPanel::selectedResult() const {
    const auto rows = mTable->selectionModel()->selectedRows();
    if (rows.isEmpty()) return std::nullopt;
    const qint64 id = mTable->item(rows.front().row(), 0)->data(Qt::UserRole).toLongLong();
    for (const auto& r : mResults)
        if (r.id == id) return r;
    return std::nullopt;
}

void HistoryPanel::selectRow(int row) { mTable->selectRow(row); }

void HistoryPanel::updateButtons() {
    const auto r = selectedResult();
    const bool hasRecording = r && !r->recordingPath.isEmpty() && QFileInfo::exists(r->recordingPath);
    mReport->setEnabled(hasRecording);
    mReplay->setEnabled(hasRecording);
}

}  // namespace palpate
