#include "widgets/RecorderPanel.h"

#include "results/HandOff.h"

#include "engine/replay/RecordingPlayer.h"
#include "engine/record/RecordingReader.h"
#include "widgets/RecordingTimeline.h"

#include <QApplication>
#include <QBoxLayout>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGroupBox>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QThread>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

const char* const kFolderKey = "recorder/folder";
const char* const kOpenFolderKey = "recorder/openFolder";
const QString kSuffix = QStringLiteral(".palprec");
/// A frame's stepping stops after this much time: playback falls behind rather than freeze.
constexpr qint64 kFrameBudgetNs = 12'000'000;
/// After this long a worker job shows a busy cursor and the progress bar.
constexpr int kBusyFeedbackMs = 200;
/// Ticks the worker replays between looks at the target and the cancel flag.
constexpr std::uint64_t kSeekBatchTicks = 256;
/// Longest frame step: after a stall (a dialog, a busy machine) playback does not leap ahead.
constexpr double kMaxFrameS = 0.1;
constexpr int kProgressSteps = 1000;
const QString kErrorStyle = QStringLiteral("color: #c62828; font-weight: bold;");
const QString kWarningStyle = QStringLiteral("color: #8d6e00;");
const QString kGoodStyle = QStringLiteral("color: #2e7d32; font-weight: bold;");

QLabel* textLabel(QWidget* parent, const char* objectName, bool wrap = true) {
    auto* label = new QLabel(parent);
    label->setObjectName(QLatin1String(objectName));
    label->setTextFormat(Qt::PlainText);
    label->setWordWrap(wrap);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

QPushButton* button(QWidget* parent, const char* objectName, const QString& text, const QString& toolTip) {
    auto* b = new QPushButton(text, parent);
    b->setObjectName(QLatin1String(objectName));
    b->setToolTip(toolTip);
    return b;
}

/// Why a recording cannot be played, naming the file; "" when it can be tried.
QString openProblem(const RecordingReader& reader, const QString& path) {
    if (!reader.fileError().empty()) {
        const QString error = QString::fromStdString(reader.fileError());
        return error.contains(path) ? error : path + QStringLiteral(": ") + error;
    }
    if (!reader.headerOk()) {
        const QString why = QString::fromStdString(reader.headerError());
        if (reader.summary().chunks == 0)
            return why.contains(QStringLiteral("not a Palpate recording"))
                       ? QStringLiteral("%1: %2").arg(path, why)
                       : RecorderPanel::tr("%1 is not a Palpate recording (%2)").arg(path, why);
        return RecorderPanel::tr("%1: the header is damaged (%2); %3 chunks were recovered, but a replay needs the header")
            .arg(path, why)
            .arg(reader.summary().chunks);
    }
    return {};
}

/// What was recovered and lost from a damaged file, or "" for an intact one.
QString damageWarning(const RecordingReader& reader, const QString& path) {
    const RecordingSummary& s = reader.summary();
    QStringList lost;
    if (s.damagedRegions > 0)
        lost << RecorderPanel::tr("%1 damaged region(s) skipped (%2 bytes)").arg(s.damagedRegions).arg(s.damagedBytes);
    if (s.lostTicks > 0) lost << RecorderPanel::tr("%1 ticks lost").arg(s.lostTicks);
    if (s.droppedTicks > 0)
        lost << RecorderPanel::tr("%1 ticks dropped while recording (%2 gap(s))").arg(s.droppedTicks).arg(s.gaps);
    if (s.hashMismatches > 0) lost << RecorderPanel::tr("%1 chunk(s) whose hash disagrees with their ticks").arg(s.hashMismatches);
    if (!s.closedCleanly) lost << RecorderPanel::tr("not closed cleanly (the program ended while recording)");
    if (lost.isEmpty()) return {};
    const bool damaged = s.damagedRegions > 0 || s.lostTicks > 0 || s.hashMismatches > 0;
    return (damaged ? RecorderPanel::tr("%1 is damaged. Recovered %2 chunks (%3 ticks); lost: %4.")
                    : RecorderPanel::tr("%1 is incomplete. Recovered %2 chunks (%3 ticks); lost: %4."))
        .arg(QFileInfo(path).fileName())
        .arg(s.chunks)
        .arg(s.ticks)
        .arg(lost.join(QStringLiteral("; ")));
}

/// The damaged regions one by one (the warning's tooltip).
QString damageDetails(const RecordingReader& reader) {
    QStringList lines;
    for (const DamagedRegion& d : reader.damage()) {
        QString line = RecorderPanel::tr("offset %1, %2 bytes: %3").arg(d.offset).arg(d.bytes).arg(QString::fromStdString(d.reason));
        if (d.ticksKnown) line += RecorderPanel::tr(" (ticks %1 to %2)").arg(d.firstTick).arg(d.firstTick + d.count - 1);
        lines << line;
        if (lines.size() == 20) {
            lines << RecorderPanel::tr("…");
            break;
        }
    }
    return lines.join(QLatin1Char('\n'));
}

RecordingTimeline::Marker markerOf(const RecordingEvent& e) {
    using Kind = RecordingTimeline::MarkerKind;
    const QString text = QString::fromStdString(e.text);
    switch (e.kind) {
        case EventKind::Mark: return {e.tick, Kind::Mark, RecorderPanel::tr("Mark: %1").arg(text)};
        case EventKind::Exercise: return {e.tick, Kind::Mark, RecorderPanel::tr("Exercise event: %1").arg(text)};
        case EventKind::ParamsApplied: return {e.tick, Kind::Parameters, RecorderPanel::tr("Parameters applied")};
        case EventKind::SceneChanged:
            if (!e.scene)
                return {e.tick, Kind::Problem, RecorderPanel::tr("Scene changed without a description (the replay stops here)")};
            return {e.tick, Kind::Scene,
                    RecorderPanel::tr("Scene changed: %1").arg(QFileInfo(QString::fromStdString(e.scene->meshPath)).fileName())};
        case EventKind::DeviceChanged:
            return {e.tick, Kind::Device,
                    RecorderPanel::tr("Device changed: %1")
                        .arg(e.device ? QString::fromStdString(e.device->uri) : RecorderPanel::tr("(not described)"))};
        case EventKind::DeviceState:
            return {e.tick, Kind::Device,
                    RecorderPanel::tr("Device state: %1").arg(QString::fromLatin1(deviceStateName(e.deviceState)))};
        case EventKind::Paused: return {e.tick, Kind::Pause, RecorderPanel::tr("Paused")};
        case EventKind::Resumed: return {e.tick, Kind::Pause, RecorderPanel::tr("Resumed")};
        case EventKind::CommandsLost:
            return {e.tick, Kind::Problem,
                    RecorderPanel::tr("%1 command(s) lost: the replay may differ from here").arg(e.count)};
        case EventKind::Divergence:
            return {e.tick, Kind::Problem,
                    RecorderPanel::tr("Divergence guard fired: %1").arg(QString::fromLatin1(divergenceKindName(e.divergence)))};
    }
    return {e.tick, Kind::Problem, text};
}

}  // namespace

/// What the worker hands back after opening a file.
struct RecorderPanel::OpenResult {
    QString path;
    std::shared_ptr<RecordingReader> reader;
    std::unique_ptr<RecordingPlayer> player;
    QString error;
    QString warning;
    QString warningDetails;
};

RecorderPanel::RecorderPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("recorderPanel"));
    const QString saved = QSettings().value(kFolderKey).toString();
    mFolder = saved.isEmpty() ? defaultRecordingFolder() : saved;

    auto* recordBox = new QGroupBox(tr("Recording"), this);
    recordBox->setObjectName(QStringLiteral("recordingBox"));
    buildRecordingBox(recordBox);
    auto* playbackBox = new QGroupBox(tr("Playback"), this);
    playbackBox->setObjectName(QStringLiteral("playbackBox"));
    buildPlaybackBox(playbackBox);

    auto* layout = new QBoxLayout(QBoxLayout::LeftToRight, this);
    layout->setObjectName(QStringLiteral("recorderLayout"));
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(recordBox, 2);
    layout->addWidget(playbackBox, 5);

    // Space on a button presses it (not the window's live Pause); on the timeline it plays.
    for (QWidget* w : findChildren<QPushButton*>()) w->installEventFilter(this);
    mSpeedCombo->installEventFilter(this);
    installEventFilter(this);  // the layout direction follows the dock's shape

    mFrameTimer.setTimerType(Qt::PreciseTimer);
    mFrameTimer.setInterval(kFrameIntervalMs);
    connect(&mFrameTimer, &QTimer::timeout, this, &RecorderPanel::onFrameTimer);
    mProgressTimer.setInterval(50);
    connect(&mProgressTimer, &QTimer::timeout, this, &RecorderPanel::pollProgress);

    setRecordingStopped(QString());
    updateVerdict();
    updateTimeLabels();
    updateButtons();
}

RecorderPanel::~RecorderPanel() {
    mCancel.store(true);
    if (mWorker) {
        mWorker->wait();
        delete mWorker;
        mWorker = nullptr;
    }
    if (mBusyCursor) QApplication::restoreOverrideCursor();
    mPlayer.reset();  // before the reader it reads
    mReader.reset();
}

void RecorderPanel::buildRecordingBox(QWidget* box) {
    mRecordButton = button(box, "recordButton", tr("● &Record"), QString());
    mStopButton = button(box, "stopRecordingButton", tr("■ S&top"),
                         tr("Stop recording and close the file cleanly (Ctrl+Shift+R)"));
    mFolderButton = button(box, "recordingFolderButton", tr("Folder…"), QString());
    mRecordStatus = textLabel(box, "recordingStatus");
    mRecordError = textLabel(box, "recordingError");
    mRecordError->setStyleSheet(kErrorStyle);
    mRecordError->hide();
    mMarkEdit = new QLineEdit(box);
    mMarkEdit->setObjectName(QStringLiteral("markEdit"));
    mMarkEdit->setPlaceholderText(tr("Mark text (optional)"));
    mMarkEdit->setToolTip(tr("The text of the next mark; Return adds it"));
    mMarkEdit->setClearButtonEnabled(true);
    mMarkButton = button(box, "markButton", tr("&Mark"), tr("Add a mark at the current tick of the recording (M)"));

    connect(mRecordButton, &QPushButton::clicked, this, &RecorderPanel::recordRequested);
    connect(mStopButton, &QPushButton::clicked, this, &RecorderPanel::stopRequested);
    connect(mFolderButton, &QPushButton::clicked, this, &RecorderPanel::chooseFolder);
    connect(mMarkButton, &QPushButton::clicked, this, [this] { emit markRequested(nextMarkText()); });
    connect(mMarkEdit, &QLineEdit::returnPressed, this, [this] {
        if (mRecording) emit markRequested(nextMarkText());
    });

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(mRecordButton);
    buttons->addWidget(mStopButton);
    buttons->addStretch(1);
    buttons->addWidget(mFolderButton);
    auto* mark = new QHBoxLayout;
    mark->addWidget(mMarkEdit, 1);
    mark->addWidget(mMarkButton);
    auto* layout = new QVBoxLayout(box);
    layout->addLayout(buttons);
    layout->addWidget(mRecordStatus);
    layout->addWidget(mRecordError);
    layout->addLayout(mark);
    layout->addStretch(1);
}

void RecorderPanel::buildPlaybackBox(QWidget* box) {
    mOpenButton = button(box, "openRecordingButton", tr("&Open…"),
                         tr("Open a recording to play it back (the live session pauses while it plays)"));
    mFileLabel = textLabel(box, "playbackFile", false);
    mFileLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    mLiveButton = button(box, "backToLiveButton", tr("Back to &Live"),
                         tr("Close the recording and resume the live session"));
    mPlaybackError = textLabel(box, "playbackError");
    mPlaybackError->setStyleSheet(kErrorStyle);
    mPlaybackError->hide();
    mPlaybackWarning = textLabel(box, "playbackWarning");
    mPlaybackWarning->setStyleSheet(kWarningStyle);
    mPlaybackWarning->hide();
    mTimeline = new RecordingTimeline(box);
    mPlayButton = button(box, "playRecordingButton", tr("▶ &Play"),
                         tr("Play or pause the recording (Space while the timeline has the focus)"));
    mSpeedCombo = new QComboBox(box);
    mSpeedCombo->setObjectName(QStringLiteral("playbackSpeed"));
    mSpeedCombo->setToolTip(tr("Playback speed"));
    mSpeedCombo->setAccessibleName(tr("Playback speed"));
    for (const double s : kSpeeds) mSpeedCombo->addItem(tr("%1×").arg(s), s);
    mSpeedCombo->setCurrentIndex(2);  // 1×
    mTimeLabel = textLabel(box, "playbackTime", false);
    mTimeLabel->setToolTip(tr("Current time / length of the recording (loop clock)"));
    mProgress = new QProgressBar(box);
    mProgress->setObjectName(QStringLiteral("playbackProgress"));
    mProgress->setRange(0, kProgressSteps);
    mProgress->setMaximumWidth(160);
    mProgress->setToolTip(tr("Replaying from the start to reach that tick"));
    mProgress->hide();
    mVerdictLabel = textLabel(box, "replayVerdict");

    connect(mOpenButton, &QPushButton::clicked, this, &RecorderPanel::chooseRecording);
    connect(mLiveButton, &QPushButton::clicked, this, &RecorderPanel::backToLiveRequested);
    connect(mPlayButton, &QPushButton::clicked, this, [this] { setPlaying(!mPlaying); });
    connect(mTimeline, &RecordingTimeline::playPauseRequested, this, [this] { setPlaying(!mPlaying); });
    connect(mTimeline, &RecordingTimeline::scrubbed, this, [this](quint64 tick) { seekTo(tick); });

    auto* file = new QHBoxLayout;
    file->addWidget(mOpenButton);
    file->addWidget(mFileLabel, 1);
    file->addWidget(mLiveButton);
    auto* transport = new QHBoxLayout;
    transport->addWidget(mPlayButton);
    transport->addWidget(mSpeedCombo);
    transport->addWidget(mTimeLabel, 1);
    transport->addWidget(mProgress);
    auto* layout = new QVBoxLayout(box);
    layout->addLayout(file);
    layout->addWidget(mPlaybackError);
    layout->addWidget(mPlaybackWarning);
    layout->addWidget(mTimeline);
    layout->addLayout(transport);
    layout->addWidget(mVerdictLabel);
    layout->addStretch(1);
}

bool RecorderPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride && watched != this) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Space && key->modifiers() == Qt::NoModifier) {
            event->accept();  // the focused button or combo gets its Space, not the window's Pause
            return true;
        }
    }
    if (watched == this && event->type() == QEvent::Resize) {
        // Side by side under the viewport; stacked when the dock is narrow (docked at a side).
        if (auto* box = qobject_cast<QBoxLayout*>(layout()))
            box->setDirection(width() >= 640 ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
    }
    return QWidget::eventFilter(watched, event);
}

// --- recording -------------------------------------------------------------------------------

QString RecorderPanel::defaultRecordingFolder() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("recordings"));
}

void RecorderPanel::setRecordingFolder(const QString& folder, bool persist) {
    mFolder = folder.isEmpty() ? defaultRecordingFolder() : QDir::cleanPath(folder);
    if (persist) QSettings().setValue(kFolderKey, mFolder);
    if (!mRecording) setRecordingStopped(QString());
    updateButtons();
}

void RecorderPanel::chooseFolder() {
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Folder for New Recordings"), mFolder);
    if (!folder.isEmpty()) setRecordingFolder(folder, true);
}

QString RecorderPanel::newRecordingPath(QString* error) const {
    QDir dir(mFolder);
    if (!dir.mkpath(QStringLiteral("."))) {
        if (error) *error = tr("%1: the recordings folder cannot be created").arg(mFolder);
        return {};
    }
    const QString stem = QStringLiteral("palpate-%1").arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    QString path = dir.filePath(stem + kSuffix);
    for (int n = 2; QFileInfo::exists(path); ++n) path = dir.filePath(QStringLiteral("%1-%2%3").arg(stem).arg(n).arg(kSuffix));
    return path;
}

QString RecorderPanel::nextMarkText() const {
    const QString typed = mMarkEdit->text().trimmed();
    return typed.isEmpty() ? tr("Mark %1").arg(mMarksAdded + 1) : typed;
}

void RecorderPanel::setRecordingStarted(const QString& path) {
    mRecording = true;
    mRecordingPath = path;
    mMarksAdded = 0;
    mRecordError->hide();
    mRecordStatus->setStyleSheet(QString());
    mRecordStatus->setText(tr("Recording to %1…").arg(QFileInfo(path).fileName()));
    mRecordStatus->setToolTip(path);
    updateButtons();
}

void RecorderPanel::setRecordingStopped(const QString& error) {
    const bool wasRecording = mRecording;
    mRecording = false;
    if (!error.isEmpty()) showRecordingError(error);
    if (!wasRecording) {
        mRecordStatus->setStyleSheet(QString());
        // A folder of any length (a data folder setting of kilobytes) in at most kShownPathChars,
        // elided in the middle, the whole of it in the tooltip: the label never widens the window.
        constexpr qsizetype kShownPathChars = 90;
        QString folder = QDir::toNativeSeparators(mFolder);
        const QString whole = folder;
        if (folder.size() > kShownPathChars)
            folder = folder.left(kShownPathChars / 3) + QChar(0x2026) +
                     folder.right(kShownPathChars - kShownPathChars / 3);
        mRecordStatus->setText(tr("Not recording.\nFolder: %1").arg(folder));
        mRecordStatus->setToolTip(whole);
    }
    updateButtons();
}

void RecorderPanel::showRecordingStats(const RecordingStats& stats) {
    const QLocale locale;
    QString text = tr("%1 %2 · %3 ticks · %4 · %5 B/tick · drops %6 (%7 gaps)")
                       .arg(mRecording                 ? tr("● REC")
                            : mRecordError->isHidden() ? tr("Saved %1:").arg(QFileInfo(mRecordingPath).fileName())
                                                       : tr("Stopped %1:").arg(QFileInfo(mRecordingPath).fileName()),
                            RecordingTimeline::formatTime(stats.elapsedS))
                       .arg(locale.toString(qulonglong(stats.ticks)))
                       .arg(locale.formattedDataSize(qint64(stats.bytes)))
                       .arg(locale.toString(stats.bytesPerTick(), 'f', 1))
                       .arg(stats.droppedTicks)
                       .arg(stats.gaps);
    if (stats.lostCommands > 0) text += tr(" · %1 commands lost").arg(stats.lostCommands);
    mRecordStatus->setText(text);
    mRecordStatus->setToolTip(tr("%1\nElapsed loop time, ticks written, file size, bytes per tick, ticks dropped "
                                 "because the writer fell behind (each run is a gap)")
                                  .arg(mRecordingPath));
    mRecordStatus->setStyleSheet(stats.droppedTicks > 0 || stats.lostCommands > 0 ? kWarningStyle : QString());
}

void RecorderPanel::showRecordingError(const QString& message) {
    mRecordError->setText(message);
    mRecordError->show();
}

void RecorderPanel::noteMarkAdded(const QString& text) {
    ++mMarksAdded;
    mMarkEdit->clear();
    mMarkEdit->setPlaceholderText(tr("Added “%1” · next mark text").arg(text));
}

QString RecorderPanel::recordingStatusText() const { return mRecordStatus->text(); }

QString RecorderPanel::recordingErrorText() const { return mRecordError->isHidden() ? QString() : mRecordError->text(); }

void RecorderPanel::setRecordingAllowed(bool allowed) {
    mRecordingAllowed = allowed;
    updateButtons();
}

void RecorderPanel::updateButtons() {
    mRecordButton->setEnabled(!mRecording && mRecordingAllowed);
    mRecordButton->setToolTip(
        mRecordingAllowed
            ? tr("Record the live session to a new file in %1 (Ctrl+Shift+R).\nStarting resets the tissue to rest "
                 "and the force ramps in again (as after a device switch): a recording replays from its start "
                 "alone.")
                  .arg(QDir::toNativeSeparators(mFolder))
            : tr("Go back to the live session to record"));
    mStopButton->setEnabled(mRecording);
    mMarkButton->setEnabled(mRecording);
    mFolderButton->setEnabled(!mRecording);
    mFolderButton->setToolTip(tr("Where new recordings go: %1").arg(QDir::toNativeSeparators(mFolder)));

    const bool loaded = mPlayer != nullptr;
    mOpenButton->setEnabled(mJob != Job::Open);
    mLiveButton->setEnabled(loaded);
    mPlayButton->setEnabled(loaded);
    mSpeedCombo->setEnabled(loaded);
    mTimeline->setEnabled(loaded);
    mPlayButton->setText(mPlaying ? tr("❚❚ &Pause") : tr("▶ &Play"));
}

// --- playback --------------------------------------------------------------------------------

QString RecorderPanel::openDialogFolder() const {
    const QString last = QSettings().value(kOpenFolderKey).toString();
    return !last.isEmpty() && QFileInfo(last).isDir() ? last : mFolder;
}

void RecorderPanel::chooseRecording() {
    // Its own folder: without one, Qt starts where any file dialog was last (the meshes, say).
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Recording"), openDialogFolder(),
                                                      tr("Palpate recordings (*.palprec);;All files (*)"));
    if (path.isEmpty()) return;
    QSettings().setValue(kOpenFolderKey, QFileInfo(path).absolutePath());
    openRecording(path);
}

QString RecorderPanel::playbackMeshPath() const { return mPlayer ? mShownMeshPath : QString(); }

bool RecorderPanel::openRecording(const QString& path) {
    if (mJob == Job::Open) return false;
    if (mJob == Job::Seek) {  // the player being replaced: stop its seek (a batch of ticks away)
        mCancel.store(true);
        finishWorker();
    }
    setPlaying(false);
    mPlaybackError->hide();
    mFileLabel->setText(tr("Opening %1…").arg(QFileInfo(path).fileName()));
    mFileLabel->setToolTip(path);
    auto result = std::make_shared<OpenResult>();
    result->path = path;
    mJob = Job::Open;
    startWorker([this, result] {
        const QString& p = result->path;
        // Refused before it is read: reading a FIFO would block this worker, and the window's
        // close waiting for it, forever.
        const QFileInfo info(p);
        if (info.exists() && info.isDir()) result->error = tr("%1: is a folder, not a recording").arg(p);
        else if (info.exists() && !info.isFile())
            result->error = tr("%1: is not a regular file (a FIFO or a device), not a recording").arg(p);
        // Off the GUI thread no event loop catches an exception: it would end the process, and
        // without the result posted the dock would wait for it forever.
        if (result->error.isEmpty()) {
            try {
                auto reader = std::make_shared<RecordingReader>(RecordingReader::open(p.toStdString()));
                result->error = openProblem(*reader, p);
                if (result->error.isEmpty()) {
                    std::string error;
                    result->player = RecordingPlayer::open(*reader, error);
                    if (!result->player) {
                        QString why = QString::fromStdString(error);
                        result->error = why.contains(p) ? why : tr("%1: cannot replay: %2").arg(p, why);
                    } else {
                        result->player->step(1);  // something to show: the first tick
                    }
                }
                result->warning = damageWarning(*reader, p);
                result->warningDetails = damageDetails(*reader);
                result->reader = std::move(reader);
            } catch (const std::exception& e) {
                result->player.reset();
                result->reader.reset();
                result->error = tr("%1: cannot replay: %2").arg(p, QString::fromLocal8Bit(e.what()));
            }
        }
        handOffTo(this, [this, result] { onOpenFinished(result); });
    });
    return true;
}

void RecorderPanel::startWorker(std::function<void()> work) {
    mCancel.store(false);
    mWorker = QThread::create(std::move(work));
    mWorker->setObjectName(QStringLiteral("recordingPlayback"));
    mJobClock.start();
    mProgressTimer.start();
    mWorker->start();
    updateButtons();
}

void RecorderPanel::finishWorker() {
    if (mWorker) {
        mWorker->wait();  // it posted its result as its last act (or stops within a batch when cancelled)
        delete mWorker;
        mWorker = nullptr;
    }
    mJob = Job::None;
    mProgressTimer.stop();
    mProgress->hide();
    if (mBusyCursor) {
        QApplication::restoreOverrideCursor();
        mBusyCursor = false;
    }
    updateButtons();
}

void RecorderPanel::pollProgress() {
    if (!mWorker || mJobClock.elapsed() < kBusyFeedbackMs) return;
    if (!mBusyCursor) {
        QApplication::setOverrideCursor(Qt::BusyCursor);
        mBusyCursor = true;
    }
    mProgress->show();
    if (mJob == Job::Open) {
        mProgress->setRange(0, 0);  // reading and checking the file: no figure to show
        return;
    }
    mProgress->setRange(0, kProgressSteps);
    const std::uint64_t from = mSeekFrom.load(), target = mSeekTarget.load(), reached = mSeekReached.load();
    const double fraction = target > from ? double(std::clamp(reached, from, target) - from) / double(target - from) : 1.0;
    mProgress->setValue(int(fraction * kProgressSteps));
    mTimeLabel->setText(tr("Replaying to %1… %2 %")
                            .arg(RecordingTimeline::formatTime(timeOfTick(target)))
                            .arg(int(fraction * 100.0)));
}

void RecorderPanel::onOpenFinished(const std::shared_ptr<OpenResult>& result) {
    const bool cancelled = mCancel.load();  // Back to live while it opened
    finishWorker();
    if (cancelled || !result->error.isEmpty()) {
        // The playback in progress (if any) stays as it was.
        mFileLabel->setText(mPlayer ? QFileInfo(mPlaybackPath).fileName() : QString());
        mFileLabel->setToolTip(mPlayer ? mPlaybackPath : QString());
        if (cancelled) return;
        setPlaybackError(result->error);
        emit openFailed(result->error);
        return;
    }
    mPlayer.reset();  // the old player before the reader it reads
    mReader = result->reader;
    mPlayer = std::move(result->player);
    mPlaybackPath = result->path;
    mShownMesh.reset();
    mShownSceneId = 0;
    mPlaying = false;
    mTickCarry = 0.0;
    setPlaybackError(QString());
    setPlaybackWarning(result->warning);
    mPlaybackWarning->setToolTip(result->warningDetails);

    const RecordingReader& reader = *mReader;
    const RecordingSummary& summary = reader.summary();
    mRateHz = reader.header().rateHz;
    mTimeChunks.clear();
    for (const ChunkInfo& c : reader.chunks())
        if (c.type == ChunkType::Data && c.count > 0) mTimeChunks.push_back(c);
    std::sort(mTimeChunks.begin(), mTimeChunks.end(),
              [](const ChunkInfo& a, const ChunkInfo& b) { return a.firstTick < b.firstTick; });
    mStartTimeS = mTimeChunks.empty() ? 0.0 : mTimeChunks.front().firstTimeS;

    mFileLabel->setText(QFileInfo(mPlaybackPath).fileName());
    mFileLabel->setToolTip(tr("%1\nRecorded with Palpate %2 at %3 Hz on %4; device %5; %6 ticks, %7 events")
                               .arg(mPlaybackPath, QString::fromStdString(reader.header().engineVersion))
                               .arg(mRateHz)
                               .arg(QFileInfo(QString::fromStdString(reader.header().scene.meshPath)).fileName(),
                                    QString::fromStdString(reader.header().device.uri))
                               .arg(summary.ticks)
                               .arg(summary.events));

    // The timeline: every recovered tick, the events, and what the replay cannot show.
    mTimeline->setRange(summary.firstTick, std::max(summary.lastTick, mPlayer->lastTick()));
    mTimeline->setSingleStep(std::max<std::uint64_t>(1, std::uint64_t(mRateHz / 20.0)));  // 50 ms
    mTimeline->setPageStep(std::max<std::uint64_t>(1, std::uint64_t(mRateHz)));            // 1 s
    mTimeline->setTimeOfTick([this](std::uint64_t tick) { return timeOfTick(tick); });
    std::vector<RecordingTimeline::Marker> markers;
    for (const RecordingEvent& e : reader.events()) markers.push_back(markerOf(e));
    mTimeline->setMarkers(std::move(markers));
    std::vector<RecordingTimeline::Region> regions;
    for (const ChunkInfo& c : reader.chunks())
        if (c.type == ChunkType::Gap && c.count > 0)
            regions.push_back({c.firstTick, c.firstTick + c.count - 1, tr("Dropped while recording")});
    for (const DamagedRegion& d : reader.damage())
        if (d.ticksKnown && d.count > 0)
            regions.push_back({d.firstTick, d.firstTick + d.count - 1,
                               tr("Damaged (%1)").arg(QString::fromStdString(d.reason))});
    for (std::size_t i = 1; i < mTimeChunks.size(); ++i) {
        const std::uint64_t end = mTimeChunks[i - 1].firstTick + mTimeChunks[i - 1].count;
        const bool covered = std::any_of(regions.begin(), regions.end(),
                                         [&](const RecordingTimeline::Region& r) { return r.firstTick == end; });
        if (mTimeChunks[i].firstTick > end && !covered)
            regions.push_back({end, mTimeChunks[i].firstTick - 1, tr("Lost (damaged or missing)")});
    }
    if (mPlayer->lastTick() < summary.lastTick)
        regions.push_back({mPlayer->lastTick() + 1, summary.lastTick,
                           tr("Past where the replay stops (%1)").arg(QString::fromStdString(mPlayer->status().stopReason))});
    mTimeline->setRegions(std::move(regions));

    updateButtons();
    updateVerdict();
    emit playbackStarted(mPlaybackPath);
    presentFrame();
}

void RecorderPanel::closePlayback() {
    setPlaying(false);
    if (mJob == Job::Seek) {
        mCancel.store(true);
        finishWorker();
    } else if (mJob == Job::Open) {
        mCancel.store(true);  // the worker has its own reader and player: dropped when they arrive
    }
    mPlayer.reset();
    mReader.reset();
    mPlaybackPath.clear();
    mShownMesh.reset();
    mShownSceneId = 0;
    mTimeChunks.clear();
    mTimeline->clear();
    mFileLabel->clear();
    mFileLabel->setToolTip(QString());
    setPlaybackWarning(QString());
    updateVerdict();
    updateTimeLabels();
    updateButtons();
}

double RecorderPanel::timeOfTick(std::uint64_t tick) const {
    if (mTimeChunks.empty()) return 0.0;
    const double periodS = 1.0 / mRateHz;
    auto after = std::upper_bound(mTimeChunks.begin(), mTimeChunks.end(), tick,
                                  [](std::uint64_t t, const ChunkInfo& c) { return t < c.firstTick; });
    if (after == mTimeChunks.begin()) return 0.0;
    const ChunkInfo& c = *(after - 1);
    const std::uint64_t last = c.firstTick + c.count - 1;
    double t;
    if (tick <= last)
        t = c.count > 1 ? c.firstTimeS + (c.lastTimeS - c.firstTimeS) * double(tick - c.firstTick) / double(c.count - 1)
                        : c.firstTimeS;
    else
        t = c.lastTimeS + double(tick - last) * periodS;  // in a gap: as if the clock kept its rate
    return std::max(0.0, t - mStartTimeS);
}

std::uint64_t RecorderPanel::currentTick() const {
    if (!mPlayer) return 0;
    if (mJob == Job::Seek) return mSeekReached.load();
    return mPlayer->currentTick();
}

bool RecorderPanel::seekTo(std::uint64_t tick) {
    if (!mPlayer || mJob == Job::Open) return false;
    tick = std::clamp(tick, mPlayer->firstTick(), mPlayer->lastTick());
    mTimeline->setValue(tick);
    if (mJob == Job::Seek) {
        mSeekTarget.store(tick);  // the worker chases the newest target
        return true;
    }
    const bool have = mPlayer->recordedTick() != nullptr;
    const std::uint64_t current = mPlayer->currentTick();
    if (have && tick == current) {
        presentFrame();
        return true;
    }
    // Forwards replays from here; backwards restarts and replays from the first tick.
    const std::uint64_t cost = have && tick > current ? tick - current : tick - mPlayer->firstTick() + 1;
    if (double(cost) * mUsPerTick > mSyncSeekBudgetUs) {
        startSeekJob(tick);
        return true;
    }
    QElapsedTimer clock;
    clock.start();
    mPlayer->seek(tick);
    mUsPerTick = 0.8 * mUsPerTick + 0.2 * std::max(0.1, double(clock.nsecsElapsed()) * 1e-3 / double(cost));
    presentFrame();
    updateVerdict();
    return true;
}

void RecorderPanel::startSeekJob(std::uint64_t tick) {
    const bool have = mPlayer->recordedTick() != nullptr;
    mSeekTarget.store(tick);
    mSeekFrom.store(have && tick > mPlayer->currentTick() ? mPlayer->currentTick() : mPlayer->firstTick());
    mSeekReached.store(mSeekFrom.load());
    mJob = Job::Seek;
    RecordingPlayer* player = mPlayer.get();
    startWorker([this, player] {
        QElapsedTimer clock;
        clock.start();
        std::uint64_t ran = 0;
        std::optional<std::uint64_t> reached;  // the target it stopped at, if it got there
        while (!mCancel.load()) {
            const std::uint64_t target = mSeekTarget.load();
            const bool started = player->recordedTick() != nullptr;
            const std::uint64_t current = player->currentTick();
            if (started && current == target) {
                reached = target;
                break;
            }
            if (started && target < current) {
                mSeekFrom.store(player->firstTick());
                if (!player->seek(player->firstTick())) break;  // restart: replays the first tick
                ++ran;
                continue;
            }
            const std::uint64_t stepped = player->step(std::min(kSeekBatchTicks, target - current));
            ran += stepped;
            mSeekReached.store(player->currentTick());
            if (stepped == 0) break;  // the replay can go no further (end, or it stopped)
        }
        const double usPerTick = ran > 0 ? double(clock.nsecsElapsed()) * 1e-3 / double(ran) : 0.0;
        handOffTo(this, [this, usPerTick, reached] {
            if (usPerTick > 0.0) mUsPerTick = 0.5 * mUsPerTick + 0.5 * usPerTick;
            onSeekFinished(reached);
        });
    });
    updateTimeLabels();
}

void RecorderPanel::onSeekFinished(std::optional<std::uint64_t> reachedTick) {
    if (mJob != Job::Seek) return;  // cancelled: a new recording is opening, or playback closed
    finishWorker();
    if (!mPlayer) return;
    // Retargeted after the worker reached its last target and before this arrived: go on there.
    // (A replay that stopped short reached nothing and is not chased again.)
    const std::uint64_t target = mSeekTarget.load();
    if (reachedTick && *reachedTick != target) {
        seekTo(target);
        if (mJob == Job::Seek) return;  // far enough for the worker again
    }
    presentFrame();
    updateVerdict();
    mFrameClock.restart();  // playing on: the seek's time is not played through
}

void RecorderPanel::setPlaying(bool playing) {
    if (playing && (!mPlayer || mJob == Job::Open)) playing = false;
    if (playing && mJob == Job::None && mPlayer->atEnd()) seekTo(mPlayer->firstTick());  // play again
    mPlaying = playing;
    mTickCarry = 0.0;
    if (playing) {
        mFrameClock.start();
        mFrameTimer.start();
    } else {
        mFrameTimer.stop();
    }
    updateButtons();
}

void RecorderPanel::setSpeed(double speed) {
    int best = 0;
    for (int i = 0; i < mSpeedCombo->count(); ++i)
        if (std::abs(mSpeedCombo->itemData(i).toDouble() - speed) < std::abs(mSpeedCombo->itemData(best).toDouble() - speed))
            best = i;
    mSpeedCombo->setCurrentIndex(best);
}

double RecorderPanel::speed() const { return mSpeedCombo->currentData().toDouble(); }

void RecorderPanel::onFrameTimer() {
    const double elapsedS = double(mFrameClock.nsecsElapsed()) * 1e-9;
    mFrameClock.restart();
    advanceFrame(elapsedS);
}

void RecorderPanel::advanceFrame(double elapsedS) {
    if (!mPlaying || !mPlayer || mJob == Job::Seek) return;
    ++mFramesPlayed;
    mTickCarry += mRateHz * std::clamp(elapsedS, 0.0, kMaxFrameS) * speed();
    const auto wanted = std::uint64_t(mTickCarry);
    mTickCarry -= double(wanted);
    if (wanted > 0) stepBudgeted(wanted);
    presentFrame();
    if (mPlayer->atEnd()) {
        setPlaying(false);
        updateVerdict();
    }
}

std::uint64_t RecorderPanel::stepBudgeted(std::uint64_t ticks) {
    QElapsedTimer clock;
    clock.start();
    std::uint64_t done = 0;
    while (done < ticks) {
        const std::uint64_t batch = std::min<std::uint64_t>(ticks - done, 32);
        const std::uint64_t ran = mPlayer->step(batch);
        done += ran;
        if (ran < batch) break;
        if (clock.nsecsElapsed() > kFrameBudgetNs) {
            mTickCarry = 0.0;  // too slow to keep up: play slower than asked rather than freeze
            break;
        }
    }
    if (done > 0) mUsPerTick = 0.9 * mUsPerTick + 0.1 * std::max(0.1, double(clock.nsecsElapsed()) * 1e-3 / double(done));
    return done;
}

void RecorderPanel::presentFrame() {
    if (!mPlayer || mJob == Job::Seek) return;
    const HapticSnapshot& s = mPlayer->snapshot();
    if (s.sceneId != mShownSceneId) {
        // A new scene: the recording switched meshes, or a backwards seek rebuilt the same one.
        mShownSceneId = s.sceneId;
        // The scene's file: the header's, or that of the last switch up to here.
        std::string meshPath = mReader->header().scene.meshPath;
        for (const RecordingEvent& e : mReader->events())
            if (e.kind == EventKind::SceneChanged && e.scene && e.tick <= mPlayer->currentTick()) meshPath = e.scene->meshPath;
        mShownMeshPath = QString::fromStdString(meshPath);
        const TissueMesh& mesh = mPlayer->mesh();
        const bool same = mShownMesh && mShownMesh->restPositionsMm() == mesh.restPositionsMm() &&
                          mShownMesh->triangles() == mesh.triangles();
        if (!same) {
            mShownMesh = std::make_unique<TissueMesh>(mesh);
            emit playbackMeshChanged(*mShownMesh);
        }
    }
    const auto positions = mPlayer->positionsMm();
    mFrame.positionsMm.assign(positions.begin(), positions.end());
    mFrame.rings.assign(positions.size(), kNoRing);
    const std::uint32_t displaced = std::min<std::uint32_t>(s.displacedCount, HapticSnapshot::kMaxDisplaced);
    for (std::uint32_t i = 0; i < displaced; ++i)
        if (s.displacedIds[i] < mFrame.rings.size()) mFrame.rings[s.displacedIds[i]] = s.displacedRings[i];
    mFrame.version = 0;  // read whole: a replay jumps
    mFrame.changed.clear();
    mFrame.touched = s.touched;
    mFrame.contact = s.contact;
    mFrame.hasTool = s.deviceState == DeviceState::Ready && s.toolSampleSequence > 0;
    mFrame.toolTipMm = s.toolTipMm;
    mFrame.forceN = s.forceN;
    mTimeline->setValue(mPlayer->currentTick());
    updateTimeLabels();
    emit playbackFrame(mFrame);
}

void RecorderPanel::updateTimeLabels() {
    if (!mPlayer || !mReader) {
        mTimeLabel->setText(tr("—:— / —:—"));
        return;
    }
    if (mJob == Job::Seek) return;  // pollProgress says where the seek is
    const RecordedTick* tick = mPlayer->recordedTick();
    const double nowS = tick ? std::max(0.0, tick->nowS - mStartTimeS) : 0.0;
    mTimeLabel->setText(tr("%1 / %2  (tick %3)")
                            .arg(RecordingTimeline::formatTime(nowS),
                                 RecordingTimeline::formatTime(mReader->summary().durationS))
                            .arg(mPlayer->currentTick()));
}

void RecorderPanel::updateVerdict() {
    if (!mPlayer || mJob == Job::Seek) {
        mVerdictLabel->setStyleSheet(QString());
        mVerdictLabel->setText(mPlayer ? QString() : tr("Open a recording to play it back and check its replay."));
        return;
    }
    if (!mPlayer->atEnd()) {
        mVerdictLabel->setStyleSheet(QString());
        mVerdictLabel->setText(tr("Replay check: play or go to the end (End) to compare every tick with the recording."));
        return;
    }
    const ReplayStatus& st = mPlayer->status();
    if (st.ok()) {
        mVerdictLabel->setStyleSheet(kGoodStyle);
        mVerdictLabel->setText(tr("✔ The replay matches the recording bit for bit (%1 ticks, %2 chunk hashes checked).")
                                   .arg(st.ticksReplayed)
                                   .arg(st.hashChecks));
    } else if (st.mismatch) {
        mVerdictLabel->setStyleSheet(kErrorStyle);
        mVerdictLabel->setText(tr("✘ The replay differs from the recording (%1 ticks). First: %2")
                                   .arg(st.mismatches)
                                   .arg(QString::fromStdString(st.firstMismatch)));
    } else if (st.hashMismatches > 0) {
        mVerdictLabel->setStyleSheet(kErrorStyle);
        mVerdictLabel->setText(tr("✘ %1 of %2 chunk hashes differ from the replay's.").arg(st.hashMismatches).arg(st.hashChecks));
    } else {
        mVerdictLabel->setStyleSheet(kWarningStyle);
        mVerdictLabel->setText(tr("The replay stopped early: %1. The %2 ticks replayed match the recording.")
                                   .arg(QString::fromStdString(st.stopReason))
                                   .arg(st.ticksReplayed));
    }
}

void RecorderPanel::setPlaybackError(const QString& text) {
    mPlaybackError->setText(text);
    mPlaybackError->setVisible(!text.isEmpty());
}

void RecorderPanel::setPlaybackWarning(const QString& text) {
    mPlaybackWarning->setText(text);
    mPlaybackWarning->setVisible(!text.isEmpty());
    if (text.isEmpty()) mPlaybackWarning->setToolTip(QString());
}

QString RecorderPanel::playbackErrorText() const { return mPlaybackError->isHidden() ? QString() : mPlaybackError->text(); }

QString RecorderPanel::playbackWarningText() const {
    return mPlaybackWarning->isHidden() ? QString() : mPlaybackWarning->text();
}

QString RecorderPanel::verdictText() const {
    return mPlayer && mJob != Job::Seek && mPlayer->atEnd() ? mVerdictLabel->text() : QString();
}

QString RecorderPanel::timeText() const { return mTimeLabel->text(); }

}  // namespace palpate
