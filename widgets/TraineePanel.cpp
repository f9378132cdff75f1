#include "widgets/TraineePanel.h"

#include "report/MetricText.h"
#include "engine/exercise/ExerciseKind.h"
#include "widgets/ExerciseText.h"

#include "widgets/ForceGauge.h"
#include "widgets/ScoreCard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QLocale>
#include <QGridLayout>
#include <QScrollBar>
#include <QScrollArea>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace palpate {


TraineePanel::TraineePanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);

    auto* who = new QFormLayout();
    auto* traineeRow = new QHBoxLayout();
    mTrainees = new QComboBox(this);
    mTrainees->setAccessibleName(tr("Trainee"));
    mTrainees->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    auto* newTrainee = new QPushButton(tr("New…"), this);
    newTrainee->setToolTip(tr("Add a trainee"));
    traineeRow->addWidget(mTrainees, 1);
    traineeRow->addWidget(newTrainee);
    who->addRow(tr("Trainee:"), traineeRow);
    auto* exerciseRow = new QHBoxLayout();
    mExercises = new QComboBox(this);
    mExercises->setObjectName(QStringLiteral("exerciseCombo"));
    mExercises->setAccessibleName(tr("Exercise"));
    mExercises->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    auto* openExercise = new QPushButton(tr("Open…"), this);
    openExercise->setToolTip(tr("Choose an exercise file"));
    exerciseRow->addWidget(mExercises, 1);
    exerciseRow->addWidget(openExercise);
    who->addRow(tr("Exercise:"), exerciseRow);
    layout->addLayout(who);
    mExpert = new QCheckBox(tr("E&xpert reference session"), this);
    mExpert->setObjectName(QStringLiteral("expertSessionBox"));
    mExpert->setToolTip(tr("An instructor's session: stored as an expert's, it sets the exercise's pass marks "
                           "(expert mean ± 2 SD) and moves no staircase"));
    layout->addWidget(mExpert);
    mDescription = new QLabel(this);
    mDescription->setObjectName(QStringLiteral("exerciseDescriptionLabel"));
    mDescription->setWordWrap(true);
    layout->addWidget(mDescription);

    // Two by two: four buttons side by side (longer in German) would make the dock wider than a
    // 1280-pixel window leaves it.
    auto* buttons = new QGridLayout();
    mStart = new QPushButton(tr("Start"), this);
    mStart->setToolTip(tr("Start the exercise (F6)"));
    mStop = new QPushButton(tr("Stop"), this);
    mStop->setToolTip(tr("End the exercise now and score it (Shift+F6)"));
    mMark = new QPushButton(tr("Mark"), this);
    mMark->setToolTip(tr("Mark the lump where the tool presses now (M)"));
    buttons->addWidget(mStart, 0, 0);
    buttons->addWidget(mStop, 0, 1);
    mFinish = new QPushButton(tr("Finish"), this);
    mFinish->setObjectName(QStringLiteral("finishExaminationButton"));
    mFinish->setToolTip(tr("End the examination: every lump you found is marked (F7)"));
    mFinish->setVisible(false);
    buttons->addWidget(mMark, 1, 0);
    buttons->addWidget(mFinish, 1, 1);
    layout->addLayout(buttons);
    mMessage = new QLabel(this);
    mMessage->setWordWrap(true);
    layout->addWidget(mMessage);

    mPages = new QStackedWidget(this);
    auto* guidance = new QWidget(mPages);
    auto* g = new QVBoxLayout(guidance);
    g->setContentsMargins(0, 0, 0, 0);
    mInstruction = new QLabel(guidance);
    mInstruction->setWordWrap(true);
    QFont bold = mInstruction->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.15);
    mInstruction->setFont(bold);
    mDetail = new QLabel(guidance);
    mDetail->setWordWrap(true);
    mGauge = new ForceGauge(guidance);
    mProgress = new QProgressBar(guidance);
    mProgress->setRange(0, 100);
    mTime = new QLabel(guidance);
    g->addWidget(mInstruction);
    g->addWidget(mDetail);
    g->addWidget(mGauge);
    g->addWidget(mProgress);
    g->addWidget(mTime);
    g->addStretch();
    mCard = new ScoreCard(mPages);
    mPages->addWidget(guidance);
    mPages->addWidget(mCard);
    layout->addWidget(mPages, 1);

    connect(newTrainee, &QPushButton::clicked, this, &TraineePanel::newTraineeRequested);
    connect(openExercise, &QPushButton::clicked, this, &TraineePanel::openExerciseRequested);
    connect(mStart, &QPushButton::clicked, this, &TraineePanel::startRequested);
    connect(mStop, &QPushButton::clicked, this, &TraineePanel::stopRequested);
    connect(mMark, &QPushButton::clicked, this, &TraineePanel::markRequested);
    connect(mFinish, &QPushButton::clicked, this, &TraineePanel::finishRequested);
    connect(mTrainees, &QComboBox::currentIndexChanged, this, [this] { emit traineeChanged(traineeId()); });
    connect(mExercises, &QComboBox::currentIndexChanged, this, [this] { emit exerciseChanged(exercisePath()); });
    connect(mExercises, &QComboBox::activated, this, &TraineePanel::exercisePicked);
    setState(State::Idle);
}

bool TraineePanel::event(QEvent* event) {
    const bool handled = QWidget::event(event);
    if (event->type() == QEvent::LayoutRequest) {
        // The scroll area's viewport is this panel's parent, the area its grandparent.
        if (auto* scroll = parentWidget() ? qobject_cast<QScrollArea*>(parentWidget()->parentWidget()) : nullptr) {
            const int scrollBarPx = scroll->verticalScrollBar()->sizeHint().width();
            const int needPx = minimumSizeHint().width() + scrollBarPx;
            if (scroll->minimumWidth() < needPx) scroll->setMinimumWidth(needPx);
        }
    }
    return handled;
}

void TraineePanel::setTrainees(const QList<QPair<QString, qint64>>& trainees, qint64 selectId) {
    const QSignalBlocker block(mTrainees);
    const qint64 keep = selectId >= 0 ? selectId : traineeId();
    mTrainees->clear();
    for (const auto& [name, id] : trainees) mTrainees->addItem(name, id);
    const int index = mTrainees->findData(keep);
    mTrainees->setCurrentIndex(index >= 0 ? index : (mTrainees->count() ? 0 : -1));
    emit traineeChanged(traineeId());
}

qint64 TraineePanel::traineeId() const { return mTrainees->currentIndex() < 0 ? -1 : mTrainees->currentData().toLongLong(); }
QString TraineePanel::traineeName() const { return mTrainees->currentIndex() < 0 ? QString() : mTrainees->currentText(); }

QString TraineePanel::distinctTitle(const QString& title, const QString& path) const {
    // Two exercises of one name (a shipped one and a copy imported from a bundle) are told apart
    // by their folder.
    if (mExercises->findText(title, Qt::MatchExactly) < 0) return title;
    return tr("%1 (in %2)").arg(title, QFileInfo(path).absoluteDir().dirName());
}

void TraineePanel::setExercises(const QList<QPair<QString, QString>>& exercises, const QString& select) {
    {
        const QSignalBlocker block(mExercises);
        mExercises->clear();
        for (const auto& [title, path] : exercises) {
            mExercises->addItem(distinctTitle(title, path), path);
            mExercises->setItemData(mExercises->count() - 1, path, Qt::ToolTipRole);
        }
        const int index = mExercises->findData(select);
        mExercises->setCurrentIndex(index >= 0 ? index : (mExercises->count() ? 0 : -1));
    }
    emit exerciseChanged(exercisePath());
}

void TraineePanel::addExercise(const QString& title, const QString& path) {
    int index = mExercises->findData(path);
    if (index < 0) {
        const QSignalBlocker block(mExercises);
        mExercises->addItem(distinctTitle(title, path), path);
        index = mExercises->count() - 1;
        mExercises->setItemData(index, path, Qt::ToolTipRole);
    }
    if (index == mExercises->currentIndex()) emit exerciseChanged(path);
    else mExercises->setCurrentIndex(index);
}

void TraineePanel::showRunningExercise(const QString& title, const QString& path) {
    if (!path.isEmpty()) {
        addExercise(title, path);
        return;
    }
    // One entry stands for whatever unsaved exercise is being tried: it has no file to start.
    const QString text = tr("%1 (preview, not saved)").arg(title);
    int index = mExercises->findData(QString());
    const QSignalBlocker block(mExercises);
    if (index < 0) {
        mExercises->addItem(text, QString());
        index = mExercises->count() - 1;
    }
    mExercises->setItemText(index, text);
    mExercises->setCurrentIndex(index);
}

QString TraineePanel::exerciseTitle() const { return mExercises->currentText(); }

QList<QPair<QString, QString>> TraineePanel::exercises() const {
    QList<QPair<QString, QString>> out;
    for (int i = 0; i < mExercises->count(); ++i) out.append({mExercises->itemText(i), mExercises->itemData(i).toString()});
    return out;
}

QString TraineePanel::exercisePath() const { return mExercises->currentIndex() < 0 ? QString() : mExercises->currentData().toString(); }

void TraineePanel::setExerciseDescription(const QString& text) { mDescription->setText(text); }

void TraineePanel::setFinishShown(bool shown) { mFinish->setVisible(shown); }

void TraineePanel::setGaugeLevel(double level) { mGauge->setLevel(level); }

bool TraineePanel::expertSession() const { return mExpert->isChecked(); }

void TraineePanel::setMessage(const QString& text) { mMessage->setText(text); }

void TraineePanel::setState(State state) {
    mState = state;
    const bool running = state == State::Starting || state == State::Running;
    mStart->setEnabled(!running && mExercises->count() > 0);
    mStop->setEnabled(running);
    mMark->setEnabled(state == State::Running);
    mFinish->setEnabled(state == State::Running);
    mTrainees->setEnabled(!running);
    mExpert->setEnabled(!running);
    mExercises->setEnabled(!running);
    mPages->setCurrentIndex(state == State::Finished ? 1 : 0);
    // The gauge and the progress mean something only while an exercise runs.
    mGauge->setVisible(running);
    mProgress->setVisible(running);
    if (state == State::Idle) {
        mInstruction->setText(tr("Choose a trainee and an exercise, then Start (F6)."));
        mDetail->clear();
        mTime->clear();
        mProgress->setValue(0);
        mGauge->setForceN(0.0);
    } else if (state == State::Starting) {
        mInstruction->setText(tr("Starting…"));
    }
}

QString TraineePanel::instructionText() const { return mInstruction->text(); }
QString TraineePanel::timeText() const { return mTime->text(); }
QString TraineePanel::detailText() const { return mDetail->text(); }

void TraineePanel::showGuidance(const Exercise& exercise, const ScoreGuidance& guidance, double scoreSoFar) {
    mGauge->setExcessiveN(exercise.excessiveForceN);
    mGauge->setFullScaleN(std::max(4.0, exercise.excessiveForceN * 1.2));
    mGauge->setForceN(guidance.forceN);
    const GuidanceView view = exerciseKind(exercise.type).guidance(exercise, guidance);
    mGauge->setWindow(view.windowMinN, view.windowMaxN);
    mGauge->setExamineAtN(view.examineAtN);
    mMark->setToolTip(view.markTip.empty() ? tr("Mark the lump where the tool presses now (M)") : exerciseText(view.markTip));
    const QString instruction = exerciseText(view.instruction);
    QStringList details;
    for (const ViewText& part : view.detail) details << exerciseText(part);
    const QString detail = details.join(QStringLiteral(" · "));
    const int progressPercent = int(std::lround(100.0 * view.progress));
    if (!view.progressFormat.empty()) mProgress->setFormat(exerciseText(view.progressFormat));
    mInstruction->setText(instruction);
    mDetail->setText(detail);
    mProgress->setValue(std::clamp(progressPercent, 0, 100));
    // Where the score so far would give the answer away (which marks hit), it waits for Finish.
    const QString timeLeft = QLocale().toString(std::max(0.0, guidance.timeLeftS), 'f', 0);
    mTime->setText(showsLiveScore(exercise)
                       ? tr("Time left %1 s · score so far %2").arg(timeLeft, scoreText(scoreSoFar))
                       : tr("Time left %1 s · score at Finish").arg(timeLeft));
}

}  // namespace palpate
