#pragma once
// How the window opens a mesh file: File > Open Mesh…, Open Recent, Import Mesh… and a drop. It
// asks once for the unit of a mesh whose size is implausible in mm and remembers the answer per
// file (docs/meshes.md, "Units"), offers the import dialog for a mesh refused for its faults, and
// keeps the recent files. The window shows the mesh once it is loaded (the loaded signal).

#include "app/gui/HapticSession.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>
#include <string>

class QMainWindow;
class QMenu;

namespace palpate {

class ExerciseController;
class MeshImportDialog;

class MeshOpener final : public QObject {
    Q_OBJECT
public:
    /// Its dialogs and messages are `window`'s; no mesh changes while `exercises` runs one.
    MeshOpener(QMainWindow& window, HapticSession& session, const ExerciseController& exercises,
               QObject* parent = nullptr);

    /// Loads `path` in the unit remembered for it (mm if none); see MainWindow::loadMesh.
    QString loadMesh(const QString& path, bool* deviceFailed = nullptr);
    /// The rest of a mesh load once the session has it (or `error`): the recent files, then loaded(). "" or `error`.
    QString finishLoad(const QString& path, const std::string& error);
    /// Asks for the unit when needed, offers Import…; see MainWindow::openMeshFile.
    QString openMeshFile(const QString& path);
    /// File > Open Mesh…: the file dialog, starting in meshDialogFolder().
    void openMeshDialog();
    /// File > Import Mesh…: the dialog (one per window, kept), with `path` previewed if given.
    MeshImportDialog* openImportDialog(const QString& path = {});
    /// The import dialog once opened (null before).
    MeshImportDialog* importDialog() const { return mImportDialog; }

    /// The unit a mesh file is read in, as chosen for it before (QSettings "meshUnits", by
    /// absolute path); nullopt when never asked.
    static std::optional<MeshUnit> rememberedMeshUnit(const QString& path);
    static void rememberMeshUnit(const QString& path, const MeshUnit& unit);
    /// Where File > Open Mesh… starts: the folder a mesh was last opened from with it (QSettings
    /// "meshes/lastFolder"), else the bundled meshes.
    static QString meshDialogFolder();

    /// Recent mesh files, newest first (kept in QSettings).
    static QStringList recentFiles();
    /// File > Open Recent: filled now and after each mesh opened.
    void setRecentMenu(QMenu* menu);

signals:
    /// The session has the mesh in `path` (the window draws it, or will once the loop runs it).
    void loaded(const QString& path);

private:
    /// Shows why `path` cannot be opened; offers the import dialog when importing may help.
    void showOpenError(const QString& path, const QString& error, bool offerImport);
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();

    QMainWindow& mWindow;
    HapticSession& mSession;
    const ExerciseController& mExercises;
    QMenu* mRecentMenu = nullptr;
    MeshImportDialog* mImportDialog = nullptr;  // owned by Qt (child of the window)
};

}  // namespace palpate
