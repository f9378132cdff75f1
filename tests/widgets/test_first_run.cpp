// The first-run experience under QT_QPA_PLATFORM=offscreen (docs/user-guide.md): the welcome page (shown once,
// "Don't show this again", its three actions on a real stepped MainWindow), the Preferences dialog
// (fields, validation, the QSettings keys) and what the preferences do to a window, the Help menu's
// User Guide (F1, shown in the guide window; no browser is started) and formatForce. Own main().
#include "base/resources/ShippedResources.h"
#include "app/gui/ExerciseController.h"
#include "app/gui/FirstRun.h"
#include "app/gui/MainWindow.h"
#include "widgets/PreferencesDialog.h"
#include "widgets/RecorderPanel.h"
#include "widgets/WelcomePage.h"

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCommandLinkButton>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QAbstractTextDocumentLayout>
#include <QFile>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>

#include <cstdlib>
#include <memory>
#include <utility>

using namespace palpate;

namespace {

/// A stepped window with the default mesh, its first-run actions in the Edit and Help menus
/// (installed here unless MainWindow::createMenus already did).
std::unique_ptr<MainWindow> makeWindow() {
    auto window = std::make_unique<MainWindow>(RendererChoice::Software, LoopMode::Stepped);
    if (!window->findChild<QAction*>(QStringLiteral("userGuideAction"))) {
        const QList<QAction*> menus = window->menuBar()->actions();
        QMenu* edit = nullptr;
        for (QAction* a : menus)
            if (a->menu() && a->menu()->actions().size() > 0 && a->text() == MainWindow::tr("&Edit")) edit = a->menu();
        installFirstRunActions(*window, edit, menus.last()->menu());
    }
    const std::string mesh = findResource(kDefaultMesh);
    EXPECT_FALSE(mesh.empty());
    EXPECT_EQ(window->setDeviceUri(QStringLiteral("sim:press")), QString());
    EXPECT_EQ(window->loadMesh(QString::fromStdString(mesh)), QString());
    window->resize(1024, 768);
    window->show();
    return window;
}

class FirstRunTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        mPreviousOpener = setUrlOpener([this](const QUrl& url) {
            mOpened << url;
            return true;
        });
    }
    void TearDown() override {
        setUrlOpener(mPreviousOpener);
        QSettings().clear();
    }
    QList<QUrl> mOpened;
    UrlOpener mPreviousOpener;
};

}  // namespace

TEST_F(FirstRunTest, WelcomeShowsOnFirstStartUntilDontShowAgain) {
    auto window = makeWindow();
    WelcomePage* page = maybeShowWelcome(*window);
    ASSERT_NE(page, nullptr);
    EXPECT_TRUE(page->isVisible());
    EXPECT_FALSE(page->dontShowAgain());
    page->reject();  // closed without the tick: shown again next time
    EXPECT_FALSE(QSettings().value(Preferences::kFirstRunDoneKey).toBool());
    QApplication::processEvents();

    page = maybeShowWelcome(*window);
    ASSERT_NE(page, nullptr);
    page->dontShowAgainBox()->click();
    page->reject();
    EXPECT_TRUE(QSettings().value(Preferences::kFirstRunDoneKey).toBool());
    QApplication::processEvents();
    EXPECT_EQ(maybeShowWelcome(*window), nullptr);

    // Help > Welcome still shows it, with the tick as stored.
    QAction* welcome = window->findChild<QAction*>(QStringLiteral("welcomeAction"));
    ASSERT_NE(welcome, nullptr);
    welcome->trigger();
    auto* again = window->findChild<WelcomePage*>(QStringLiteral("welcomePage"));
    ASSERT_NE(again, nullptr);
    EXPECT_TRUE(again->isVisible());
    EXPECT_TRUE(again->dontShowAgain());
    again->reject();
}

TEST_F(FirstRunTest, WelcomeTouchModeSwitchesToTheMouse) {
    auto window = makeWindow();
    EXPECT_FALSE(window->touchMode());
    WelcomePage* page = showWelcome(*window);
    ASSERT_NE(page, nullptr);
    page->touchModeButton()->click();
    EXPECT_EQ(QString::fromStdString(window->session().deviceUri()), QStringLiteral("mouse:"));
    EXPECT_TRUE(window->touchMode());
    EXPECT_TRUE(window->touchModeAction()->isChecked());
    EXPECT_FALSE(page->isVisible());
}

TEST_F(FirstRunTest, WelcomeSampleSceneAndExampleExercise) {
    auto window = makeWindow();
    EXPECT_EQ(window->loadMesh(QString::fromStdString(findResource("meshes/sphere_1442.off"))), QString());
    showWelcome(*window)->sampleSceneButton()->click();
    EXPECT_TRUE(QString::fromStdString(window->session().drawnPath()).endsWith(QLatin1String("stomach_3970.off")));

    showWelcome(*window)->exerciseButton()->click();
    EXPECT_EQ(window->mode(), MainWindow::Mode::Trainee);
    EXPECT_TRUE(window->exercises().running());
}

TEST_F(FirstRunTest, PreferencesDialogSavesItsKeys) {
    PreferencesDialog dialog;
    EXPECT_EQ(dialog.preferences(), Preferences{});  // nothing stored: the defaults
    dialog.languageBox()->setCurrentIndex(dialog.languageBox()->findData(QStringLiteral("ms")));
    dialog.forceUnitBox()->setCurrentIndex(dialog.forceUnitBox()->findData(QStringLiteral("gf")));
    dialog.hapticRateBox()->setCurrentIndex(dialog.hapticRateBox()->findData(2000));
    dialog.deviceBox()->setCurrentText(QStringLiteral("sim:press"));
    QTemporaryDir data;
    dialog.dataFolderEdit()->setText(data.path());
    EXPECT_EQ(dialog.problem(), QString());
    dialog.accept();

    QSettings settings;
    EXPECT_EQ(settings.value("language").toString(), QStringLiteral("ms"));
    EXPECT_EQ(settings.value("units/force").toString(), QStringLiteral("gf"));
    EXPECT_EQ(settings.value("haptic/rateHz").toInt(), 2000);
    EXPECT_EQ(settings.value("device/defaultUri").toString(), QStringLiteral("sim:press"));
    EXPECT_EQ(settings.value("dataFolder").toString(), data.path());
    EXPECT_EQ(preferredDeviceUri(), QStringLiteral("sim:press"));
    EXPECT_EQ(Preferences::load().effectiveLanguage(), QStringLiteral("ms"));

    // A new dialog shows what is stored; Restore Defaults goes back to the defaults.
    PreferencesDialog reopened;
    EXPECT_EQ(reopened.preferences(), Preferences::load());
    auto* box = reopened.findChild<QDialogButtonBox*>();
    ASSERT_NE(box, nullptr);
    box->button(QDialogButtonBox::RestoreDefaults)->click();
    EXPECT_EQ(reopened.preferences(), Preferences{});
}

TEST_F(FirstRunTest, PreferencesDialogRefusesABadDeviceAndARelativeFolder) {
    PreferencesDialog dialog;
    auto* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    dialog.deviceBox()->setCurrentText(QStringLiteral("nosuchscheme:3"));
    EXPECT_TRUE(dialog.problem().contains(QLatin1String("nosuchscheme")));
    EXPECT_FALSE(ok->isEnabled());
    dialog.accept();  // refused: nothing stored
    EXPECT_FALSE(QSettings().contains("device/defaultUri"));

    dialog.deviceBox()->setCurrentIndex(0);
    EXPECT_EQ(dialog.problem(), QString());
    dialog.dataFolderEdit()->setText(QStringLiteral("relative/folder"));
    EXPECT_FALSE(dialog.problem().isEmpty());
    EXPECT_FALSE(ok->isEnabled());

    // A password in the server's URL, in any form, is refused here as where the URL is read.
    dialog.dataFolderEdit()->clear();
    auto* server = dialog.findChild<QLineEdit*>(QStringLiteral("resultsServerEdit"));
    ASSERT_NE(server, nullptr);
    for (const char* url : {"postgresql://room12:pw@host/palpate", "postgresql://room12@host/palpate?password=pw",
                            "postgresql://room12@host/palpate?sslmode=prefer%20password%3Dpw"}) {
        server->setText(QString::fromLatin1(url));
        EXPECT_TRUE(dialog.problem().contains(QLatin1String("password")))
            << url << ": " << dialog.problem().toStdString();
        EXPECT_FALSE(ok->isEnabled()) << url;
    }
    server->setText(QStringLiteral("postgresql://room12@host/palpate?sslrootcert=/etc/passwords/ca.crt"));
    EXPECT_EQ(dialog.problem(), QString());
}

TEST_F(FirstRunTest, PreferencesApplyToTheWindow) {
    auto window = makeWindow();
    QTemporaryDir data;
    Preferences p;
    p.dataFolder = data.path();
    p.hapticRateHz = 500;
    p.save();
    applyPreferences(*window);
    EXPECT_EQ(window->recorderPanel()->recordingFolder(), QDir(data.path()).filePath(QStringLiteral("recordings")));
    EXPECT_EQ(window->exercises().database().path(), QDir(data.path()).filePath(QStringLiteral("results.sqlite")));
    EXPECT_TRUE(QFileInfo::exists(QDir(data.path()).filePath(QStringLiteral("results.sqlite"))));
    EXPECT_EQ(window->session().preset().hapticRateHz, 500.0);
    window->advanceTicks(10);  // the loop runs at the new rate
    EXPECT_DOUBLE_EQ(window->session().periodS(), 1.0 / 500.0);

    // Cleared, the data folder is the default one again.
    p.dataFolder.clear();
    p.save();
    applyPreferences(*window);
    EXPECT_EQ(window->recorderPanel()->recordingFolder(), RecorderPanel::defaultRecordingFolder());
    EXPECT_EQ(window->exercises().database().path(), ExerciseController::defaultDatabasePath());

    // Edit > Preferences… opens the dialog (once).
    QAction* action = window->findChild<QAction*>(QStringLiteral("preferencesAction"));
    ASSERT_NE(action, nullptr);
    EXPECT_EQ(action->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Comma));
    action->trigger();
    action->trigger();
    const auto dialogs = window->findChildren<PreferencesDialog*>();
    ASSERT_EQ(dialogs.size(), 1);
    EXPECT_TRUE(dialogs.front()->isVisible());
    EXPECT_EQ(dialogs.front()->preferences(), Preferences::load());
    dialogs.front()->reject();
}

TEST_F(FirstRunTest, UserGuideOpensFromHelpWithF1) {
    const QString path = userGuidePath();
    ASSERT_FALSE(path.isEmpty()) << "docs/user-guide.md not found";
    EXPECT_TRUE(path.endsWith(QLatin1String("user-guide.md")));

    auto window = makeWindow();
    QAction* guide = window->findChild<QAction*>(QStringLiteral("userGuideAction"));
    ASSERT_NE(guide, nullptr);
    EXPECT_EQ(guide->shortcut(), QKeySequence(QKeySequence::HelpContents));
    EXPECT_EQ(guide->shortcut(), QKeySequence(Qt::Key_F1));
    guide->trigger();
    auto* browser = window->findChild<QTextBrowser*>(QStringLiteral("userGuideBrowser"));
    ASSERT_NE(browser, nullptr);
    EXPECT_TRUE(browser->isVisible());
    EXPECT_TRUE(browser->toPlainText().contains(QLatin1String("Palpate user guide")));
    EXPECT_TRUE(browser->toPlainText().contains(QLatin1String("Touch mode")));
    // The guide's pictures load (the document has images, all of them found next to the guide).
    EXPECT_TRUE(browser->toHtml().contains(QLatin1String("<img")));
    EXPECT_TRUE(mOpened.isEmpty());  // nothing went to a browser
}

TEST_F(FirstRunTest, WelcomeIsNotShownOverACommandLineTask) {
    auto window = makeWindow();
    // `palpate --exercise FILE ...` (and --mesh, --open-recording...): the command line says what to do.
    for (const char* option : {"exercise", "mesh", "open-recording", "preset", "trainee", "show-dialog"}) {
        EXPECT_EQ(maybeShowWelcome(*window, {QStringLiteral("mode"), QLatin1String(option)}), nullptr) << option;
        EXPECT_EQ(window->findChild<WelcomePage*>(QStringLiteral("welcomePage")), nullptr) << option;
    }
    // Options that only set something up (the device, the mode) leave the first start as it is.
    WelcomePage* page = maybeShowWelcome(*window, {QStringLiteral("device"), QStringLiteral("mode")});
    ASSERT_NE(page, nullptr);
    EXPECT_TRUE(page->isVisible());
    page->reject();
}

TEST_F(FirstRunTest, UserGuideContentsLinksScrollToTheirHeading) {
    auto window = makeWindow();
    auto* dialog = openUserGuide(window.get());
    ASSERT_NE(dialog, nullptr);
    auto* browser = window->findChild<QTextBrowser*>(QStringLiteral("userGuideBrowser"));
    ASSERT_NE(browser, nullptr);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    QTextDocument* document = browser->document();
    // The contents' links, and the headings they name.
    int linksChecked = 0;
    const std::pair<const char*, const char*> kLinks[] = {{"where-palpate-keeps-things", "Where Palpate keeps things"},
                                                          {"the-tissue-parameters-and-presets", "The tissue: parameters and presets"},
                                                          {"installing", "Installing"}};
    for (const auto& [slug, title] : kLinks) {
        const QString href = QLatin1Char('#') + QLatin1String(slug);
        QTextCursor link;
        for (QTextBlock b = document->begin(); b.isValid() && link.isNull(); b = b.next())
            for (auto it = b.begin(); !it.atEnd(); ++it)
                if (it.fragment().charFormat().anchorHref() == href) {
                    link = QTextCursor(document);
                    link.setPosition(it.fragment().position() + 1);
                    break;
                }
        ASSERT_FALSE(link.isNull()) << "no contents link to " << slug;
        QTextBlock heading;
        for (QTextBlock b = document->begin(); b.isValid(); b = b.next())
            if (b.blockFormat().headingLevel() > 0 && b.text() == QLatin1String(title)) heading = b;
        ASSERT_TRUE(heading.isValid()) << "no heading " << title;

        // Back to the top, where the contents are, and click the link.
        browser->verticalScrollBar()->setValue(0);
        QApplication::processEvents();
        const QRect at = browser->cursorRect(link);
        ASSERT_TRUE(browser->viewport()->rect().contains(at.center())) << slug;
        QTest::mouseClick(browser->viewport(), Qt::LeftButton, {}, at.center());
        QApplication::processEvents();
        const int headingY = int(document->documentLayout()->blockBoundingRect(heading).top());
        EXPECT_GT(browser->verticalScrollBar()->value(), 0) << slug;
        // The heading is at the top of the view (or the view is scrolled to its end).
        EXPECT_TRUE(std::abs(browser->verticalScrollBar()->value() - headingY) <= 2 ||
                    browser->verticalScrollBar()->value() == browser->verticalScrollBar()->maximum())
            << slug << ": scrolled to " << browser->verticalScrollBar()->value() << ", heading at " << headingY;
        EXPECT_TRUE(browser->toPlainText().contains(QLatin1String("Palpate user guide")));  // still the guide
        ++linksChecked;
    }
    EXPECT_EQ(linksChecked, 3);
    EXPECT_TRUE(mOpened.isEmpty());  // nothing went to a browser
}

TEST(HeadingAnchors, GitHubSlugsAndRepeats) {
    QTextDocument document;
    document.setMarkdown(QStringLiteral("# Palpate user guide\n\n## The tissue: parameters and presets\n\ntext\n\n"
                                        "## Writing exercises (instructors)\n\n## Notes\n\n## Notes\n"));
    addHeadingAnchors(document);
    QStringList names;
    for (QTextBlock b = document.begin(); b.isValid(); b = b.next())
        if (b.blockFormat().headingLevel() > 0) names << b.begin().fragment().charFormat().anchorNames();
    EXPECT_EQ(names, (QStringList{QStringLiteral("palpate-user-guide"), QStringLiteral("the-tissue-parameters-and-presets"),
                                  QStringLiteral("writing-exercises-instructors"), QStringLiteral("notes"),
                                  QStringLiteral("notes-1")}));
    // Again (a page shown again): nothing changes.
    const int revision = document.revision();
    addHeadingAnchors(document);
    EXPECT_EQ(document.revision(), revision);
}

/// setApplicationNames() changes where QSettings and QStandardPaths point: put back the test's names.
class ApplicationNames : public ::testing::Test {
protected:
    void SetUp() override {
        mName = QCoreApplication::applicationName();
        mOrganization = QCoreApplication::organizationName();
        mDomain = QCoreApplication::organizationDomain();
    }
    void TearDown() override {
        QCoreApplication::setApplicationName(mName);
        QCoreApplication::setOrganizationName(mOrganization);
        QCoreApplication::setOrganizationDomain(mDomain);
    }
    QString mName, mOrganization, mDomain;
};

TEST_F(ApplicationNames, SettingsWhereTheGuideSaysAndTheDataFolderStays) {
    setApplicationNames();
    // docs/user-guide.md, "Where Palpate keeps things" (test mode: under ~/.qttest instead of ~).
    const QString config = QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation);
    EXPECT_EQ(QSettings().fileName(), config + QStringLiteral("/palpate/palpate.conf"));
    const QString data = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    EXPECT_EQ(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation), data + QStringLiteral("/palpate"));
    EXPECT_EQ(Preferences::defaultDataFolder(), data + QStringLiteral("/palpate"));
    EXPECT_EQ(RecorderPanel::defaultRecordingFolder(), data + QStringLiteral("/palpate/recordings"));
    EXPECT_EQ(ExerciseController::defaultDatabasePath(), data + QStringLiteral("/palpate/results.sqlite"));
}

TEST_F(ApplicationNames, OldSettingsFileIsMovedOnce) {
    setApplicationNames();
    const QString config = QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation);
    const QString oldPath = config + QStringLiteral("/Unknown Organization/palpate.conf");
    const QString newPath = QSettings().fileName();
    QFile::remove(oldPath);  // a failed run's leftovers
    QFile::remove(newPath);
    EXPECT_FALSE(migrateOldSettings());  // nothing to move
    auto writeOld = [&](const char* mode) {
        ASSERT_TRUE(QDir().mkpath(QFileInfo(oldPath).absolutePath()));
        QFile old(oldPath);
        ASSERT_TRUE(old.open(QIODevice::WriteOnly | QIODevice::Truncate));
        old.write(QByteArray("[General]\nfirstRunDone=true\n\n[window]\nmode=") + mode + "\n");
    };
    writeOld("trainee");
    ASSERT_TRUE(migrateOldSettings());
    EXPECT_FALSE(QFileInfo::exists(oldPath));
    EXPECT_TRUE(QSettings().value(QStringLiteral("firstRunDone")).toBool());
    EXPECT_EQ(QSettings().value(QStringLiteral("window/mode")).toString(), QStringLiteral("trainee"));
    // Once: a file that turns up at the old place later does not replace the preferences.
    writeOld("instructor");
    EXPECT_FALSE(migrateOldSettings());
    EXPECT_TRUE(QFileInfo::exists(oldPath));
    EXPECT_EQ(QSettings().value(QStringLiteral("window/mode")).toString(), QStringLiteral("trainee"));
    QFile::remove(oldPath);
    QFile::remove(newPath);
    QDir(config).rmdir(QStringLiteral("Unknown Organization"));
}

TEST(FormatForce, NewtonsAndGramForce) {
    EXPECT_EQ(formatForce(1.25, QStringLiteral("N")), QStringLiteral("1.25 N"));
    EXPECT_EQ(formatForce(1.0, QStringLiteral("gf")), QStringLiteral("102.0 gf"));  // 1 N = 101.97 gf
    EXPECT_EQ(formatForce(0.0, QStringLiteral("gf"), 1), QStringLiteral("0 gf"));
    // The stored unit, as Preferences saves it.
    Preferences p;
    p.forceUnit = QStringLiteral("gf");
    p.save();
    EXPECT_EQ(formatForce(0.5), QStringLiteral("51.0 gf"));
    p.forceUnit = QStringLiteral("N");
    p.save();
    EXPECT_EQ(formatForce(0.5), QStringLiteral("0.50 N"));
    QSettings().clear();
}

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // QSettings and the data folder are not the user's
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("palpate-first-run-tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
