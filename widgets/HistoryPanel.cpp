#include "widgets/HistoryPanel.h"

#include "report/ExerciseWords.h"
#include "report/MetricText.h"
#include "results/LearningCurve.h"
#include "report/LearningCurveImage.h"
#include "engine/exercise/ExerciseFile.h"
#include "widgets/GuardedLoad.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDialog>
#include <QMessageBox>
#include <QPixmap>
#include <QTemporaryDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
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
    mChart->legend()->setShowToolTips(true);  // an entry elided in a narrow dock shows its name on hover
    mChart->setMargins(QMargins(4, 4, 4, 4));
    mChartView = new QChartView(mChart, this);
    mChartView->setRenderHint(QPainter::Antialiasing);
    mChartView->setMinimumHeight(220);
    layout->addWidget(mChartView, 2);

    mSummary = new QLabel(this);
    mSummary->setWordWrap(true);
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
    mCurve = new QPushButton(tr("Learning Curve…"), this);
    mCurve->setObjectName(QStringLiteral("learningCurveButton"));
    mCurve->setToolTip(tr("The trainee's sessions of the selected result's exercise against the experts' pass marks"));
    buttons->addWidget(mReport);
    buttons->addWidget(mReplay);
    buttons->addWidget(mCurve);
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
    connect(mCurve, &QPushButton::clicked, this, [this] {
        if (const QString problem = showLearningCurve(); !problem.isEmpty())
            QMessageBox::information(this, tr("Learning curve"), problem);
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

QString HistoryPanel::shownName(const ResultRecord& r) const {
    if (r.exercisePath.isEmpty()) return r.exerciseName;
    auto it = mShownNames.find(r.exercisePath);
    if (it == mShownNames.end()) {
        const std::string path = r.exercisePath.toStdString();
        const auto loaded = guardedLoad(path, [&] { return loadExercise(path); });
        // Results are grouped under the stored name: a file since renamed names another exercise.
        const bool same = loaded.exercise && QString::fromStdString(loaded.exercise->name) == r.exerciseName;
        it = mShownNames.insert(r.exercisePath, same ? shownExerciseName(*loaded.exercise) : QString());
    }
    return it->isEmpty() ? r.exerciseName : *it;
}

void HistoryPanel::rebuild() {
    mResults.clear();
    mShownNames.clear();
    const qint64 id = traineeId();
    if (mDatabase && mDatabase->isOpen() && id >= 0) mResults = mDatabase->results(id);

    mChart->removeAllSeries();
    for (QAbstractAxis* axis : mChart->axes()) {
        mChart->removeAxis(axis);
        delete axis;
    }
    // The x axis counts sessions, oldest first: sessions a minute apart and sessions a month apart
    // are equally far apart, and the dates are in the table (and the axis title gives their span).
    const int sessions = int(mResults.size());
    auto* sessionAxis = new QValueAxis();
    sessionAxis->setObjectName(QStringLiteral("sessionAxis"));
    sessionAxis->setRange(0.5, std::max(sessions, 1) + 0.5);
    sessionAxis->setLabelFormat(QStringLiteral("%d"));
    sessionAxis->setTickType(QValueAxis::TicksDynamic);
    sessionAxis->setTickAnchor(1.0);
    // A label per session up to 8, then every 2nd, 5th, 10th, ...: never more than about 8 labels.
    double step = 1.0;
    for (const double s : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0})
        if (sessions / s <= 8.0) {
            step = s;
            break;
        }
    sessionAxis->setTickInterval(step);
    sessionAxis->setMinorTickCount(0);
    sessionAxis->setTitleText(tr("Session"));
    auto* scoreAxis = new QValueAxis();
    scoreAxis->setRange(0.0, 100.0);
    scoreAxis->setTitleText(tr("Score"));
    scoreAxis->setLabelFormat(QStringLiteral("%.0f"));
    mChart->addAxis(sessionAxis, Qt::AlignBottom);
    mChart->addAxis(scoreAxis, Qt::AlignLeft);
    auto attach = [&](QAbstractSeries* s) {
        mChart->addSeries(s);
        s->attachAxis(sessionAxis);
        s->attachAxis(scoreAxis);
    };

    // One line per exercise, in the order exercises first appear; a stopped session is no point of
    // it (its partial score is not a score) but a grey dashed mark across the chart at its place.
    std::map<QString, std::pair<QLineSeries*, QScatterSeries*>> byExercise;
    mStoppedSeries.clear();
    for (int i = 0; i < sessions; ++i) {
        const ResultRecord& r = mResults[std::size_t(i)];
        const double x = i + 1;
        if (!isScored(r.outcome)) {
            auto* mark = new QLineSeries();
            mark->setName(tr("Stopped"));
            QPen pen(QColor(150, 150, 150));
            pen.setStyle(Qt::DashLine);
            pen.setWidthF(1.5);
            mark->setPen(pen);
            mark->append(x, 0.0);
            mark->append(x, 100.0);
            attach(mark);
            // One legend entry for all of them.
            if (!mStoppedSeries.empty())
                for (QLegendMarker* m : mChart->legend()->markers(mark)) m->setVisible(false);
            mStoppedSeries.push_back(mark);
            continue;
        }
        auto& pair = byExercise[r.exerciseName];
        if (!pair.first) {
            pair.first = new QLineSeries();
            pair.first->setName(shownName(r));
            pair.second = new QScatterSeries();
            pair.second->setMarkerSize(8.0);
            attach(pair.first);
            attach(pair.second);
            pair.second->setColor(pair.first->color());
            // The dots carry no legend entry of their own: the line's names the exercise.
            for (QLegendMarker* m : mChart->legend()->markers(pair.second)) m->setVisible(false);
        }
        pair.first->append(x, r.score);
        pair.second->append(x, r.score);
    }
    mChart->setTitle(mTrainees->currentIndex() >= 0 ? tr("Scores of %1").arg(mTrainees->currentText()) : tr("No trainee yet"));

    mTable->setRowCount(sessions);
    // Newest first in the table: that is what one looks for.
    for (int row = 0; row < sessions; ++row) {
        const ResultRecord& r = mResults[mResults.size() - 1 - std::size_t(row)];
        auto* when = new QTableWidgetItem(r.startedUtc.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")));
        when->setData(Qt::UserRole, r.id);
        mTable->setItem(row, 0, when);
        const QString name = shownName(r);
        auto* exercise = new QTableWidgetItem(name);
        exercise->setToolTip(name);  // the column elides a long name at the dock's width
        mTable->setItem(row, 1, exercise);
        auto* score = new QTableWidgetItem(scoreText(r.score, locale()));
        score->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (!isScored(r.outcome)) {
            score->setText(tr("stopped"));
            score->setForeground(QColor(120, 120, 120));
            QFont italic = score->font();
            italic.setItalic(true);
            score->setFont(italic);
            score->setToolTip(tr("Stopped before the end: %1 points so far, not a score (not in the best or "
                                 "the mean)")
                                  .arg(scoreText(r.score, locale())));
        } else if (r.outcome == ResultOutcome::TimeUp) {
            score->setToolTip(tr("The time limit passed before the task was done"));
        }
        mTable->setItem(row, 2, score);
        auto* time = new QTableWidgetItem(locale().toString(r.durationS, 'f', 1));
        time->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        mTable->setItem(row, 3, time);
    }
    mSummary->setText(sessionsSummary(sessions));
    updateButtons();
}

QString HistoryPanel::sessionsSummary(int sessions) const {
    if (mResults.empty())
        return mTrainees->count() == 0 ? tr("No trainees yet: add one in the Exercise dock.") : tr("No results yet.");
    {
        // Best and mean per exercise: scores of different exercises do not mix.
        struct Tally {
            QString exercise;  ///< the stored name: what groups them
            QString shown;
            double best = 0.0, sum = 0.0;
            int scored = 0;
        };
        std::vector<Tally> tallies;
        int scored = 0;
        for (const auto& r : mResults) {
            if (!isScored(r.outcome)) continue;
            auto it = std::find_if(tallies.begin(), tallies.end(),
                                   [&](const Tally& t) { return t.exercise == r.exerciseName; });
            if (it == tallies.end()) it = tallies.insert(tallies.end(), Tally{r.exerciseName, shownName(r)});
            it->best = std::max(it->best, r.score);
            it->sum += r.score;
            ++it->scored;
            ++scored;
        }
        const int stopped = sessions - scored;
        // When: the first and the last session, on a 24-hour clock (the day once when it is one day).
        const QDateTime first = mResults.front().startedUtc.toLocalTime();
        const QDateTime last = mResults.back().startedUtc.toLocalTime();
        const QString day = QStringLiteral("yyyy-MM-dd"), time = QStringLiteral("HH:mm");
        const QString when = sessions == 1 ? first.toString(day + QLatin1Char(' ') + time)
                             : first.date() == last.date()
                                 ? tr("%1, %2 to %3").arg(first.toString(day), first.toString(time), last.toString(time))
                                 : tr("%1 to %2").arg(first.toString(day + QLatin1Char(' ') + time),
                                                      last.toString(day + QLatin1Char(' ') + time));
        QStringList perExercise;
        for (const Tally& t : tallies)
            perExercise << tr("%1: best %2, mean %3")
                               .arg(t.shown, scoreText(t.best, locale()),
                                    scoreText(t.sum / double(t.scored), locale()));
        // No plural translation is loaded for English: the two forms are spelled out.
        const QString count = sessions == 1 ? tr("1 session (%1)").arg(when)
                                            : tr("%1 sessions (%2)").arg(sessions).arg(when);
        QString text = scored > 0 ? count + QStringLiteral("; ") + perExercise.join(QStringLiteral("; "))
                                  : tr("%n session(s) (%1); none scored", "", sessions).arg(when);
        if (stopped > 0) text += QLatin1Char(' ') + tr("(%n stopped, not counted)", "", stopped);
        return text;
    }
}

int HistoryPanel::plottedPointCount() const {
    int n = 0;
    for (QAbstractSeries* s : mChart->series())
        if (auto* line = qobject_cast<QLineSeries*>(s); line && !qobject_cast<QScatterSeries*>(s) &&
                                                        std::find(mStoppedSeries.begin(), mStoppedSeries.end(), line) ==
                                                            mStoppedSeries.end())
            n += line->count();
    return n;
}

QString HistoryPanel::summaryText() const { return mSummary->text(); }

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
    mCurve->setEnabled(r && !r->exercisePath.isEmpty());
}

QString HistoryPanel::showLearningCurve() {
    const auto r = selectedResult();
    if (!r || !mDatabase) return tr("Select a session first.");
    if (r->exercisePath.isEmpty()) return tr("This session names no exercise file to draw the curve of.");
    // The exercise's rubric says which way each metric is better.
    const auto loaded = guardedLoad(r->exercisePath.toStdString(), [&] { return loadExercise(r->exercisePath.toStdString()); });
    if (!loaded.exercise) return tr("%1: %2").arg(r->exercisePath, QString::fromStdString(loaded.error()));
    QString trainee = mTrainees->currentText();
    const LearningCurve curve = learningCurve(*mDatabase, r->traineeId, *loaded.exercise, r->exercisePath,
                                              trainee + QStringLiteral(": ") + QString::fromStdString(loaded.exercise->name));
    if (curve.sessions.empty()) return tr("%1 has no scored sessions of this exercise to draw.").arg(trainee);
    // One metric at a time, large enough to read: the score first, then the exercise's metrics.
    mCurveData = curve.chart;
    LearningCurveMetric score;
    score.key = QLatin1String(kLearningCurveScoreKey);
    for (const ResultRecord& s : curve.sessions) score.values.push_back(s.score);
    mCurveData.metrics.insert(mCurveData.metrics.begin(), score);
    if (!mCurveDialog) {
        mCurveDialog = new QDialog(this);
        mCurveDialog->setObjectName(QStringLiteral("learningCurveDialog"));
        mCurveDialog->setWindowTitle(tr("Learning curve"));
        mCurveDialog->resize(760, 520);
        auto* layout = new QVBoxLayout(mCurveDialog);
        mCurveHeading = new QLabel(mCurveDialog);
        mCurveHeading->setWordWrap(true);
        auto* row = new QHBoxLayout;
        auto* label = new QLabel(tr("&Show:"), mCurveDialog);
        mCurveMetric = new QComboBox(mCurveDialog);
        mCurveMetric->setObjectName(QStringLiteral("curveMetricCombo"));
        label->setBuddy(mCurveMetric);
        row->addWidget(label);
        row->addWidget(mCurveMetric, 1);
        layout->addWidget(mCurveHeading);
        layout->addLayout(row);
        connect(mCurveMetric, &QComboBox::currentIndexChanged, this, &HistoryPanel::showCurveMetric);
    }
    QString heading = mCurveData.title;
    if (mCurveData.proficientAtSession)
        heading += QLatin1Char(' ') + tr("- proficient at session %1").arg(*mCurveData.proficientAtSession);
    else if (!mCurveData.passed.empty()) heading += QLatin1Char(' ') + tr("- not yet proficient");
    else heading += QLatin1Char(' ') + tr("- no expert standard yet: the pass marks come from experts' sessions");
    mCurveHeading->setText(heading);
    {
        const QSignalBlocker block(mCurveMetric);
        mCurveMetric->clear();
        for (const LearningCurveMetric& m : mCurveData.metrics) mCurveMetric->addItem(learningCurveMetricTitle(m));
        mCurveMetric->setCurrentIndex(0);
    }
    showCurveMetric(0);
    mCurveDialog->show();
    mCurveDialog->raise();
    return {};
}

void HistoryPanel::showCurveMetric(int index) {
    if (!mCurveDialog || index < 0 || index >= int(mCurveData.metrics.size())) return;
    delete mCurveChart;
    mCurveChart = learningCurveMetricChart(mCurveData.metrics[std::size_t(index)], mCurveData.passed, 1.0,
                                           mCurveDialog);
    mCurveChart->setObjectName(QStringLiteral("curveChart"));
    mCurveChart->setMinimumHeight(360);
    mCurveDialog->layout()->addWidget(mCurveChart);
}

}  // namespace palpate
