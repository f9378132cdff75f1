// The GUI starts whatever its settings say and never aborts on a bad file (docs/reliability.md): a
// start-up device that cannot be opened (from --device or Preferences) gives way to a fallback that
// is named; replay:FILE of an intact recording starts; a preset or exercise with a number that
// overflows is an error naming the file; an exception escaping an event is reported and the event
// loop runs on; a thread that cannot be created ends the GUI with a message, not a hang; a file-size
// limit is a write error; a broken results database is named with its path and reason. Some run
// the real `palpate` binary, as a user does. Own main() (a GuiApplication).
#include "base/resources/ShippedResources.h"
#include "app/gui/ExerciseController.h"
#include "app/gui/FirstRun.h"
#include "app/gui/GuiApplication.h"
#include "app/gui/MainWindow.h"
#include "widgets/ChartsPanel.h"
#include "widgets/DevicePanel.h"
#include "widgets/ExerciseEditorPanel.h"
#include "widgets/GuardedLoad.h"
#include "widgets/PreferencesDialog.h"
#include "widgets/RecorderPanel.h"
#include "widgets/SaveFileChoice.h"
#include "widgets/TraineePanel.h"

#include <gtest/gtest.h>
#include <functional>

#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>

#include <cerrno>
#include <fcntl.h>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

using namespace palpate;

namespace {

QString resource(const char* relative) { return QString::fromStdString(findResource(relative)); }
QString defaultMesh() { return resource("meshes/stomach_3970.off"); }

struct GuiRun {
    int exitCode = -1;
    bool crashed = false;
    QString out, err;
};

/// The real GUI binary, offscreen, with its settings and data folders in `dir` (not the user's).
GuiRun runGui(const QTemporaryDir& dir, const QStringList& arguments) {
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
    env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
    process.setProcessEnvironment(env);
    process.start(QStringLiteral(PALPATE_GUI_BINARY), arguments);
    GuiRun run;
    if (!process.waitForFinished(120000)) {
        process.kill();
        process.waitForFinished();
        run.err = QStringLiteral("(did not finish)");
        return run;
    }
    run.crashed = process.exitStatus() != QProcess::NormalExit;
    run.exitCode = process.exitCode();
    run.out = QString::fromLocal8Bit(process.readAllStandardOutput());
    run.err = QString::fromLocal8Bit(process.readAllStandardError());
    return run;
}

/// `source` with its first `from` replaced by `to`, written to `path`.
QString writeEdited(const QString& source, const QString& path, const QString& from, const QString& to) {
    QFile in(source);
    EXPECT_TRUE(in.open(QIODevice::ReadOnly)) << source.toStdString();
    QString text = QString::fromUtf8(in.readAll());
    const int at = text.indexOf(from);
    EXPECT_GE(at, 0) << from.toStdString();
    text.replace(at, from.size(), to);
    QFile out(path);
    EXPECT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(text.toUtf8());
    return path;
}

/// A real recording of a stepped session, in `dir`.
QString makeRecording(const QTemporaryDir& dir) {
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    window.recorderPanel()->setRecordingFolder(dir.filePath(QStringLiteral("recordings")));
    QString problem;
    EXPECT_EQ(window.startSession(defaultMesh(), QStringLiteral("sim:press"), QStringLiteral("sim:stroke"), problem),
              QString());
    EXPECT_EQ(window.startRecording(), QString());
    window.advanceTicks(500);
    EXPECT_EQ(window.stopRecording(), QString());
    const QStringList files = QDir(dir.filePath(QStringLiteral("recordings"))).entryList(QDir::Files);
    EXPECT_EQ(files.size(), 1);
    return files.isEmpty() ? QString() : dir.filePath(QStringLiteral("recordings/") + files.front());
}

}  // namespace

// A palpate.conf that is not a regular file is neither read (a FIFO would block the start for
// ever) nor saved over (a link to a device would replace the device): the window starts, says so,
// and leaves the thing as it was.
TEST(Settings, APreferencesFileThatIsNotARegularFileIsNeitherReadNorReplaced) {
    QTemporaryDir dir;
    ASSERT_TRUE(QDir().mkpath(dir.filePath(QStringLiteral("config/palpate"))));
    const QString conf = dir.filePath(QStringLiteral("config/palpate/palpate.conf"));
    const QString fifo = dir.filePath(QStringLiteral("a-fifo"));
    ASSERT_EQ(::mkfifo(fifo.toLocal8Bit().constData(), 0644), 0);
    struct Case {
        const char* what;
        std::function<bool()> make;
        const char* said;
    };
    const std::vector<Case> cases = {
        {"a FIFO", [&] { return ::mkfifo(conf.toLocal8Bit().constData(), 0644) == 0; }, "a FIFO"},
        {"a link to a FIFO", [&] { return QFile::link(fifo, conf); }, "a link to a FIFO"},
        {"a folder", [&] { return QDir().mkdir(conf); }, "a folder"},
        {"a link to nothing", [&] { return QFile::link(dir.filePath(QStringLiteral("gone")), conf); },
         "a link to nothing"}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        ASSERT_TRUE(c.make());
        // A screenshot run reads the preferences and, at exit, saves the window's state.
        const GuiRun run = runGui(dir, {QStringLiteral("--screenshot"), dir.filePath(QStringLiteral("shot.png")),
                                        QStringLiteral("--ticks"), QStringLiteral("20")});
        EXPECT_FALSE(run.crashed);
        EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
        EXPECT_TRUE(run.err.contains(QStringLiteral("not a regular file"))) << run.err.toStdString();
        EXPECT_TRUE(run.err.contains(QLatin1String(c.said))) << run.err.toStdString();
        // Still what it was.
        struct stat after {};
        ASSERT_EQ(::lstat(conf.toLocal8Bit().constData(), &after), 0);
        EXPECT_FALSE(S_ISREG(after.st_mode));
        struct stat target {};
        if (::stat(fifo.toLocal8Bit().constData(), &target) == 0) EXPECT_TRUE(S_ISFIFO(target.st_mode));
        EXPECT_FALSE(QFileInfo::exists(dir.filePath(QStringLiteral("gone"))));
        if (QFileInfo(conf).isDir() && !QFileInfo(conf).isSymLink()) QDir(conf).removeRecursively();
        else QFile::remove(conf);
    }
}

// A data folder of kilobytes (a pasted path, a broken setting) is shown elided: the window keeps
// its width.
TEST(Settings, AVeryLongDataFolderDoesNotWidenTheWindow) {
    QTemporaryDir dir;
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    const int usualWidth = window.minimumSizeHint().width();
    QString folder = dir.path();
    while (folder.size() < 4500) folder += QStringLiteral("/a-very-long-folder-name-without-any-space");
    window.recorderPanel()->setRecordingFolder(folder);
    QApplication::processEvents();
    EXPECT_LE(window.minimumSizeHint().width(), usualWidth + 50) << "from " << usualWidth;
    EXPECT_LE(window.minimumSizeHint().width(), 1280);
}

TEST(StartupDevice, UnopenableDeviceGivesWayToTheFallbackAndIsNamed) {
    QTemporaryDir dir;
    const QString garbage = dir.filePath(QStringLiteral("garbage.palprec"));
    {
        QFile file(garbage);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write("this is not a recording");
    }
    // A FIFO and a folder are refused before they are read: the FIFO would block the start forever.
    const QString fifo = dir.filePath(QStringLiteral("fifo.palprec"));
    ASSERT_EQ(::mkfifo(fifo.toLocal8Bit().constData(), 0644), 0);
    for (const QString& uri : {QStringLiteral("falcon:abc"), QStringLiteral("replay:") + garbage,
                               QStringLiteral("replay:") + fifo, QStringLiteral("replay:") + dir.path()}) {
        SCOPED_TRACE(uri.toStdString());
        MainWindow window(RendererChoice::Software, LoopMode::Stepped);
        QString problem;
        EXPECT_EQ(window.startSession(defaultMesh(), uri, QStringLiteral("sim:stroke"), problem), QString());
        EXPECT_TRUE(problem.contains(uri)) << problem.toStdString();
        EXPECT_TRUE(problem.contains(QStringLiteral("sim:stroke"))) << problem.toStdString();
        EXPECT_EQ(window.session().deviceUri(), "sim:stroke");
        window.advanceTicks(10);  // the session runs
        bool shown = false;
        for (const QLabel* label : window.devicePanel()->findChildren<QLabel*>())
            shown = shown || (label->text().contains(uri) && !label->isHidden());
        EXPECT_TRUE(shown) << "the Device dock names the device that could not be opened";
    }
}

TEST(StartupDevice, CommandLineDeviceThatCannotOpenStillStartsTheGui) {
    QTemporaryDir dir;
    const QString shot = dir.filePath(QStringLiteral("shot.png"));
    const GuiRun run = runGui(dir,
                              {QStringLiteral("--device"), QStringLiteral("falcon:abc"), QStringLiteral("--screenshot"),
                               shot, QStringLiteral("--ticks"), QStringLiteral("20")});
    EXPECT_FALSE(run.crashed);
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_TRUE(run.err.contains(QStringLiteral("falcon:abc"))) << run.err.toStdString();
    EXPECT_TRUE(QFileInfo::exists(shot));
}

TEST(StartupDevice, PreferencesDeviceThatCannotOpenLeavesPreferencesReachable) {
    QSettings().setValue(QLatin1String(Preferences::kDeviceUriKey), QStringLiteral("falcon:abc"));
    const QString uri = preferredDeviceUri();  // what main() starts the interactive window with
    ASSERT_EQ(uri, QStringLiteral("falcon:abc"));
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    QString problem;
    ASSERT_EQ(window.startSession(defaultMesh(), uri, QStringLiteral("mouse:"), problem), QString());
    EXPECT_TRUE(problem.contains(uri)) << problem.toStdString();
    EXPECT_EQ(window.session().deviceUri(), "mouse:");
    auto* dialog = qobject_cast<PreferencesDialog*>(showFirstRunDialog(window, QStringLiteral("preferences")));
    ASSERT_NE(dialog, nullptr);
    dialog->deviceBox()->setCurrentText(QStringLiteral("sim:press"));
    dialog->accept();
    EXPECT_EQ(preferredDeviceUri(), QStringLiteral("sim:press"));
    QSettings().clear();
}

TEST(StartupDevice, ReplayOfAnIntactRecordingStartsFromTheCommandLine) {
    QTemporaryDir dir;
    const QString recording = makeRecording(dir);
    ASSERT_FALSE(recording.isEmpty());
    const QString shot = dir.filePath(QStringLiteral("replay.png"));
    const GuiRun run = runGui(dir,
                              {QStringLiteral("--device"), QStringLiteral("replay:") + recording,
                               QStringLiteral("--screenshot"), shot, QStringLiteral("--ticks"), QStringLiteral("100")});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_FALSE(run.err.contains(QStringLiteral("Cannot open"))) << run.err.toStdString();
    EXPECT_TRUE(run.out.contains(QStringLiteral("device replay:"))) << run.out.toStdString();
}

TEST(BadFiles, OverflowingNumberInAPresetOrExerciseOpenedInTheWindowIsAnErrorNamingTheFile) {
    QTemporaryDir dir;
    const QString preset = writeEdited(resource("presets/tissues/phantom_gel.json"),
                                       dir.filePath(QStringLiteral("big.json")),
                                       QStringLiteral("\"haptic_rate_hz\": 1000.0"),
                                       QStringLiteral("\"haptic_rate_hz\": 1e400"));
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    QString problem;
    ASSERT_EQ(window.startSession(defaultMesh(), QStringLiteral("sim:press"), QStringLiteral("sim:stroke"), problem),
              QString());
    const QString error = window.loadPresetFile(preset);  // what --preset and the panel's Load… do
    EXPECT_TRUE(error.contains(QStringLiteral("big.json"))) << error.toStdString();
    EXPECT_EQ(window.loadPresetFile(resource("presets/tissues/phantom_gel.json")), QString());  // the window goes on
    window.advanceTicks(10);
    const QString exercise = writeEdited(resource("exercises/press_targets.json"),
                                         dir.filePath(QStringLiteral("big_ex.json")),
                                         QStringLiteral("\"time_limit_s\": 40.0"),
                                         QStringLiteral("\"time_limit_s\": 1e400"));
    // Exercise > Open Exercise…'s slot, and the editor's Open.
    EXPECT_TRUE(window.exercises().addExerciseFile(exercise).contains(exercise));
    EXPECT_TRUE(window.exerciseEditor()->openExercise(exercise).contains(exercise));
    window.advanceTicks(10);
}

TEST(BadFiles, OverflowingNumberInAnExerciseOrItsPresetIsNamedOnceByTheGui) {
    QTemporaryDir dir;
    const QString exercise = writeEdited(resource("exercises/press_targets.json"),
                                         dir.filePath(QStringLiteral("big_ex.json")),
                                         QStringLiteral("\"time_limit_s\": 40.0"),
                                         QStringLiteral("\"time_limit_s\": 1e400"));
    const QString preset = writeEdited(resource("presets/tissues/skin.json"),
                                       dir.filePath(QStringLiteral("big_preset.json")),
                                       QStringLiteral("\"haptic_rate_hz\": 1000.0"),
                                       QStringLiteral("\"haptic_rate_hz\": 1e400"));
    const QString naming = writeEdited(resource("exercises/press_targets.json"),
                                       dir.filePath(QStringLiteral("names_big.json")),
                                       QStringLiteral("\"presets/tissues/skin.json\""),
                                       QLatin1Char('"') + preset + QLatin1Char('"'));
    for (const QString& file : {exercise, naming}) {
        SCOPED_TRACE(file.toStdString());
        const GuiRun run = runGui(dir, {QStringLiteral("--exercise"), file, QStringLiteral("--screenshot"),
                                        dir.filePath(QStringLiteral("x.png")), QStringLiteral("--ticks"),
                                        QStringLiteral("5")});
        EXPECT_FALSE(run.crashed) << run.err.toStdString();
        EXPECT_EQ(run.exitCode, 1);
        EXPECT_EQ(run.err.count(file), 1) << run.err.toStdString();  // named, and once
    }
    EXPECT_TRUE(runGui(dir, {QStringLiteral("--exercise"), naming, QStringLiteral("--screenshot"),
                             dir.filePath(QStringLiteral("x.png")), QStringLiteral("--ticks"), QStringLiteral("5")})
                    .err.contains(preset));
}

TEST(BadFiles, ALoaderThatThrowsGivesAnErrorNamingTheFile) {
    struct Result {
        std::vector<std::string> errors;
    };
    const Result result = guardedLoad("presets/x.json", []() -> Result { throw std::length_error("too long"); });
    ASSERT_EQ(result.errors.size(), 1u);
    EXPECT_EQ(result.errors.front(), "presets/x.json: too long");
}

TEST(BadFiles, AFolderOrGarbageOpenedAsARecordingIsAnErrorNamingIt) {
    QTemporaryDir dir;
    const QString folder = dir.filePath(QStringLiteral("folder.palprec"));
    ASSERT_TRUE(QDir().mkpath(folder));
    const QString garbage = dir.filePath(QStringLiteral("garbage.palprec"));
    {
        QFile file(garbage);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(QByteArray(100000, '\xff'));
    }
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    QString problem;
    ASSERT_EQ(window.startSession(defaultMesh(), QStringLiteral("sim:press"), QStringLiteral("sim:stroke"), problem),
              QString());
    const QString fifo = dir.filePath(QStringLiteral("fifo.palprec"));
    ASSERT_EQ(::mkfifo(fifo.toLocal8Bit().constData(), 0644), 0);
    for (const QString& path : {folder, garbage, fifo}) {
        SCOPED_TRACE(path.toStdString());
        QSignalSpy failed(window.recorderPanel(), &RecorderPanel::openFailed);
        window.openRecording(path);  // File > Open Recording…'s slot
        ASSERT_TRUE(failed.wait(20000));
        EXPECT_TRUE(failed.front().front().toString().contains(path))
            << failed.front().front().toString().toStdString();
        EXPECT_FALSE(window.inPlayback());
        window.advanceTicks(10);  // the live session goes on
    }
}

TEST(EventLoop, AnExceptionEscapingAnEventIsReportedAndTheLoopRunsOn) {
    auto* app = qobject_cast<GuiApplication*>(QCoreApplication::instance());
    ASSERT_NE(app, nullptr);
    QStringList reported;
    app->setErrorHandler([&reported](const QString& message) { reported << message; });
    QObject receiver;
    QTimer::singleShot(0, &receiver, [] { throw std::runtime_error("bad.json: a loader threw"); });
    bool after = false;
    QTimer::singleShot(0, &receiver, [&after] { after = true; });
    for (int i = 0; i < 5 && !after; ++i) QCoreApplication::processEvents();
    app->setErrorHandler({});
    ASSERT_EQ(reported.size(), 1);
    EXPECT_TRUE(reported.front().contains(QStringLiteral("bad.json: a loader threw")))
        << reported.front().toStdString();
    EXPECT_TRUE(after) << "the events after the one that threw are delivered";
}

namespace {

/// The address space in use now (bytes), from /proc/self/statm.
rlim_t addressSpaceBytes() {
    QFile statm(QStringLiteral("/proc/self/statm"));
    if (!statm.open(QIODevice::ReadOnly)) return 0;
    return rlim_t(statm.readAll().split(' ').front().toULongLong()) * rlim_t(sysconf(_SC_PAGESIZE));
}

}  // namespace

namespace {

/// Runs in the death test's child: a thread started with no room left for its stack (ulimit -v).
[[noreturn]] void startThreadWithoutAddressSpace() {
    exitOnThreadCreationFailure();
    QThread* thread = QThread::create([] {});
    const rlimit limit{addressSpaceBytes() + 256 * 1024, RLIM_INFINITY};
    setrlimit(RLIMIT_AS, &limit);
    thread->start();
    std::exit(thread->wait(5000) ? 0 : 3);  // without the guard: a thread that never ran, or ran
}

/// Runs in the death test's child: writes past a file-size limit (ulimit -f) of 1024 bytes.
[[noreturn]] void writePastFileSizeLimit(const QByteArray& path) {
    ignoreFileSizeSignal();
    const rlimit limit{1024, 1024};
    setrlimit(RLIMIT_FSIZE, &limit);
    const int fd = ::open(path.constData(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const std::vector<char> bytes(4096, 'x');
    ssize_t written = ::write(fd, bytes.data(), bytes.size());  // 1024 of them
    if (written >= 0) written = ::write(fd, bytes.data(), bytes.size());
    std::exit(written < 0 && errno == EFBIG ? 0 : 2);
}

}  // namespace

TEST(ProcessLimits, ThreadThatCannotBeCreatedEndsTheGuiWithAMessage) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(startThreadWithoutAddressSpace(), ::testing::ExitedWithCode(1), "cannot start a thread");
}

TEST(ProcessLimits, FileSizeLimitIsAWriteErrorNotASignal) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    QTemporaryDir dir;
    EXPECT_EXIT(writePastFileSizeLimit(dir.filePath(QStringLiteral("big.bin")).toLocal8Bit()),
                ::testing::ExitedWithCode(0), "");
}

namespace {

QByteArray contentsOf(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/// Answers the next modal question box with `button`; `asked` says whether one came.
void answerNextQuestion(QMessageBox::StandardButton button, bool& asked) {
    QTimer::singleShot(0, [button, &asked] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        asked = box != nullptr;
        if (box) box->button(button)->click();
    });
}

}  // namespace

TEST(Saving, SuffixAddedAfterTheDialogAsksBeforeReplacing) {
    QTemporaryDir dir;
    const QString typed = dir.filePath(QStringLiteral("tissue"));
    EXPECT_EQ(withSuffixConfirmed(nullptr, typed, QStringLiteral(".json")),
              typed + QStringLiteral(".json"));  // no such file
    QFile(typed + QStringLiteral(".json")).open(QIODevice::WriteOnly);
    bool asked = false;
    answerNextQuestion(QMessageBox::No, asked);
    EXPECT_EQ(withSuffixConfirmed(nullptr, typed, QStringLiteral(".json")), QString());
    EXPECT_TRUE(asked);
    answerNextQuestion(QMessageBox::Yes, asked);
    EXPECT_EQ(withSuffixConfirmed(nullptr, typed, QStringLiteral(".json")), typed + QStringLiteral(".json"));
    EXPECT_EQ(withSuffixConfirmed(nullptr, typed + QStringLiteral(".txt"), QStringLiteral(".json")),
              typed + QStringLiteral(".txt"));  // the dialog asked about that name itself
}

TEST(Saving, SweepCsvDoesNotReplaceAFileBesideItThatIsNotItsDescription) {
    QTemporaryDir dir;
    ChartsPanel panel;
    ASSERT_TRUE(panel.loadCsv(QStringLiteral(PALPATE_SOURCE_DIR "/docs/bench/sweep.csv")));  // with its sweep.json
    const QString preset = dir.filePath(QStringLiteral("skin.json"));
    ASSERT_TRUE(QFile::copy(resource("presets/tissues/skin.json"), preset));
    const QByteArray before = contentsOf(preset);
    QString error;
    EXPECT_FALSE(panel.saveCsv(dir.filePath(QStringLiteral("skin.csv")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("skin.json"))) << error.toStdString();
    EXPECT_EQ(contentsOf(preset), before);
    EXPECT_TRUE(panel.saveCsv(dir.filePath(QStringLiteral("sweep.csv")), &error)) << error.toStdString();
    EXPECT_TRUE(panel.saveCsv(dir.filePath(QStringLiteral("sweep.csv")), &error)) << "its own description is replaced";
}

TEST(Saving, ScorePdfIsNeverWrittenOverItsRecording) {
    QTemporaryDir dir;
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    window.recorderPanel()->setRecordingFolder(dir.filePath(QStringLiteral("recordings")));
    QString problem;
    ASSERT_EQ(window.startSession(defaultMesh(),
                                  QStringLiteral("sim:path:") + resource("exercises/press_targets.good.path"),
                                  QStringLiteral("sim:stroke"), problem),
              QString());
    ASSERT_EQ(window.runExercise(resource("exercises/press_targets.json"), QString()), QString());  // a preview
    for (int done = 0; done < 60000 && window.exercises().running(); done += 100) window.advanceTicks(100);
    const QString recording = window.exercises().lastRecordingPath();
    ASSERT_TRUE(QFileInfo::exists(recording)) << recording.toStdString();
    const QByteArray before = contentsOf(recording);
    const QString error = window.exercises().exportLastReportPdf(recording);
    EXPECT_TRUE(error.contains(recording)) << error.toStdString();
    EXPECT_EQ(contentsOf(recording), before) << "the recording is intact";
    EXPECT_EQ(window.exercises().exportLastReportPdf(dir.filePath(QStringLiteral("report.pdf"))), QString());
}

TEST(ResultsDatabase, BrokenDatabaseIsNamedWithItsPathAndReason) {
    QTemporaryDir dir;
    const QString database = dir.filePath(QStringLiteral("results.sqlite"));
    {
        QFile file(database);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(QByteArray(8192, 'z'));  // not SQLite
    }
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    const QString openError = window.exercises().openDatabase(database);
    EXPECT_TRUE(openError.contains(QDir::toNativeSeparators(database))) << openError.toStdString();
    QString problem;
    ASSERT_EQ(window.startSession(defaultMesh(), QStringLiteral("sim:press"), QStringLiteral("sim:stroke"), problem),
              QString());
    const QString exercise = resource("exercises/press_targets.json");
    const QString error = window.runExercise(exercise, QStringLiteral("Ada"));  // what --exercise --trainee does
    EXPECT_TRUE(error.contains(QDir::toNativeSeparators(database))) << error.toStdString();
    EXPECT_TRUE(error.contains(openError)) << "the reason: " << error.toStdString();
    EXPECT_FALSE(error.startsWith(exercise)) << error.toStdString();
}

TEST(ResultsDatabase, AResultThatCannotBeStoredSaysWhereTheSessionIsKept) {
    QTemporaryDir dir;
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    window.recorderPanel()->setRecordingFolder(dir.filePath(QStringLiteral("recordings")));
    ASSERT_EQ(window.exercises().openDatabase(dir.filePath(QStringLiteral("results.sqlite"))), QString());
    QString problem;
    ASSERT_EQ(window.startSession(defaultMesh(),
                                  QStringLiteral("sim:path:") + resource("exercises/press_targets.good.path"),
                                  QStringLiteral("sim:stroke"), problem),
              QString());
    ASSERT_EQ(window.runExercise(resource("exercises/press_targets.json"), QStringLiteral("Ada")), QString());
    window.exercises().database().close();  // the database goes away during the session
    for (int done = 0; done < 60000 && window.exercises().running(); done += 100) window.advanceTicks(100);
    const QString recording = QDir::toNativeSeparators(window.exercises().lastRecordingPath());
    ASSERT_TRUE(QFileInfo::exists(recording));
    QString message;
    for (const QLabel* label : window.traineePanel()->findChildren<QLabel*>())
        if (label->text().contains(QStringLiteral("NOT stored"))) message = label->text();
    EXPECT_TRUE(message.contains(recording)) << message.toStdString();
}

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // QSettings and the data folder are not the user's
    GuiApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("palpate-gui-robustness-tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
