#include "app/gui/FirstRun.h"
#include "results/DataFolder.h"
#include "results/ResultUploader.h"

#include "base/resources/ShippedResources.h"
#include "app/gui/ExerciseController.h"
#include "app/gui/MainWindow.h"
#include "widgets/ParameterPanel.h"
#include "widgets/PreferencesDialog.h"
#include "widgets/RecorderPanel.h"
#include "widgets/WelcomePage.h"

#include <QAction>
#include <QCoreApplication>
#include <QDesktopServices>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QLibraryInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPointer>
#include <QLocale>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QTranslator>
#include <QVBoxLayout>

#include <memory>
#include <utility>
#include <vector>

namespace palpate {

/// The translation context of the texts below (they belong to no widget class).
class FirstRun {
    Q_DECLARE_TR_FUNCTIONS(palpate::FirstRun)
};

namespace {

QTranslator* gAppTranslator = nullptr;
QTranslator* gQtTranslator = nullptr;

// Qt's standard buttons (Close, OK, Cancel, ...) take their words from Qt's own catalogue, which
// Debian ships for German but not for Malay: ours carries them too, in Qt's context, so that no
// dialog shows an English button in a translated window. Only looked up, never called.
[[maybe_unused]] constexpr const char* kStandardButtonTexts[] = {
    QT_TRANSLATE_NOOP("QPlatformTheme", "OK"),      QT_TRANSLATE_NOOP("QPlatformTheme", "Cancel"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Close"),   QT_TRANSLATE_NOOP("QPlatformTheme", "Save"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Discard"), QT_TRANSLATE_NOOP("QPlatformTheme", "&Yes"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "&No"),     QT_TRANSLATE_NOOP("QPlatformTheme", "Restore Defaults"),
    QT_TRANSLATE_NOOP("QPlatformTheme", "Apply"),   QT_TRANSLATE_NOOP("QPlatformTheme", "Help"),
};

UrlOpener& urlOpener() {
    static UrlOpener opener = [](const QUrl& url) { return QDesktopServices::openUrl(url); };
    return opener;
}

/// One instance per window and kind (a second Help > Welcome raises the first).
template <typename T>
T* findOpen(MainWindow& window, const QString& objectName) {
    for (T* child : window.findChildren<T*>(objectName, Qt::FindDirectChildrenOnly))
        if (child->isVisible()) return child;
    return nullptr;
}

void warn(MainWindow& window, const QString& title, const QString& error) {
    if (!error.isEmpty()) QMessageBox::warning(&window, title, error);
}

void openSampleScene(MainWindow& window) {
    const QString mesh = QString::fromStdString(findResource(kDefaultMesh));
    if (mesh.isEmpty()) {
        warn(window, FirstRun::tr("Cannot open the sample scene"),
             FirstRun::tr("The sample mesh %1 was not found (set PALPATE_RESOURCES).").arg(QLatin1String(kDefaultMesh)));
        return;
    }
    warn(window, FirstRun::tr("Cannot open the sample scene"), window.loadMesh(mesh));
    window.viewport()->fitCamera();
}

void tryTouchMode(MainWindow& window) {
    if (QString error = window.setDeviceUri(QLatin1String(HapticSession::kInteractiveDeviceUri)); !error.isEmpty()) {
        warn(window, FirstRun::tr("Cannot start touch mode"), error);
        return;
    }
    window.setTouchMode(true);
    window.setPlaying(true);
    window.statusBar()->showMessage(
        FirstRun::tr("Touch mode: left-drag presses the tissue, the wheel sets the depth, right-drag turns the view."), 15000);
}

void runExampleExercise(MainWindow& window) {
    const QString exercise = QString::fromStdString(findResource("exercises/press_targets.json"));
    if (exercise.isEmpty()) {
        warn(window, FirstRun::tr("Cannot run the example exercise"),
             FirstRun::tr("The example exercise exercises/press_targets.json was not found (set PALPATE_RESOURCES)."));
        return;
    }
    window.setMode(MainWindow::Mode::Trainee);
    warn(window, FirstRun::tr("Cannot run the example exercise"), window.runExercise(exercise, QString()));
}

/// The guide's browser: Qt's Markdown reader names no headings, so every document it loads gets
/// their anchors (a reload too: a web link's click reloads the page).
class GuideBrowser final : public QTextBrowser {
public:
    using QTextBrowser::QTextBrowser;

protected:
    void doSetSource(const QUrl& name, QTextDocument::ResourceType type) override {
        QTextBrowser::doSetSource(name, type);
        addHeadingAnchors(*document());  // a page reloaded needs them again
        // The fragment was looked for before the anchors existed.
        if (!name.fragment().isEmpty()) scrollToAnchor(name.fragment());
    }
};

/// GitHub's heading slug: lower case, letters, digits, '-' and '_' kept, spaces to '-', the rest dropped.
QString headingSlug(const QString& heading) {
    QString slug;
    for (const QChar c : heading.trimmed().toLower()) {
        if (c.isLetterOrNumber() || c == QLatin1Char('-') || c == QLatin1Char('_')) slug += c;
        else if (c == QLatin1Char(' ')) slug += QLatin1Char('-');
    }
    return slug;
}

}  // namespace

void setApplicationNames() {
    QCoreApplication::setApplicationName(QStringLiteral("palpate"));
    // QSettings takes the domain when there is no organization name, QStandardPaths only the name:
    // the preferences go to ~/.config/palpate/palpate.conf and the data stays in
    // ~/.local/share/palpate (an organization name would move it to ~/.local/share/palpate/palpate).
    QCoreApplication::setOrganizationName(QString());
    QCoreApplication::setOrganizationDomain(QStringLiteral("palpate"));
}

bool migrateOldSettings() {
    const QString newPath = QSettings().fileName();
    const QDir oldFolder(QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation) +
                         QStringLiteral("/Unknown Organization"));
    const QString oldPath = oldFolder.filePath(QCoreApplication::applicationName() + QStringLiteral(".conf"));
    if (QFileInfo::exists(newPath) || !QFileInfo::exists(oldPath)) return false;
    QDir().mkpath(QFileInfo(newPath).absolutePath());
    if (!QFile::rename(oldPath, newPath) && !QFile::copy(oldPath, newPath)) return false;
    QDir().rmdir(oldFolder.absolutePath());  // only when empty: other programs' files stay
    return true;
}

void addHeadingAnchors(QTextDocument& document) {
    QHash<QString, int> seen;
    std::vector<std::pair<QTextBlock, QString>> unnamed;
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() == 0 || block.length() <= 1) continue;
        const QString base = headingSlug(block.text());
        const int repeat = seen[base]++;
        const QString slug = repeat > 0 ? QStringLiteral("%1-%2").arg(base).arg(repeat) : base;
        if (!block.begin().fragment().charFormat().anchorNames().contains(slug)) unnamed.emplace_back(block, slug);
    }
    if (unnamed.empty()) return;  // named already: the document stays as it is
    QTextCursor cursor(&document);
    cursor.beginEditBlock();
    for (const auto& [block, slug] : unnamed) {
        cursor.setPosition(block.position());
        cursor.setPosition(block.position() + block.length() - 1, QTextCursor::KeepAnchor);
        QTextCharFormat anchor;
        anchor.setAnchor(true);
        anchor.setAnchorNames({slug});
        cursor.mergeCharFormat(anchor);
    }
    cursor.endEditBlock();
}

bool loadLanguage(QCoreApplication& app, const QString& language) {
    for (QTranslator** t : {&gAppTranslator, &gQtTranslator}) {
        if (*t) {
            app.removeTranslator(*t);
            delete *t;
            *t = nullptr;
        }
    }
    // Numbers and dates follow the language shown ("0,5 N" in German), English the system's.
    QLocale::setDefault(language == QLatin1String("de") || language == QLatin1String("ms") ? QLocale(language)
                                                                                           : QLocale::system());
    if (language != QLatin1String("de") && language != QLatin1String("ms")) return false;
    auto translator = std::make_unique<QTranslator>();
    if (!translator->load(QStringLiteral(":/i18n/palpate_%1.qm").arg(language))) return false;
    gAppTranslator = translator.release();
    app.installTranslator(gAppTranslator);
    // Qt's own strings (standard buttons, file dialogs) when Debian's qt6-translations-l10n is installed.
    auto qt = std::make_unique<QTranslator>();
    if (qt->load(QStringLiteral("qtbase_%1").arg(language), QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        gQtTranslator = qt.release();
        app.installTranslator(gQtTranslator);
    }
    return true;
}

QString installTranslator(QCoreApplication& app) {
    const QString language = Preferences::load().effectiveLanguage();
    return loadLanguage(app, language) ? language : QStringLiteral("en");
}

QString preferredDeviceUri() { return Preferences::load().deviceUri; }

void applyPreferences(MainWindow& window) {
    const Preferences p = Preferences::load();
    // The data folder (the default one too, when the preference was cleared): recordings/ and
    // results.sqlite in it. Nothing is reopened when they are there already.
    const QDir folder(p.effectiveDataFolder());
    const QString recordings = folder.filePath(QStringLiteral("recordings"));
    // The recorder's own Folder… choice (QSettings "recorder/folder") stays.
    if (!QSettings().contains(QStringLiteral("recorder/folder")) && window.recorderPanel()->recordingFolder() != recordings)
        window.recorderPanel()->setRecordingFolder(recordings);
    const QString database = resultsStorePath(folder.absolutePath());
    if (window.exercises().database().path() != database && !window.exercises().running()) {
        QDir().mkpath(folder.absolutePath());
        window.exercises().openDatabase(database);
    }
    window.resultUploader()->setLocations(window.exercises().database().path(), p.resultsServer);
    if (p.hapticRateHz > 0 && window.session().preset().hapticRateHz != p.hapticRateHz && !window.exercises().running()) {
        TissuePreset preset = window.session().preset();
        preset.hapticRateHz = p.hapticRateHz;
        window.parameterPanel()->setPreset(preset);
        warn(window, FirstRun::tr("Haptic rate not applied"), window.applyPreset(preset));
    }
}

WelcomePage* showWelcome(MainWindow& window) {
    if (WelcomePage* open = findOpen<WelcomePage>(window, QStringLiteral("welcomePage"))) {
        open->raise();
        open->activateWindow();
        return open;
    }
    auto* page = new WelcomePage(&window);
    page->setAttribute(Qt::WA_DeleteOnClose);
    page->setDontShowAgain(QSettings().value(Preferences::kFirstRunDoneKey, false).toBool());
    MainWindow* w = &window;
    QObject::connect(page, &WelcomePage::sampleSceneRequested, w, [w] { openSampleScene(*w); });
    QObject::connect(page, &WelcomePage::touchModeRequested, w, [w] { tryTouchMode(*w); });
    QObject::connect(page, &WelcomePage::exerciseRequested, w, [w] { runExampleExercise(*w); });
    QObject::connect(page, &WelcomePage::userGuideRequested, w, [w] { openUserGuide(w); });
    QObject::connect(page, &QDialog::finished, page,
                     [page] { QSettings().setValue(Preferences::kFirstRunDoneKey, page->dontShowAgain()); });
    page->open();
    return page;
}

WelcomePage* maybeShowWelcome(MainWindow& window, const QStringList& commandLineOptions) {
    if (QSettings().value(Preferences::kFirstRunDoneKey, false).toBool()) return nullptr;
    // `palpate --exercise FILE` and the like: the page would cover what was asked for.
    static const QStringList kTaskOptions = {
        QStringLiteral("mesh"),       QStringLiteral("exercise"),       QStringLiteral("trainee"),
        QStringLiteral("preset"),     QStringLiteral("open-recording"), QStringLiteral("screenshot"),
        QStringLiteral("grab-after-ms"), QStringLiteral("show-dialog")};
    for (const QString& option : commandLineOptions)
        if (kTaskOptions.contains(option)) return nullptr;
    return showWelcome(window);
}

PreferencesDialog* openPreferences(MainWindow& window) {
    if (auto* open = findOpen<PreferencesDialog>(window, QStringLiteral("preferencesDialog"))) {
        open->raise();
        open->activateWindow();
        return open;
    }
    auto* dialog = new PreferencesDialog(&window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    MainWindow* w = &window;
    QObject::connect(dialog, &QDialog::accepted, w, [w] { applyPreferences(*w); });
    dialog->open();
    return dialog;
}

QString userGuidePath() {
    QStringList candidates;
    candidates << QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("../share/doc/palpate/user-guide.md"));
    if (const std::string source = findResource("../docs/user-guide.md"); !source.empty())
        candidates << QString::fromStdString(source);
    for (const QString& path : candidates)
        if (QFileInfo(path).isFile()) return QFileInfo(path).canonicalFilePath();
    return {};
}

UrlOpener setUrlOpener(UrlOpener opener) { return std::exchange(urlOpener(), std::move(opener)); }

QWidget* openUserGuide(QWidget* parent) {
    if (parent)
        for (QDialog* open : parent->findChildren<QDialog*>(QStringLiteral("userGuide"), Qt::FindDirectChildrenOnly))
            if (open->isVisible()) {
                open->raise();
                open->activateWindow();
                return open;
            }
    const QString path = userGuidePath();
    if (path.isEmpty()) {
        QMessageBox::warning(parent, FirstRun::tr("User Guide"),
                             FirstRun::tr("The user guide (user-guide.md) was not found. It is installed in "
                                "share/doc/palpate; in a source tree it is docs/user-guide.md."));
        return nullptr;
    }
    auto* window = new QDialog(parent, Qt::Window);
    window->setObjectName(QStringLiteral("userGuide"));
    window->setAttribute(Qt::WA_DeleteOnClose);
    window->setWindowTitle(FirstRun::tr("Palpate User Guide"));
    auto* browser = new GuideBrowser(window);
    browser->setObjectName(QStringLiteral("userGuideBrowser"));
    browser->setOpenLinks(true);
    browser->setOpenExternalLinks(false);
    browser->setSearchPaths({QFileInfo(path).absolutePath()});
    browser->setSource(QUrl::fromLocalFile(path), QTextDocument::MarkdownResource);
    // Links inside the guide stay in the browser; web links go out through the opener.
    QObject::connect(browser, &QTextBrowser::anchorClicked, browser, [browser](const QUrl& url) {
        if (url.scheme() == QLatin1String("http") || url.scheme() == QLatin1String("https") ||
            url.scheme() == QLatin1String("mailto")) {
            browser->setSource(browser->source());  // stay on the page
            urlOpener()(url);
        }
    });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, window);
    QObject::connect(buttons, &QDialogButtonBox::rejected, window, &QDialog::close);
    auto* layout = new QVBoxLayout(window);
    layout->addWidget(browser);
    layout->addWidget(buttons);
    window->resize(900, 700);
    window->show();
    return window;
}

void installFirstRunActions(MainWindow& window, QMenu* editMenu, QMenu* helpMenu) {
    MainWindow* w = &window;
    if (editMenu) {
        editMenu->addSeparator();
        QAction* preferences = editMenu->addAction(FirstRun::tr("&Preferences…"), w, [w] { openPreferences(*w); });
        preferences->setObjectName(QStringLiteral("preferencesAction"));
        preferences->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Comma));
        preferences->setMenuRole(QAction::PreferencesRole);
    }
    if (helpMenu) {
        QAction* first = helpMenu->actions().isEmpty() ? nullptr : helpMenu->actions().front();
        QAction* guide = new QAction(FirstRun::tr("&User Guide"), helpMenu);
        guide->setObjectName(QStringLiteral("userGuideAction"));
        guide->setShortcut(QKeySequence::HelpContents);  // F1
        QObject::connect(guide, &QAction::triggered, w, [w] { openUserGuide(w); });
        QAction* welcome = new QAction(FirstRun::tr("&Welcome"), helpMenu);
        welcome->setObjectName(QStringLiteral("welcomeAction"));
        QObject::connect(welcome, &QAction::triggered, w, [w] { showWelcome(*w); });
        helpMenu->insertAction(first, guide);
        helpMenu->insertAction(first, welcome);
        if (first) helpMenu->insertSeparator(first);
    }
}

QWidget* showFirstRunDialog(MainWindow& window, const QString& name) {
    if (name == QLatin1String("welcome")) return showWelcome(window);
    if (name == QLatin1String("preferences")) return openPreferences(window);
    if (name == QLatin1String("guide")) return openUserGuide(&window);
    return nullptr;
}

}  // namespace palpate
