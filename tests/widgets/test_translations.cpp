// The translations (translations/README.md) under QT_QPA_PLATFORM=offscreen: the embedded German and Malay .qm
// files load, and a MainWindow built after switching finds its menus in that language; switching
// back to English gives the English menus. Own main().
#include "app/gui/FirstRun.h"
#include "base/resources/ShippedResources.h"
#include "app/gui/ExerciseController.h"
#include "app/gui/MainWindow.h"
#include "widgets/RecorderPanel.h"
#include "widgets/HistoryPanel.h"
#include "widgets/PreferencesDialog.h"
#include "widgets/ForceGauge.h"
#include "widgets/MeshSizeText.h"
#include "widgets/ScoreCard.h"
#include "widgets/TraineePanel.h"

#include "report/MetricText.h"
#include "report/PalpationSummaryText.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QTableWidget>
#include <QApplication>
#include <QLabel>
#include <QMenuBar>
#include <QSettings>
#include <QFile>
#include <QTemporaryDir>
#include <QProcess>
#include <QStandardPaths>

#include <memory>

using namespace palpate;

namespace {

QStringList menuTitles(const MainWindow& window) {
    QStringList titles;
    for (const QAction* action : window.menuBar()->actions()) titles << action->text();
    return titles;
}

QStringList actionTexts(const MainWindow& window) {
    QStringList texts;
    for (const QAction* action : window.findChildren<QAction*>()) texts << action->text();
    return texts;
}

/// Trainee mode, Ada, "press the targets" chosen and its good path as the device; recordings and
/// results in `dir`.
void preparePressTargets(MainWindow& window, const QTemporaryDir& dir) {
    window.recorderPanel()->setRecordingFolder(dir.filePath(QStringLiteral("recordings")));
    ASSERT_EQ(window.exercises().openDatabase(dir.filePath(QStringLiteral("results.sqlite"))), QString());
    ASSERT_EQ(window.setDeviceUri(QStringLiteral("sim:path:") +
                                  QString::fromStdString(findResource("exercises/press_targets.good.path"))),
              QString());
    window.setMode(MainWindow::Mode::Trainee);
    ASSERT_EQ(window.exercises().addTrainee(QStringLiteral("Ada")), QString());
    ASSERT_EQ(window.exercises().addExerciseFile(QString::fromStdString(findResource("exercises/press_targets.json"))),
              QString());
}

/// Starts the chosen exercise and steps it to its end (at most a minute of ticks).
void runPressTargets(MainWindow& window) {
    ASSERT_EQ(window.exercises().start(), QString());
    for (int done = 0; done < 60000 && window.exercises().running(); done += 100) window.advanceTicks(100);
}

/// A PDF's text as pdftotext reads it, whitespace simplified ("" when it cannot be read).
QString pdfText(const QString& pdftotext, const QString& pdf) {
    QProcess proc;
    proc.start(pdftotext, {pdf, QStringLiteral("-")});
    if (!proc.waitForFinished(30000)) return {};
    return QString::fromUtf8(proc.readAllStandardOutput()).simplified();
}

class Translations : public ::testing::Test {
protected:
    void TearDown() override { loadLanguage(*qApp, QStringLiteral("en")); }
};

}  // namespace

TEST_F(Translations, GermanMainWindow) {
    ASSERT_TRUE(loadLanguage(*qApp, QStringLiteral("de")));
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    const QStringList titles = menuTitles(window);
    EXPECT_TRUE(titles.contains(QStringLiteral("&Datei"))) << titles.join(QLatin1Char(' ')).toStdString();
    EXPECT_TRUE(titles.contains(QStringLiteral("&Hilfe"))) << titles.join(QLatin1Char(' ')).toStdString();
    EXPECT_FALSE(titles.contains(QStringLiteral("&File")));
    EXPECT_TRUE(actionTexts(window).contains(QStringLiteral("&Beenden")));
}

namespace {

/// The field names (labels ending in ':') of the Exercise and History docks: what a trainee reads.
QStringList traineeFieldNames(const MainWindow& window) {
    QStringList names;
    for (const QWidget* dock : {static_cast<const QWidget*>(window.traineePanel()), static_cast<const QWidget*>(window.historyPanel())})
        for (const QLabel* label : dock->findChildren<QLabel*>())
            if (label->text().trimmed().endsWith(QLatin1Char(':'))) names << label->text().trimmed();
    return names;
}

}  // namespace

TEST_F(Translations, TraineeModeFieldNamesAreGerman) {
    QStringList english;
    {
        MainWindow window(RendererChoice::Software, LoopMode::Stepped);
        window.setMode(MainWindow::Mode::Trainee);
        english = traineeFieldNames(window);
    }
    ASSERT_TRUE(english.contains(QStringLiteral("Trainee:"))) << english.join(QLatin1Char(' ')).toStdString();
    ASSERT_TRUE(loadLanguage(*qApp, QStringLiteral("de")));
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    window.setMode(MainWindow::Mode::Trainee);
    const QStringList german = traineeFieldNames(window);
    EXPECT_EQ(german.size(), english.size());
    for (const QString& name : german)
        EXPECT_FALSE(english.contains(name)) << name.toStdString() << " is the English text";
    // The mode itself, as the Exercise menu names it.
    EXPECT_FALSE(actionTexts(window).contains(QStringLiteral("&Trainee-Modus")));
}

TEST_F(Translations, MalayMainWindow) {
    ASSERT_TRUE(loadLanguage(*qApp, QStringLiteral("ms")));
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    const QStringList titles = menuTitles(window);
    EXPECT_TRUE(titles.contains(QStringLiteral("&Fail"))) << titles.join(QLatin1Char(' ')).toStdString();
    EXPECT_TRUE(titles.contains(QStringLiteral("&Bantuan"))) << titles.join(QLatin1Char(' ')).toStdString();
    EXPECT_FALSE(titles.contains(QStringLiteral("&File")));
}

TEST_F(Translations, BackToEnglishAndTheStoredLanguage) {
    ASSERT_TRUE(loadLanguage(*qApp, QStringLiteral("de")));
    EXPECT_FALSE(loadLanguage(*qApp, QStringLiteral("en")));  // English needs no translator
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    EXPECT_TRUE(menuTitles(window).contains(QStringLiteral("&File")));

    // installTranslator follows QSettings "language" (what Preferences stores).
    QSettings().setValue("language", QStringLiteral("de"));
    EXPECT_EQ(installTranslator(*qApp), QStringLiteral("de"));
    EXPECT_EQ(MainWindow::tr("&File"), QStringLiteral("&Datei"));
    QSettings().setValue("language", QStringLiteral("ms"));
    EXPECT_EQ(installTranslator(*qApp), QStringLiteral("ms"));
    EXPECT_EQ(MainWindow::tr("&Help"), QStringLiteral("&Bantuan"));
    QSettings().setValue("language", QStringLiteral("en"));
    EXPECT_EQ(installTranslator(*qApp), QStringLiteral("en"));
    EXPECT_EQ(MainWindow::tr("&File"), QStringLiteral("&File"));
    QSettings().remove("language");
}

// The trainee's feedback in the trainee's language: the sentence from its key and figures, the
// numbers with the locale's decimal comma; a score with one decimal, the same way.
TEST_F(Translations, FeedbackSentencesAndNumbersAreGerman) {
    const PalpationFeedback low{"low_coverage", "Examined 33.3 % of the surface at 0.4 N or more: ...", {33.3, 0.4}};
    const PalpationFeedback alarms{"false_alarms", "2 findings were on no lump: ...", {2.0}};
    EXPECT_EQ(feedbackText(low, QLocale(QStringLiteral("en"))),
              QStringLiteral("Examined 33.3 % of the surface at 0.4 N or more: cover all of it, in overlapping rows."));
    ASSERT_TRUE(loadLanguage(*qApp, QStringLiteral("de")));
    EXPECT_EQ(QLocale().decimalPoint(), QStringLiteral(","));  // the default locale follows the language
    const QString german = feedbackText(low);
    EXPECT_TRUE(german.contains(QStringLiteral("33,3 %")) && german.contains(QStringLiteral("0,4 N")) &&
                german.contains(QStringLiteral("Oberfläche")))
        << german.toStdString();
    EXPECT_TRUE(feedbackText(alarms).startsWith(QStringLiteral("2 Befunde"))) << feedbackText(alarms).toStdString();
    EXPECT_EQ(scoreText(85.25), QStringLiteral("85,3"));
    EXPECT_EQ(formatForce(1.25, QStringLiteral("N")), QStringLiteral("1,25 N"));  // the status bar, the gauge
    // A key this build does not know: its English text, as it came.
    EXPECT_EQ(feedbackText({"from_a_later_version", "Some English.", {1.0}}), QStringLiteral("Some English."));
}

// A German trainee's PDF report is German: its fields, its score with a decimal comma, its date in
// German, its feedback and metric names; the scripted good path of "press the targets".
TEST_F(Translations, TheScoreReportPdfIsGerman) {
    const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    if (pdftotext.isEmpty()) GTEST_SKIP() << "pdftotext not installed (poppler-utils)";
    ASSERT_TRUE(loadLanguage(*qApp, QStringLiteral("de")));
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    window.resize(1200, 800);
    window.show();
    ASSERT_NO_FATAL_FAILURE(preparePressTargets(window, dir));
    ASSERT_NO_FATAL_FAILURE(runPressTargets(window));
    ASSERT_TRUE(window.exercises().lastReport());
    const double score = window.exercises().lastReport()->score;
    const QString pdf = dir.filePath(QStringLiteral("bericht.pdf"));
    ASSERT_EQ(window.exercises().exportLastReportPdf(pdf), QString());
    const QString text = pdfText(pdftotext, pdf);
    ASSERT_FALSE(text.isEmpty());
    EXPECT_TRUE(text.contains(QStringLiteral("Teilnehmer:"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Datum:"))) << text.toStdString();
    EXPECT_TRUE(
        text.contains(QStringLiteral("Punktzahl: %1 / 100").arg(QLocale(QStringLiteral("de")).toString(score, 'f', 1))))
        << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("Score:"))) << text.toStdString();
    // Narrow columns' German headers stay whole words (the header's font shrinks to fit), where
    // they used to break between letters ("Abweichu ng").
    for (const char* header : {"Abweichung", "Teilpunktzahl", "Kraftfenster"})
        EXPECT_TRUE(text.contains(QString::fromUtf8(header))) << header << " in " << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("Trainee:"))) << text.toStdString();
    if (const QByteArray shots = qgetenv("PALPATE_SHOT_DIR"); !shots.isEmpty())
        QFile::copy(pdf, QString::fromLocal8Bit(shots) + QStringLiteral("/bericht.pdf"));
}

// A trainee using Palpate in German or Malay reads the shipped exercises' names and descriptions
// in that language, in the list, the dock, the score card and the PDF; results are still stored
// under the exercise's own name, so a class that mixes languages is one exercise.
TEST_F(Translations, ExercisesSpeakTheTraineesLanguage) {
    const QString pdftotext = QStandardPaths::findExecutable(QStringLiteral("pdftotext"));
    struct Case {
        const char* language;
        const char* listed;
        const char* description;
    };
    for (const Case& c : {Case{"de", "Drei Ziele drücken", "Drücken Sie die drei markierten Punkte"},
                          Case{"ms", "Tekan tiga sasaran", "Tekan tiga titik bertanda"}}) {
        SCOPED_TRACE(c.language);
        ASSERT_TRUE(loadLanguage(*qApp, QString::fromLatin1(c.language)));
        QTemporaryDir dir;
        ASSERT_TRUE(dir.isValid());
        MainWindow window(RendererChoice::Software, LoopMode::Stepped);
        ASSERT_NO_FATAL_FAILURE(preparePressTargets(window, dir));
        window.setMode(MainWindow::Mode::Trainee);
        ASSERT_EQ(window.exercises().addTrainee(QStringLiteral("Ada")), QString());
        ASSERT_EQ(
            window.exercises().addExerciseFile(QString::fromStdString(findResource("exercises/press_targets.json"))),
            QString());
        TraineePanel& panel = *window.traineePanel();
        const QString listed = QString::fromUtf8(c.listed);
        EXPECT_EQ(panel.exerciseTitle(), listed);
        QStringList titles;
        for (const auto& [title, path] : panel.exercises()) titles << title;
        EXPECT_FALSE(titles.contains(QStringLiteral("Press three targets")))
            << titles.join(QLatin1Char('|')).toStdString();
        const auto* description = panel.findChild<QLabel*>(QStringLiteral("exerciseDescriptionLabel"));
        ASSERT_NE(description, nullptr);
        EXPECT_TRUE(description->text().startsWith(QString::fromUtf8(c.description)))
            << description->text().toStdString();

        ASSERT_NO_FATAL_FAILURE(runPressTargets(window));
        ASSERT_TRUE(window.exercises().lastReport());
        const std::vector<ResultRecord> stored = window.exercises().database().allResults();
        ASSERT_EQ(stored.size(), 1u);
        EXPECT_EQ(stored.front().exerciseName, QStringLiteral("Press three targets"));
        const auto* card = panel.findChild<ScoreCard*>();
        ASSERT_NE(card, nullptr);
        EXPECT_TRUE(card->titleText().contains(listed)) << card->titleText().toStdString();
        // The card's points follow the language's decimal sign; History names the exercise so too.
        const QChar decimal = QLocale(QString::fromLatin1(c.language)).decimalPoint().at(0);
        for (int row = 0; row < card->breakdownTable()->rowCount(); ++row) {
            const QString points = card->breakdownTable()->item(row, 3)->text();
            EXPECT_TRUE(points.contains(decimal)) << points.toStdString();
        }
        QTableWidget* history = window.historyPanel()->table();
        ASSERT_GE(history->rowCount(), 1);
        EXPECT_EQ(history->item(0, 1)->text(), listed);
        if (pdftotext.isEmpty()) continue;
        const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
        ASSERT_EQ(window.exercises().exportLastReportPdf(pdf), QString());
        const QString text = pdfText(pdftotext, pdf);
        ASSERT_FALSE(text.isEmpty());
        EXPECT_TRUE(text.contains(listed)) << text.toStdString();
        EXPECT_FALSE(text.contains(QStringLiteral("Press three targets"))) << text.toStdString();
    }
}

// A stopped session's card in German ("Abgebrochen: bisher 0,0 Punkte, keine Bewertung", large)
// wraps in the Exercise dock instead of widening the window past a 1280-pixel screen; the force
// gauge and the mesh's size take the decimal comma; Qt's own buttons speak Malay too (Debian ships
// no Malay catalogue for Qt: ours carries them).
TEST_F(Translations, AStoppedCardWrapsAndStandardButtonsAreTranslated) {
    ASSERT_TRUE(loadLanguage(*qApp, QStringLiteral("de")));
    ForceGauge gauge;
    gauge.setForceN(0.5);
    EXPECT_EQ(gauge.readingText(), QStringLiteral("0,50 N"));
    EXPECT_EQ(formatLengthMm(75.94), QStringLiteral("75,9"));  // the mesh's size in the status bar
    EXPECT_EQ(formatLengthMm(1500.0), QStringLiteral("1500"));
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    window.resize(1280, 800);
    window.show();
    ASSERT_NO_FATAL_FAILURE(preparePressTargets(window, dir));
    window.resize(1280, 800);
    ASSERT_EQ(window.exercises().start(), QString());
    window.advanceTicks(200);
    window.exercises().stop();
    ASSERT_FALSE(window.exercises().running());
    for (int i = 0; i < 3; ++i) QApplication::processEvents();
    const auto* card = window.traineePanel()->findChild<ScoreCard*>();
    ASSERT_NE(card, nullptr);
    EXPECT_TRUE(card->scoreText().startsWith(QStringLiteral("Abgebrochen"))) << card->scoreText().toStdString();
    EXPECT_LE(window.width(), 1280) << "the card needs " << window.minimumSizeHint().width() << " px";

    ASSERT_TRUE(loadLanguage(*qApp, QStringLiteral("ms")));
    QDialogButtonBox buttons(QDialogButtonBox::Close | QDialogButtonBox::Cancel);
    EXPECT_EQ(buttons.button(QDialogButtonBox::Close)->text(), QStringLiteral("Tutup"));
    EXPECT_EQ(buttons.button(QDialogButtonBox::Cancel)->text(), QStringLiteral("Batal"));
}

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // QSettings are not the user's
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("palpate-translation-tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
