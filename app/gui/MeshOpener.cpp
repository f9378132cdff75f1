#include "app/gui/MeshOpener.h"

#include "app/gui/ExerciseController.h"
#include "base/resources/ShippedResources.h"
#include "widgets/MeshImportDialog.h"
#include "widgets/MeshSizeText.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QList>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPair>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>

namespace palpate {

namespace {

constexpr int kMaxRecentFiles = 8;
const char* const kRecentFilesKey = "recentFiles";
const char* const kMeshFolderKey = "meshes/lastFolder";  // where File > Open Mesh… starts
const char* const kMeshUnitsKey = "meshUnits";           // each mesh file's unit: path, unit (newest first)
constexpr int kMaxRememberedUnits = 500;                 // the oldest answers are forgotten (asked again)

/// The remembered units, newest first: (absolute path, unit text). An array in the settings, so
/// that the file stays readable (a map would be a binary blob).
QList<QPair<QString, QString>> readMeshUnits(QSettings& settings) {
    QList<QPair<QString, QString>> entries;
    const int count = settings.beginReadArray(kMeshUnitsKey);
    for (int i = 0; i < count; ++i) {
        settings.setArrayIndex(i);
        entries.append({settings.value("path").toString(), settings.value("unit").toString()});
    }
    settings.endArray();
    return entries;
}

}  // namespace

MeshOpener::MeshOpener(QMainWindow& window, HapticSession& session, const ExerciseController& exercises,
                       QObject* parent)
    : QObject(parent), mWindow(window), mSession(session), mExercises(exercises) {}

QString MeshOpener::loadMesh(const QString& path, bool* deviceFailed) {
    const MeshUnit unit = rememberedMeshUnit(path).value_or(kMillimetres);
    return finishLoad(path, mSession.loadMesh(path.toStdString(), unit, deviceFailed));
}

QString MeshOpener::finishLoad(const QString& path, const std::string& error) {
    if (!error.empty()) return QString::fromStdString(error);
    addRecentFile(path);
    emit loaded(path);
    return {};
}

std::optional<MeshUnit> MeshOpener::rememberedMeshUnit(const QString& path) {
    QSettings settings;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    for (const auto& [file, unit] : readMeshUnits(settings)) {
        if (file != absolute) continue;
        std::string ignored;
        return parseMeshUnit(unit.toStdString(), ignored);  // an edited, invalid setting: asked again
    }
    return std::nullopt;
}

void MeshOpener::rememberMeshUnit(const QString& path, const MeshUnit& unit) {
    QSettings settings;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    auto entries = readMeshUnits(settings);
    entries.removeIf([&absolute](const auto& entry) { return entry.first == absolute; });
    entries.prepend({absolute, QString::fromStdString(unit.text())});
    while (entries.size() > kMaxRememberedUnits) entries.removeLast();
    settings.remove(kMeshUnitsKey);
    settings.beginWriteArray(kMeshUnitsKey, int(entries.size()));
    for (int i = 0; i < entries.size(); ++i) {
        settings.setArrayIndex(i);
        settings.setValue("path", entries[i].first);
        settings.setValue("unit", entries[i].second);
    }
    settings.endArray();
}

QString MeshOpener::openMeshFile(const QString& path) {
    // Asked before: as answered then. Otherwise read as mm first: its size decides whether to ask
    // (docs/meshes.md, "Units").
    const std::optional<MeshUnit> remembered = rememberedMeshUnit(path);
    MeshReport report;
    std::string error;
    auto mesh = HapticSession::loadTissueMesh(path.toStdString(), error, remembered.value_or(kMillimetres), &report);
    const auto suggestion = !remembered && report.bboxDiagonalMm > 0.0 ? suggestMeshUnit(report.bboxDiagonalMm)
                                                                       : std::nullopt;
    if (suggestion) {
        const QString unitName = QString::fromStdString(suggestion->unit.text());
        QMessageBox box(QMessageBox::Question, tr("Which unit is this mesh in?"),
                        tr("%1 is %2 if its coordinates are millimetres.")
                            .arg(QFileInfo(path).fileName(), meshSizeText(report.sizeMm)),
                        QMessageBox::NoButton, &mWindow);
        box.setObjectName(QStringLiteral("meshUnitQuestion"));
        QString reason = QString::fromStdString(suggestion->reason);
        if (!reason.isEmpty()) reason[0] = reason[0].toUpper();  // the engine's sentence starts a paragraph here
        box.setInformativeText(reason);
        QPushButton* suggested = box.addButton(tr("Open in %1").arg(unitName), QMessageBox::AcceptRole);
        suggested->setObjectName(QStringLiteral("openInSuggestedUnit"));
        QPushButton* asMm = box.addButton(tr("Open as mm"), QMessageBox::AcceptRole);
        asMm->setObjectName(QStringLiteral("openAsMillimetres"));
        QPushButton* import = box.addButton(tr("Import…"), QMessageBox::ActionRole);
        import->setObjectName(QStringLiteral("openInImportDialog"));
        box.addButton(QMessageBox::Cancel);
        box.setDefaultButton(suggested);
        box.exec();
        if (box.clickedButton() == import) {
            openImportDialog(path);
            return {};
        }
        if (box.clickedButton() == suggested) {
            mesh = HapticSession::loadTissueMesh(path.toStdString(), error, suggestion->unit, &report);
            if (mesh) rememberMeshUnit(path, suggestion->unit);
        } else if (box.clickedButton() == asMm) {
            if (mesh) rememberMeshUnit(path, kMillimetres);
        } else {
            return {};  // cancelled: nothing opened, nothing remembered
        }
    }
    if (!mesh) {
        showOpenError(path, QString::fromStdString(error), report.triangleCount > 0);
        return QString::fromStdString(error);
    }
    const QString loaded = finishLoad(path, mSession.loadMesh(path.toStdString(), std::move(*mesh)));
    if (!loaded.isEmpty()) showOpenError(path, loaded, false);
    return loaded;
}

void MeshOpener::showOpenError(const QString& path, const QString& error, bool offerImport) {
    // The error names the file and every problem found. A file that was read but refused (faults, a
    // size no unit explains) may import: repair and the unit are the import dialog's.
    QMessageBox box(QMessageBox::Warning, tr("Cannot open mesh"), error, QMessageBox::Close, &mWindow);
    box.setObjectName(QStringLiteral("meshOpenError"));
    QPushButton* import = nullptr;
    if (offerImport) {
        import = box.addButton(tr("Import…"), QMessageBox::ActionRole);
        import->setObjectName(QStringLiteral("openInImportDialog"));
        box.setInformativeText(tr("Import Mesh can repair the faults and scale the file to mm."));
    }
    box.exec();
    if (import && box.clickedButton() == import) openImportDialog(path);
}

MeshImportDialog* MeshOpener::openImportDialog(const QString& path) {
    if (!mImportDialog) {
        mImportDialog = new MeshImportDialog(&mWindow);
        mImportDialog->resize(760, 620);
        connect(mImportDialog, &MeshImportDialog::imported, this, [this](const QString& output) {
            // Written in mm: so it is read, whatever an older file of that name was read in.
            rememberMeshUnit(output, kMillimetres);
            if (mExercises.running()) {
                mWindow.statusBar()->showMessage(tr("An exercise is running: the mesh cannot change now."), 6000);
                return;
            }
            // No message on success: it would hide the status bar's mesh field, which names the new file.
            if (const QString error = loadMesh(output); !error.isEmpty())
                QMessageBox::warning(&mWindow, tr("Cannot open mesh"), error);
        });
    }
    if (!path.isEmpty()) mImportDialog->setInputPath(path);
    mImportDialog->show();
    mImportDialog->raise();
    mImportDialog->activateWindow();
    return mImportDialog;
}

QString MeshOpener::meshDialogFolder() {
    const QString last = QSettings().value(kMeshFolderKey).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir()) return last;
    const std::string bundled = findResource(kDefaultMesh);
    return bundled.empty() ? QString() : QFileInfo(QString::fromStdString(bundled)).absolutePath();
}

void MeshOpener::openMeshDialog() {
    // Its own folder: without one, Qt starts where any file dialog was last (the recordings, say).
    const QString path = QFileDialog::getOpenFileName(&mWindow, tr("Open Mesh"), meshDialogFolder(),
                                                      tr("Meshes (*.obj *.off *.ply *.stl *.om);;All files (*)"));
    if (path.isEmpty()) return;
    if (openMeshFile(path).isEmpty()) QSettings().setValue(kMeshFolderKey, QFileInfo(path).absolutePath());
}

QStringList MeshOpener::recentFiles() { return QSettings().value(kRecentFilesKey).toStringList(); }

void MeshOpener::setRecentMenu(QMenu* menu) {
    mRecentMenu = menu;
    rebuildRecentMenu();
}

void MeshOpener::addRecentFile(const QString& path) {
    QStringList files = recentFiles();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    QSettings().setValue(kRecentFilesKey, files);
    rebuildRecentMenu();
}

void MeshOpener::rebuildRecentMenu() {
    if (!mRecentMenu) return;
    mRecentMenu->clear();
    const QStringList files = recentFiles();
    for (int i = 0; i < files.size(); ++i) {
        const QString path = files[i];
        QAction* action = mRecentMenu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()));
        action->setToolTip(path);
        connect(action, &QAction::triggered, this, [this, path] { openMeshFile(path); });
    }
    mRecentMenu->setEnabled(!files.isEmpty());
}

}  // namespace palpate
