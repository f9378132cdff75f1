#pragma once
// The trainee's Exercise dock: who (pick or create a trainee), what (an exercise: the shipped
// examples or a file), Start / Stop / Mark, and while it runs the guidance: what to do now, a
// force gauge with the window, the hold progress, the path covered, the time left. When it ends
// the score card takes the guidance's place. The panel only shows and asks; the window's
// ExerciseController runs the session.

#include "engine/exercise/Exercise.h"
#include "engine/exercise/ScoreReport.h"

#include <QPair>
#include <QString>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QStackedWidget;

namespace palpate {

class ForceGauge;
class ScoreCard;

class TraineePanel final : public QWidget {
    Q_OBJECT
public:
    enum class State { Idle, Starting, Running, Finished };

    explicit TraineePanel(QWidget* parent = nullptr);

    /// The trainees to choose from (name, id), selecting `selectId` if present.
    void setTrainees(const QList<QPair<QString, qint64>>& trainees, qint64 selectId = -1);
    qint64 traineeId() const;
    QString traineeName() const;
    /// The exercises to choose from (title, path); `select` is selected if present.
    void setExercises(const QList<QPair<QString, QString>>& exercises, const QString& select = {});
    /// Adds (or selects, if listed) one exercise file.
    void addExercise(const QString& title, const QString& path);
    /// Shows the exercise that runs in the combo: its file's entry (added if missing), or, for an
    /// exercise that has no file (the editor's unsaved preview), one entry marked as a preview.
    void showRunningExercise(const QString& title, const QString& path);
    QString exercisePath() const;
    /// The combo's title of the selected entry.
    QString exerciseTitle() const;
    /// The listed exercises (title, path), in the combo's order.
    QList<QPair<QString, QString>> exercises() const;
    void setExerciseDescription(const QString& text);

    void setState(State state);
    State state() const { return mState; }
    /// The running session's guidance and score so far.
    void showGuidance(const Exercise& exercise, const ScoreGuidance& guidance, double scoreSoFar);
    /// What the trainee is told (the guidance's first line).
    QString instructionText() const;
    /// "Time left 42 s · score so far 63", or "… · score at Finish" where the score waits.
    QString timeText() const;
    /// The guidance's detail line ("0 finding(s) marked · in contact · …").
    QString detailText() const;
    void setMessage(const QString& text);

    ForceGauge* forceGauge() const { return mGauge; }
    ScoreCard* scoreCard() const { return mCard; }
    QPushButton* startButton() const { return mStart; }
    QPushButton* stopButton() const { return mStop; }
    QPushButton* markButton() const { return mMark; }
    /// Detect lumps: ends the examination (shown only for that type).
    QPushButton* finishButton() const { return mFinish; }
    /// Shows Finish: for an exercise the trainee ends (detect lumps).
    void setFinishShown(bool shown);
    /// The force gauge's level for this session (fading guidance): 1 shown .. 0 hidden.
    void setGaugeLevel(double level);
    /// "Expert reference session": the next session is stored as an instructor's, which sets the
    /// exercise's pass marks (docs/scoring.md, "Proficiency") and moves no staircase.
    bool expertSession() const;
    QCheckBox* expertBox() const { return mExpert; }
    ForceGauge* gauge() const { return mGauge; }
    QProgressBar* progressBar() const { return mProgress; }

signals:
    void newTraineeRequested();
    void openExerciseRequested();
    void startRequested();
    void stopRequested();
    void markRequested();
    void finishRequested();
    void traineeChanged(qint64 traineeId);
    void exerciseChanged(const QString& path);
    /// The trainee chose an exercise in the combo (not a programmatic selection).
    void exercisePicked();

protected:
    /// Whenever the panel's layout changes (a score card with its table, a longer instruction), a
    /// scroll area holding it is kept at least as wide as the panel needs: it wraps, never clips.
    bool event(QEvent* event) override;

private:
    /// `title`, or "title (in FOLDER)" when the list holds an exercise of that title already.
    QString distinctTitle(const QString& title, const QString& path) const;
    State mState = State::Idle;
    QComboBox* mTrainees = nullptr;
    QComboBox* mExercises = nullptr;
    QLabel* mDescription = nullptr;
    QPushButton* mStart = nullptr;
    QPushButton* mStop = nullptr;
    QPushButton* mMark = nullptr;
    QPushButton* mFinish = nullptr;
    QCheckBox* mExpert = nullptr;
    QStackedWidget* mPages = nullptr;
    QLabel* mInstruction = nullptr;
    QLabel* mDetail = nullptr;
    ForceGauge* mGauge = nullptr;
    QProgressBar* mProgress = nullptr;
    QLabel* mTime = nullptr;
    QLabel* mMessage = nullptr;
    ScoreCard* mCard = nullptr;
};

}  // namespace palpate
