#pragma once
// The first-run experience and the preferences, wired to a MainWindow through its public API:
// the translator, the welcome page, Edit > Preferences…, Help > Welcome and Help > User Guide (F1).
//
// MainWindow::createMenus() ends with   installFirstRunActions(*this, edit, help);
// main.cpp calls setApplicationNames() and migrateOldSettings() right after QApplication exists,
// before anything reads QSettings; then installTranslator(), preferredDeviceUri() for the
// interactive default device, applyPreferences(window) once the window exists (before --preset, so
// that an explicit preset wins), and maybeShowWelcome(window) once the interactive window is shown.

#include <QString>
#include <QStringList>
#include <QUrl>

#include <functional>

class QCoreApplication;
class QMenu;
class QTextDocument;
class QWidget;

namespace palpate {

class MainWindow;
class PreferencesDialog;
class WelcomePage;

/// The names QSettings and QStandardPaths build their paths from (docs/user-guide.md, "Where
/// Palpate keeps things"): the preferences in ~/.config/palpate/palpate.conf, the data folder
/// ~/.local/share/palpate.
void setApplicationNames();
/// Palpate 0.1 kept its preferences in ~/.config/Unknown Organization/palpate.conf (no organization
/// was set). Moves that file to QSettings' file, once: only while the new one does not exist. True
/// when moved. After setApplicationNames(), before the first QSettings.
bool migrateOldSettings();

/// Loads the translation of Preferences::effectiveLanguage() (QSettings "language", else the system
/// locale) from the embedded :/i18n/palpate_<lang>.qm, and Qt's own (qtbase_<lang>) when installed.
/// Returns the language in use: "de", "ms", or "en" (no translator needed).
QString installTranslator(QCoreApplication& app);
/// Loads `language` ("de", "ms"; anything else removes Palpate's translator). True when loaded.
/// For tests that switch languages; the GUI switches at start only.
bool loadLanguage(QCoreApplication& app, const QString& language);

/// Adds Edit > Preferences… (Ctrl+,) and Help > Welcome, Help > User Guide (F1) to the window.
void installFirstRunActions(MainWindow& window, QMenu* editMenu, QMenu* helpMenu);

/// QSettings "device/defaultUri", "" when unset (then the built-in default applies).
QString preferredDeviceUri();
/// The stored preferences that act on a window: the data folder (recordings/, results.sqlite) and
/// the haptic rate. Called at start; the Preferences dialog's OK calls it again.
void applyPreferences(MainWindow& window);

/// Shows the welcome page (non-modal) unless QSettings "firstRunDone" is true, or the command line
/// already says what to do: `commandLineOptions` (QCommandLineParser::optionNames(), the options
/// given) has one of --mesh, --exercise, --trainee, --preset, --open-recording, --screenshot,
/// --grab-after-ms, --show-dialog. Null if not shown.
WelcomePage* maybeShowWelcome(MainWindow& window, const QStringList& commandLineOptions = {});
/// Shows the welcome page (Help > Welcome). "Don't show this again" sets "firstRunDone"; closing
/// the first-run page without it ticked shows it again at the next start.
WelcomePage* showWelcome(MainWindow& window);
/// Shows the Preferences dialog (non-modal); OK saves and applies (applyPreferences).
PreferencesDialog* openPreferences(MainWindow& window);

/// The user guide to open: the installed <prefix>/share/doc/palpate/user-guide.md, else the
/// source tree's docs/user-guide.md. "" when neither exists.
QString userGuidePath();
/// Help > User Guide: shows the guide (Markdown, with its pictures) in a window of its own. Links
/// to web pages go to the URL opener; the contents' links (#heading-slug) scroll to their heading.
/// Null, with a message box, when the guide is not found.
QWidget* openUserGuide(QWidget* parent);
/// Gives every heading of a Markdown document the anchor name a link to it uses: GitHub's slug
/// ("Where Palpate keeps things" -> where-palpate-keeps-things; a repeated heading gets -1, -2...).
/// Qt's Markdown reader names no headings, so `#slug` links would not scroll without this.
void addHeadingAnchors(QTextDocument& document);
/// What opens web links from the guide: QDesktopServices::openUrl unless replaced (tests replace it
/// so that no browser starts). Returns the previous opener.
using UrlOpener = std::function<bool(const QUrl&)>;
UrlOpener setUrlOpener(UrlOpener opener);

/// For the guide's screenshots (palpate --show-dialog NAME --screenshot FILE --whole-window): shows
/// "welcome", "preferences" or "guide" over the window and returns it; null for another name.
QWidget* showFirstRunDialog(MainWindow& window, const QString& name);

}  // namespace palpate
