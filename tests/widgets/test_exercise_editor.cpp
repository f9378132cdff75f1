// The instructor's exercise editor under QT_QPA_PLATFORM=offscreen (main() is in test_viewport.cpp):
// shipped examples open as the engine reads them; targets, the lump and path points placed by
// clicks (stored in the mesh file's numbering, drawn at the engine vertex's rest position); undo
// and redo; problems naming the key; save writes resources-relative paths that load back the
// same; the rubric; a mesh mismatch; Try it; malformed files; the modified flag and the discard
// question; targets whose window the mouse cannot reach are warned about, the first target gets a
// window it can, and every shipped example can be done with the mouse; in the main window,
// clicking places targets while touch mode is on, and Try it leaves touch mode on.
#include "base/resources/ShippedResources.h"
#include "app/gui/ExerciseController.h"
#include "app/gui/HapticSession.h"
#include "app/gui/MainWindow.h"
#include "widgets/ExerciseEditCommands.h"
#include "widgets/ExerciseEditorPanel.h"
#include "widgets/Viewport.h"
#include "widgets/OrbitCamera.h"
#include <QPainter>
#include <glm/geometric.hpp>

#include "engine/core/TissueMesh.h"
#include "widgets/ParameterPanel.h"
#include "widgets/ChartsPanel.h"
#include "widgets/StiffeningPanel.h"
#include "engine/exercise/ExerciseBundle.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/scoring/TargetReachability.h"
#include "engine/exercise/ExerciseKind.h"

#include <QAction>
#include <QElapsedTimer>
#include <QWheelEvent>
#include <QScrollBar>
#include <QApplication>
#include <QElapsedTimer>
#include <QComboBox>
#include <QPlainTextEdit>
#include <QDockWidget>
#include <QDir>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMouseEvent>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalSpy>
#include <QStackedWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

using namespace palpate;

namespace {

const std::string kResources = std::string(PALPATE_SOURCE_DIR) + "/resources/";

/// The source tree's resources/, as the app's findResource finds them.
std::string findInSource(const std::string& relative) {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::path(kResources) / relative;
    return std::filesystem::is_regular_file(p, ec) ? std::filesystem::weakly_canonical(p, ec).string() : std::string();
}

std::string json(const Exercise& e) { return exerciseToJson(e, -1); }

struct DrawnMesh {
    std::shared_ptr<const TissueMesh> mesh;
    QString path;
};

DrawnMesh loadMesh(const char* relative) {
    const std::string path = findInSource(relative);
    auto loaded = TissueMesh::load(path);
    EXPECT_TRUE(loaded.mesh) << loaded.error();
    return {loaded.mesh ? std::make_shared<const TissueMesh>(std::move(*loaded.mesh)) : nullptr, QString::fromStdString(path)};
}

/// `count` engine vertices spread over the mesh.
std::vector<VertexId> spreadVertices(const TissueMesh& mesh, std::size_t count) {
    std::vector<VertexId> out;
    for (std::size_t i = 0; i < count; ++i) out.push_back(VertexId(7 + i * (mesh.vertexCount() - 8) / count));
    return out;
}

/// The shipped meshes are stored in the engine's order already (originalIndex is the identity):
/// a copy with its vertices written in reverse tells the file's numbering from the engine's.
QString writeReversedOff(const std::string& sourceOff, const QString& target) {
    std::ifstream in(sourceOff);
    std::string header;
    std::size_t nv = 0, nf = 0, ne = 0;
    in >> header >> nv >> nf >> ne;
    std::vector<std::array<double, 3>> vertices(nv);
    for (auto& v : vertices) in >> v[0] >> v[1] >> v[2];
    std::ofstream out(target.toStdString());
    out << "OFF\n" << nv << ' ' << nf << " 0\n";
    out.precision(9);
    for (std::size_t i = nv; i-- > 0;) out << vertices[i][0] << ' ' << vertices[i][1] << ' ' << vertices[i][2] << '\n';
    for (std::size_t f = 0; f < nf; ++f) {
        std::size_t k = 0, a = 0, b = 0, c = 0;
        in >> k >> a >> b >> c;
        out << "3 " << nv - 1 - a << ' ' << nv - 1 - b << ' ' << nv - 1 - c << '\n';
    }
    return out ? target : QString();
}

/// The panel with the markers it last sent.
struct Editor {
    ExerciseEditorPanel panel{findInSource};
    ExerciseMarkers lastMarkers;
    int markerSignals = 0;
    Editor() {
        QObject::connect(&panel, &ExerciseEditorPanel::markersChanged, [this](const ExerciseMarkers& m) {
            lastMarkers = m;
            ++markerSignals;
        });
    }
};

template <typename T>
T* child(QWidget& parent, const char* name) {
    T* w = parent.findChild<T*>(QLatin1String(name));
    EXPECT_NE(w, nullptr) << name;
    return w;
}

int rubricRow(ExerciseEditorPanel& panel, const char* metric) {
    auto* table = child<QTableWidget>(panel, "rubricTable");
    for (int r = 0; r < table->rowCount(); ++r)
        if (table->item(r, 0)->text() == QLatin1String(metric)) return r;
    return -1;
}

/// The panel's warnings once the reach check of its latest change has answered (it runs on a
/// worker thread).
QStringList shownWarnings(ExerciseEditorPanel& panel) {
    QElapsedTimer waited;
    waited.start();
    while (panel.reachChecking() && waited.elapsed() < 120000)
        QCoreApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents, 50);
    EXPECT_FALSE(panel.reachChecking()) << "the reach check did not answer in 2 minutes";
    return panel.warnings();
}

bool hasProblemStartingWith(const QStringList& problems, const QString& key) {
    for (const QString& p : problems)
        if (p.startsWith(key)) return true;
    return false;
}

}  // namespace

// Scrolling the editor's form with the wheel does not change a field that passes under the cursor.
TEST(ExerciseEditor, WheelOverAnUnfocusedFieldScrollsTheFormAndLeavesTheField) {
    Editor editor;
    editor.panel.newExercise(ExerciseType::PressTargets);
    editor.panel.resize(420, 300);  // shorter than the form: it scrolls
    editor.panel.show();
    QApplication::processEvents();
    auto* scroll = editor.panel.findChild<QScrollArea*>(QStringLiteral("exerciseEditorScroll"));
    ASSERT_NE(scroll, nullptr);
    ASSERT_GT(scroll->verticalScrollBar()->maximum(), 0);
    auto* timeLimit = editor.panel.findChild<QDoubleSpinBox*>(QStringLiteral("timeLimitSpin"));
    ASSERT_NE(timeLimit, nullptr);
    const double before = timeLimit->value();
    const int scrolledBefore = scroll->verticalScrollBar()->value();
    const QPointF local = timeLimit->rect().center();
    QWheelEvent wheel(local, timeLimit->mapToGlobal(local), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(timeLimit, &wheel);
    EXPECT_EQ(timeLimit->value(), before);
    EXPECT_GT(scroll->verticalScrollBar()->value(), scrolledBefore);
}

TEST(ExerciseEditor, OpensEachShippedExampleAsTheEngineReadsIt) {
    Editor editor;
    for (const char* name : {"exercises/press_targets.json", "exercises/find_lump.json", "exercises/trace.json"}) {
        const std::string path = findInSource(name);
        ASSERT_FALSE(path.empty()) << name;
        const auto loaded = loadExercise(path);
        ASSERT_TRUE(loaded.exercise) << loaded.error();
        EXPECT_EQ(editor.panel.openExercise(QString::fromStdString(path)), QString()) << name;
        EXPECT_EQ(json(editor.panel.exercise()), json(*loaded.exercise)) << name;
        EXPECT_EQ(editor.panel.exercise().sourcePath, loaded.exercise->sourcePath);
        EXPECT_EQ(editor.panel.currentPath(), QString::fromStdString(path));
        EXPECT_FALSE(editor.panel.isModified());
        EXPECT_EQ(editor.panel.undoStack()->count(), 0);
        // A shipped exercise is valid; only the mesh the viewport shows (none here) is noted.
        for (const QString& p : editor.panel.problems())
            EXPECT_TRUE(p.startsWith(QStringLiteral("mesh: the viewport shows"))) << p.toStdString();
        // The form shows it: the type's page and its name.
        EXPECT_EQ(child<QLineEdit>(editor.panel, "exerciseNameEdit")->text().toStdString(), loaded.exercise->name);
    }
}

TEST(ExerciseEditor, TargetsAddedByClickingAreStoredInFileNumberingAndUndoable) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    ASSERT_TRUE(drawn.mesh);
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::PressTargets);
    EXPECT_EQ(editor.panel.exercise().meshPath, "meshes/sphere_1442.off");  // the drawn mesh, resources-relative
    EXPECT_TRUE(editor.panel.drawnMeshMatches());
    EXPECT_TRUE(editor.panel.exercise().pressTargets.targets.empty());

    QSignalSpy placing(&editor.panel, &ExerciseEditorPanel::placingChanged);
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    ASSERT_EQ(placing.count(), 1);
    EXPECT_TRUE(placing.at(0).at(0).toBool());
    EXPECT_TRUE(child<QToolButton>(editor.panel, "press_targets.targets.add")->isChecked());

    const std::vector<VertexId> picks = spreadVertices(*drawn.mesh, 3);
    ASSERT_EQ(picks.size(), 3u);
    for (VertexId v : picks) editor.panel.vertexPicked(v);

    const auto& targets = editor.panel.exercise().pressTargets.targets;
    ASSERT_EQ(targets.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        ASSERT_TRUE(targets[i].at.vertex);
        EXPECT_EQ(*targets[i].at.vertex, drawn.mesh->originalIndex()[picks[i]]);
    }
    EXPECT_EQ(targets[0].toleranceMm, PressTarget{}.toleranceMm);  // the defaults
    EXPECT_EQ(targets[1].forceMinN, targets[0].forceMinN);  // the first target's window
    EXPECT_EQ(targets[2].forceMaxN, targets[0].forceMaxN);
    EXPECT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::AddItem);  // stays on for more
    EXPECT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();

    auto expectTargetMarkers = [&](std::size_t count) {
        ASSERT_EQ(editor.lastMarkers.markers.size(), count);
        for (std::size_t i = 0; i < count; ++i) {
            const ExerciseMarker& m = editor.lastMarkers.markers[i];
            EXPECT_EQ(m.kind, ExerciseMarker::Kind::Target);
            EXPECT_EQ(m.positionMm, drawn.mesh->restPositionsMm()[picks[i]]) << i;
            EXPECT_EQ(m.label, QString::number(i + 1));
        }
    };
    expectTargetMarkers(3);
    EXPECT_TRUE(editor.lastMarkers.markers[2].selected);  // the one just added
    EXPECT_EQ(child<QTableWidget>(editor.panel, "press_targets.targets")->rowCount(), 3);

    EXPECT_EQ(editor.panel.undoStack()->count(), 3);  // one step per click
    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets.size(), 2u);
    expectTargetMarkers(2);
    EXPECT_EQ(child<QTableWidget>(editor.panel, "press_targets.targets")->rowCount(), 2);
    editor.panel.undoStack()->redo();
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets.size(), 3u);
    expectTargetMarkers(3);

    // Selecting a row selects its marker.
    child<QTableWidget>(editor.panel, "press_targets.targets")->selectRow(0);
    EXPECT_EQ(editor.panel.selectedIndex(), 0);
    EXPECT_TRUE(editor.lastMarkers.markers[0].selected);
    EXPECT_FALSE(editor.lastMarkers.markers[2].selected);

    // Esc stops placing (the panel's action), and the window hears it.
    editor.panel.findChild<QAction*>(QStringLiteral("stopPlacingAction"))->trigger();
    EXPECT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::None);
    ASSERT_EQ(placing.count(), 2);
    EXPECT_FALSE(placing.at(1).at(0).toBool());
    editor.panel.vertexPicked(picks[0]);  // not placing: a click changes nothing
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets.size(), 3u);

    // Move: the selected target goes to the next click, in one step, and placing ends.
    const int steps = editor.panel.undoStack()->count();
    child<QToolButton>(editor.panel, "press_targets.targets.move")->click();
    EXPECT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::MoveSelected);
    editor.panel.vertexPicked(1000);
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets[0].at.vertex.value_or(~0u), drawn.mesh->originalIndex()[1000]);
    EXPECT_EQ(editor.lastMarkers.markers[0].positionMm, drawn.mesh->restPositionsMm()[1000]);
    EXPECT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::None);
    EXPECT_EQ(editor.panel.undoStack()->count(), steps + 1);

    // Remove (Delete in the table) removes the selected target; undo brings it back.
    editor.panel.setSelectedIndex(1);
    child<QToolButton>(editor.panel, "press_targets.targets.remove")->click();
    ASSERT_EQ(editor.panel.exercise().pressTargets.targets.size(), 2u);
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets[1].at.vertex.value_or(~0u), drawn.mesh->originalIndex()[picks[2]]);
    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets.size(), 3u);
}

TEST(ExerciseEditor, ClicksOnARenumberedMeshAreStoredInTheFilesNumbering) {
    QTemporaryDir dir;
    const QString meshFile = writeReversedOff(findInSource("meshes/sphere_1442.off"), dir.filePath(QStringLiteral("reversed.off")));
    ASSERT_FALSE(meshFile.isEmpty());
    auto loaded = TissueMesh::load(meshFile.toStdString());
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    const auto mesh = std::make_shared<const TissueMesh>(std::move(*loaded.mesh));
    Editor editor;
    editor.panel.setDrawnMesh(mesh, meshFile);
    editor.panel.newExercise(ExerciseType::PressTargets);
    EXPECT_EQ(QString::fromStdString(editor.panel.exercise().meshPath), QFileInfo(meshFile).canonicalFilePath());  // not under resources/
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    const std::vector<VertexId> picks = spreadVertices(*mesh, 3);
    for (VertexId v : picks) editor.panel.vertexPicked(v);
    ASSERT_EQ(editor.panel.exercise().pressTargets.targets.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        const std::uint32_t stored = editor.panel.exercise().pressTargets.targets[i].at.vertex.value_or(~0u);
        EXPECT_EQ(stored, mesh->originalIndex()[picks[i]]);
        EXPECT_NE(stored, picks[i]);  // the file's numbering, not the engine's
        EXPECT_EQ(editor.lastMarkers.markers.at(i).positionMm, mesh->restPositionsMm()[picks[i]]);
    }
    // Saved beside its mesh: the mesh path is written relative to the exercise, and the targets
    // come back on the vertices that were clicked.
    const QString file = dir.filePath(QStringLiteral("reversed.json"));
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    const auto exercise = loadExercise(file.toStdString());
    ASSERT_TRUE(exercise.exercise) << exercise.error();
    EXPECT_EQ(exercise.exercise->meshPath, "reversed.off");
    std::string error;
    const auto geometry = ExerciseGeometry::build(*exercise.exercise, *mesh, error);
    ASSERT_TRUE(geometry) << error;
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(geometry->targets()[i].vertex, picks[i]);
}

// A mesh outside resources/ and outside the exercise's folder is copied into the folder when the
// exercise is saved, and named relative to it: the folder opens on another computer (here: moved
// elsewhere, the instructor's mesh gone).
TEST(ExerciseEditor, AnExerciseSavedAwayFromItsMeshTakesACopyAndTravels) {
    QTemporaryDir home, elsewhere;
    ASSERT_TRUE(home.isValid() && elsewhere.isValid());
    QDir(home.path()).mkpath(QStringLiteral("meshes"));
    QDir(home.path()).mkpath(QStringLiteral("class"));
    const QString meshFile = home.filePath(QStringLiteral("meshes/organ.off"));
    ASSERT_TRUE(QFile::copy(QString::fromStdString(findInSource("meshes/sphere_1442.off")), meshFile));
    auto loaded = TissueMesh::load(meshFile.toStdString());
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    const auto mesh = std::make_shared<const TissueMesh>(std::move(*loaded.mesh));
    Editor editor;
    editor.panel.setDrawnMesh(mesh, meshFile);
    editor.panel.newExercise(ExerciseType::PressTargets);
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor.panel.vertexPicked(100);
    // Someone else's organ.off is in the class folder already: never overwritten.
    const QString classFolder = home.filePath(QStringLiteral("class"));
    {
        QFile other(classFolder + QStringLiteral("/organ.off"));
        ASSERT_TRUE(other.open(QIODevice::WriteOnly));
        other.write("not this mesh");
    }
    const QString file = classFolder + QStringLiteral("/press.json");
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    const auto saved = loadExercise(file.toStdString());
    ASSERT_TRUE(saved.exercise) << saved.error();
    EXPECT_EQ(saved.exercise->meshPath, "organ-2.off");
    EXPECT_EQ(saved.exercise->tissuePresetPath.rfind("presets/", 0), 0u) << "a shipped preset stays resource-relative";
    auto* message = child<QLabel>(editor.panel, "messageLabel");
    EXPECT_TRUE(message->text().contains(QStringLiteral("organ-2.off"))) << message->text().toStdString();
    QFile other(classFolder + QStringLiteral("/organ.off"));
    ASSERT_TRUE(other.open(QIODevice::ReadOnly));
    EXPECT_EQ(other.readAll(), QByteArray("not this mesh"));
    // Saved again: the copy is reused.
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    EXPECT_FALSE(QFile::exists(classFolder + QStringLiteral("/organ-3.off")));

    // Exported as a bundle: the saved exercise with its copied mesh.
    const QString bundle = home.filePath(QStringLiteral("press.palpex"));
    ASSERT_EQ(editor.panel.exportBundle(bundle), QString());
    std::string error;
    QFile bundleFile(bundle);
    ASSERT_TRUE(bundleFile.open(QIODevice::ReadOnly));
    const auto parsed = parseExerciseBundle(bundleFile.readAll().toStdString(), bundle.toStdString(), error);
    ASSERT_TRUE(parsed) << error;
    EXPECT_EQ(parsed->exercise.meshPath, "organ-2.off");
    EXPECT_EQ(parsed->exerciseFile, "press.json");
    // The Author menu offers it, and a new exercise of every kind.
    const QList<QAction*> actions = editor.panel.editorActions();
    EXPECT_TRUE(actions.contains(child<QAction>(editor.panel, "exportBundleAction")));
    for (const ExerciseKind* kind : exerciseKinds())
        EXPECT_TRUE(actions.contains(editor.panel.newAction(kind->type())));

    // The folder moved to another computer, the instructor's mesh gone: it opens and resolves.
    const QString moved = elsewhere.filePath(QStringLiteral("press.json"));
    ASSERT_TRUE(QFile::copy(file, moved));
    ASSERT_TRUE(QFile::copy(classFolder + QStringLiteral("/organ-2.off"),
                            elsewhere.filePath(QStringLiteral("organ-2.off"))));
    ASSERT_TRUE(QFile::remove(meshFile));
    const auto travelled = loadExercise(moved.toStdString());
    ASSERT_TRUE(travelled.exercise) << travelled.error();
    EXPECT_EQ(QFileInfo(QString::fromStdString(resolveExercisePath(*travelled.exercise, travelled.exercise->meshPath,
                                                                   findInSource))),
              QFileInfo(elsewhere.filePath(QStringLiteral("organ-2.off"))));
    const QString movedMesh = elsewhere.filePath(QStringLiteral("organ-2.off"));
    auto movedLoaded = TissueMesh::load(movedMesh.toStdString());
    ASSERT_TRUE(movedLoaded.mesh) << movedLoaded.error();
    Editor reopened;
    reopened.panel.setDrawnMesh(std::make_shared<const TissueMesh>(std::move(*movedLoaded.mesh)), movedMesh);
    ASSERT_EQ(reopened.panel.openExercise(moved), QString());
    EXPECT_TRUE(reopened.panel.problems().isEmpty()) << reopened.panel.problems().join('\n').toStdString();
}

TEST(ExerciseEditor, ATargetWindowUpsideDownIsNamedByItsKey) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::PressTargets);
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor.panel.vertexPicked(100);
    ASSERT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();

    auto* table = child<QTableWidget>(editor.panel, "press_targets.targets");
    const PressTarget placed = editor.panel.exercise().pressTargets.targets[0];
    const double upsideDownN = 0.5 * placed.forceMinN;
    table->item(0, 3)->setData(Qt::EditRole, upsideDownN);  // Fmax below Fmin, as typed in the cell
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets[0].forceMaxN, upsideDownN);
    EXPECT_TRUE(hasProblemStartingWith(editor.panel.problems(), QStringLiteral("press_targets.targets[0].force_max_n")))
        << editor.panel.problems().join('\n').toStdString();
    EXPECT_TRUE(table->item(0, 3)->data(Qt::BackgroundRole).isValid());  // the cell is marked
    EXPECT_FALSE(table->item(0, 2)->data(Qt::BackgroundRole).isValid());
    auto* problemsLabel = child<QLabel>(editor.panel, "problemsLabel");
    EXPECT_TRUE(problemsLabel->text().contains(QStringLiteral("press_targets.targets[0].force_max_n")));

    // Neither saved nor tried while it is wrong.
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("bad.json"));
    EXPECT_TRUE(editor.panel.saveExercise(file).contains(QStringLiteral("force_max_n")));
    EXPECT_FALSE(QFile::exists(file));
    int previews = 0;
    QObject::connect(&editor.panel, &ExerciseEditorPanel::previewRequested, [&] { ++previews; });
    EXPECT_FALSE(editor.panel.preview());
    EXPECT_EQ(previews, 0);

    editor.panel.undoStack()->undo();
    EXPECT_TRUE(editor.panel.problems().isEmpty());
    EXPECT_EQ(table->item(0, 3)->data(Qt::EditRole).toDouble(), placed.forceMaxN);  // the form shows the undone value
}

TEST(ExerciseEditor, SaveWritesResourceRelativePathsThatLoadBackTheSame) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::PressTargets);
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor.panel.vertexPicked(10);
    editor.panel.vertexPicked(700);
    // The preset given as an absolute path (Browse… outside the list does so): written relative.
    auto* preset = child<QComboBox>(editor.panel, "tissuePresetCombo");
    preset->lineEdit()->setText(QString::fromStdString(findInSource("presets/tissues/liver.json")));
    emit preset->lineEdit()->editingFinished();
    EXPECT_EQ(editor.panel.exercise().tissuePresetPath, findInSource("presets/tissues/liver.json"));
    EXPECT_TRUE(editor.panel.isModified());

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("two_targets.json"));
    QSignalSpy modified(&editor.panel, &ExerciseEditorPanel::modifiedChanged);
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    EXPECT_FALSE(editor.panel.isModified());
    ASSERT_EQ(modified.count(), 1);
    EXPECT_FALSE(modified.at(0).at(0).toBool());
    EXPECT_EQ(editor.panel.currentPath(), QFileInfo(file).absoluteFilePath());

    const auto loaded = loadExercise(file.toStdString());
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    EXPECT_EQ(json(*loaded.exercise), json(editor.panel.exercise()));
    EXPECT_EQ(loaded.exercise->sourcePath, editor.panel.exercise().sourcePath);
    EXPECT_EQ(loaded.exercise->meshPath, "meshes/sphere_1442.off");
    EXPECT_EQ(loaded.exercise->tissuePresetPath, "presets/tissues/liver.json");
    EXPECT_EQ(resolveExercisePath(*loaded.exercise, loaded.exercise->meshPath, findInSource),
              findInSource("meshes/sphere_1442.off"));
    EXPECT_EQ(resolveExercisePath(*loaded.exercise, loaded.exercise->tissuePresetPath, findInSource),
              findInSource("presets/tissues/liver.json"));
    ASSERT_EQ(loaded.exercise->pressTargets.targets.size(), 2u);
    EXPECT_EQ(*loaded.exercise->pressTargets.targets[1].at.vertex, drawn.mesh->originalIndex()[700]);

    // Open it again: the same exercise.
    Editor again;
    ASSERT_EQ(again.panel.openExercise(file), QString());
    EXPECT_EQ(json(again.panel.exercise()), json(*loaded.exercise));

    // An edit after the save is unsaved again; undoing it is back at the saved state.
    editor.panel.vertexPicked(20);
    EXPECT_TRUE(editor.panel.isModified());
    editor.panel.undoStack()->undo();
    EXPECT_FALSE(editor.panel.isModified());
}

TEST(ExerciseEditor, PlacingTheLumpByClickingSetsItsCentre) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::FindLump);
    EXPECT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();
    const auto before = editor.panel.exercise().findLump.inclusion.centre.vertex;
    ASSERT_TRUE(before);

    child<QToolButton>(editor.panel, "find_lump.inclusion.move")->click();
    EXPECT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::MoveSelected);
    const VertexId v = 700;
    ASSERT_NE(*before, drawn.mesh->originalIndex()[v]);  // the click moves it
    editor.panel.vertexPicked(v);
    ASSERT_TRUE(editor.panel.exercise().findLump.inclusion.centre.vertex);
    EXPECT_EQ(*editor.panel.exercise().findLump.inclusion.centre.vertex, drawn.mesh->originalIndex()[v]);
    EXPECT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::None);  // one click places it
    EXPECT_FALSE(child<QToolButton>(editor.panel, "find_lump.inclusion.move")->isChecked());

    ASSERT_EQ(editor.lastMarkers.markers.size(), 1u);
    const ExerciseMarker& m = editor.lastMarkers.markers[0];
    EXPECT_EQ(m.kind, ExerciseMarker::Kind::Inclusion);  // the instructor sees it
    EXPECT_EQ(m.positionMm, drawn.mesh->restPositionsMm()[v]);
    EXPECT_EQ(m.radiusMm, editor.panel.exercise().findLump.inclusion.radiusMm);

    // The radius is a field: the circle follows; undo puts the centre back.
    // (the inclusion's row: number, vertex, radius, stiffness)
    child<QTableWidget>(editor.panel, "find_lump.inclusion")->item(0, 2)->setData(Qt::EditRole, 15.0);
    EXPECT_EQ(editor.lastMarkers.markers.at(0).radiusMm, 15.0);
    editor.panel.undoStack()->undo();
    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().findLump.inclusion.centre.vertex, before);
    EXPECT_EQ(child<QTableWidget>(editor.panel, "find_lump.inclusion")->item(0, 1)->data(Qt::EditRole).toInt(),
              int(*before));
}

TEST(ExerciseEditor, TracePointsAreAddedByClickingAndReordered) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::Trace);
    EXPECT_TRUE(hasProblemStartingWith(editor.panel.problems(), QStringLiteral("trace.path")));
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    const std::vector<VertexId> picks = spreadVertices(*drawn.mesh, 3);
    ASSERT_EQ(picks.size(), 3u);

    editor.panel.vertexPicked(picks[0]);
    // A path of one point has no geometry yet, but its point is drawn.
    ASSERT_EQ(editor.lastMarkers.markers.size(), 1u);
    EXPECT_EQ(editor.lastMarkers.markers[0].positionMm, drawn.mesh->restPositionsMm()[picks[0]]);
    editor.panel.vertexPicked(picks[1]);
    editor.panel.vertexPicked(picks[2]);
    EXPECT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();
    auto fileVertex = [&](VertexId v) { return drawn.mesh->originalIndex()[v]; };
    auto pathVertices = [&] {
        std::vector<std::uint32_t> out;
        for (const SurfacePoint& p : editor.panel.exercise().trace.path) out.push_back(p.vertex.value_or(~0u));
        return out;
    };
    EXPECT_EQ(pathVertices(), (std::vector<std::uint32_t>{fileVertex(picks[0]), fileVertex(picks[1]), fileVertex(picks[2])}));
    EXPECT_EQ(child<QTableWidget>(editor.panel, "trace.path")->rowCount(), 3);
    ASSERT_EQ(editor.lastMarkers.pathMm.size(), 3u);

    editor.panel.setSelectedIndex(2);
    child<QToolButton>(editor.panel, "trace.path.up")->click();
    EXPECT_EQ(pathVertices(), (std::vector<std::uint32_t>{fileVertex(picks[0]), fileVertex(picks[2]), fileVertex(picks[1])}));
    EXPECT_EQ(editor.panel.selectedIndex(), 1);  // the selection moves with the point
    ASSERT_EQ(editor.lastMarkers.pathMm.size(), 3u);
    EXPECT_EQ(editor.lastMarkers.pathMm[1], drawn.mesh->restPositionsMm()[picks[2]]);
    EXPECT_TRUE(editor.lastMarkers.markers[1].selected);

    editor.panel.undoStack()->undo();
    EXPECT_EQ(pathVertices(), (std::vector<std::uint32_t>{fileVertex(picks[0]), fileVertex(picks[1]), fileVertex(picks[2])}));

    // Remove the first point: the second becomes the start.
    editor.panel.setSelectedIndex(0);
    child<QToolButton>(editor.panel, "trace.path.remove")->click();
    EXPECT_EQ(pathVertices(), (std::vector<std::uint32_t>{fileVertex(picks[1]), fileVertex(picks[2])}));
}

TEST(ExerciseEditor, RubricEditsAreStoredAndSurviveSaveAndLoad) {
    Editor editor;
    const std::string example = findInSource("exercises/press_targets.json");
    ASSERT_EQ(editor.panel.openExercise(QString::fromStdString(example)), QString());
    auto* table = child<QTableWidget>(editor.panel, "rubricTable");
    // The metrics of the type, and only those.
    int applying = 0;
    for (std::size_t i = 0; i < kMetricCount; ++i) applying += exerciseKind(ExerciseType::PressTargets).measures(Metric(i));
    EXPECT_EQ(table->rowCount(), applying);
    EXPECT_EQ(rubricRow(editor.panel, "lump_error_mm"), -1);

    const int row = rubricRow(editor.panel, "completion");
    ASSERT_GE(row, 0);
    const Exercise& e = editor.panel.exercise();
    EXPECT_FALSE(e.rubric[std::size_t(Metric::Completion)]);
    EXPECT_EQ(table->item(row, 2)->data(Qt::EditRole).toDouble(), defaultRubricItem(e, Metric::Completion).weight);
    EXPECT_TRUE(table->item(row, 2)->font().italic());  // a default

    table->item(row, 2)->setData(Qt::EditRole, 55.0);
    ASSERT_TRUE(editor.panel.exercise().rubric[std::size_t(Metric::Completion)]);
    const RubricItem line = *editor.panel.exercise().rubric[std::size_t(Metric::Completion)];
    EXPECT_EQ(line.weight, 55.0);
    EXPECT_EQ(line.fullMarks, defaultRubricItem(e, Metric::Completion).fullMarks);
    EXPECT_EQ(effectiveRubric(editor.panel.exercise())[std::size_t(Metric::Completion)].weight, 55.0);
    EXPECT_FALSE(table->item(row, 2)->font().italic());  // set by the exercise now

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("weighted.json"));
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    const auto loaded = loadExercise(file.toStdString());
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    ASSERT_TRUE(loaded.exercise->rubric[std::size_t(Metric::Completion)]);
    EXPECT_EQ(loaded.exercise->rubric[std::size_t(Metric::Completion)]->weight, 55.0);
    EXPECT_EQ(loaded.exercise->meshPath, "meshes/stomach_3970.off");

    child<QPushButton>(editor.panel, "resetRubricButton")->click();
    EXPECT_FALSE(editor.panel.exercise().rubric[std::size_t(Metric::Completion)]);
    EXPECT_TRUE(table->item(row, 2)->font().italic());
    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().rubric[std::size_t(Metric::Completion)]->weight, 55.0);
}

TEST(ExerciseEditor, TypeChangeIsOneStepAndDropsRubricLinesTheNewTypeDoesNotMeasure) {
    Editor editor;
    ASSERT_EQ(editor.panel.openExercise(QString::fromStdString(findInSource("exercises/press_targets.json"))), QString());
    auto* table = child<QTableWidget>(editor.panel, "rubricTable");
    table->item(rubricRow(editor.panel, "target_error_mm"), 2)->setData(Qt::EditRole, 20.0);
    ASSERT_TRUE(editor.panel.exercise().rubric[std::size_t(Metric::TargetErrorMm)]);
    const int steps = editor.panel.undoStack()->count();

    auto* type = child<QComboBox>(editor.panel, "exerciseTypeCombo");
    type->setCurrentIndex(2);
    emit type->activated(2);  // as a user's choice
    EXPECT_EQ(editor.panel.exercise().type, ExerciseType::Trace);
    EXPECT_FALSE(editor.panel.exercise().rubric[std::size_t(Metric::TargetErrorMm)]);
    EXPECT_EQ(editor.panel.undoStack()->count(), steps + 1);
    EXPECT_GE(rubricRow(editor.panel, "band_fraction"), 0);

    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().type, ExerciseType::PressTargets);
    EXPECT_EQ(type->currentIndex(), 0);
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets.size(), 3u);  // kept across the switch
    EXPECT_TRUE(editor.panel.exercise().rubric[std::size_t(Metric::TargetErrorMm)]);
}

TEST(ExerciseEditor, AMeshOtherThanTheDrawnOneIsReportedAndNotPlacedOn) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    const std::string example = findInSource("exercises/press_targets.json");  // on stomach_3970.off
    ASSERT_EQ(editor.panel.openExercise(QString::fromStdString(example)), QString());
    EXPECT_FALSE(editor.panel.drawnMeshMatches());
    ASSERT_EQ(editor.panel.problems().size(), 1);
    EXPECT_TRUE(editor.panel.problems()[0].startsWith(QStringLiteral("mesh:")));
    EXPECT_TRUE(editor.panel.problems()[0].contains(QStringLiteral("sphere_1442.off")));
    EXPECT_TRUE(editor.panel.problems()[0].contains(QStringLiteral("stomach_3970.off")));
    EXPECT_TRUE(editor.lastMarkers.empty());  // its vertices mean nothing on the drawn mesh

    // A click on the other mesh places nothing.
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor.panel.vertexPicked(5);
    EXPECT_EQ(editor.panel.exercise().pressTargets.targets.size(), 3u);
    EXPECT_FALSE(editor.panel.isModified());

    // Show this mesh asks for the exercise's mesh; once it is drawn, its markers come.
    QSignalSpy requested(&editor.panel, &ExerciseEditorPanel::meshRequested);
    child<QPushButton>(editor.panel, "showMeshButton")->click();
    ASSERT_EQ(requested.count(), 1);
    EXPECT_EQ(requested.at(0).at(0).toString().toStdString(), findInSource("meshes/stomach_3970.off"));
    const DrawnMesh stomach = loadMesh("meshes/stomach_3970.off");
    editor.panel.setDrawnMesh(stomach.mesh, requested.at(0).at(0).toString());
    EXPECT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();
    EXPECT_EQ(editor.lastMarkers.markers.size(), 3u);

    // A vertex that the exercise's mesh does not have is a problem even when another mesh is drawn.
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    auto* table = child<QTableWidget>(editor.panel, "press_targets.targets");
    table->item(0, 1)->setData(Qt::EditRole, 99999);
    EXPECT_TRUE(hasProblemStartingWith(editor.panel.problems(), QStringLiteral("press_targets.targets[0]")))
        << editor.panel.problems().join('\n').toStdString();
}

TEST(ExerciseEditor, TryItCarriesTheUnsavedExerciseWithResolvablePaths) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::PressTargets);
    std::vector<Exercise> sentExercises;
    QObject::connect(&editor.panel, &ExerciseEditorPanel::previewRequested,
                     [&](const Exercise& e) { sentExercises.push_back(e); });
    EXPECT_FALSE(editor.panel.preview());  // no target yet
    EXPECT_TRUE(sentExercises.empty());
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor.panel.vertexPicked(42);

    editor.panel.previewAction()->trigger();  // F5
    ASSERT_EQ(sentExercises.size(), 1u);
    const Exercise& sent = sentExercises[0];
    EXPECT_EQ(json(sent), json(editor.panel.exercise()));
    EXPECT_TRUE(sent.sourcePath.empty());  // never saved
    EXPECT_EQ(resolveExercisePath(sent, sent.meshPath, findInSource), findInSource("meshes/sphere_1442.off"));
    EXPECT_FALSE(resolveExercisePath(sent, sent.tissuePresetPath, findInSource).empty());
    EXPECT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::None);  // the viewport is the trainee's now
    EXPECT_TRUE(editor.panel.isModified());  // nothing saved
}

TEST(ExerciseEditor, AMalformedFileIsRefusedNamingTheKeyAndChangesNothing) {
    Editor editor;
    const std::string example = findInSource("exercises/trace.json");
    ASSERT_EQ(editor.panel.openExercise(QString::fromStdString(example)), QString());
    child<QDoubleSpinBox>(editor.panel, "timeLimitSpin")->setValue(50.0);  // an unsaved edit
    const std::string before = json(editor.panel.exercise());
    const int steps = editor.panel.undoStack()->count();

    QTemporaryDir dir;
    auto write = [&](const char* name, const std::string& text) {
        const QString path = dir.filePath(QLatin1String(name));
        std::ofstream(path.toStdString()) << text;
        return path;
    };
    std::ifstream in(findInSource("exercises/press_targets.json"));
    nlohmann::json j = nlohmann::json::parse(in);
    j["time_limit_s"] = "sixty";
    j["press_targets"]["targets"][1]["force_mx_n"] = 2.0;
    const QString bad = write("bad.json", j.dump(2));
    const QString error = editor.panel.openExercise(bad);
    EXPECT_TRUE(error.contains(QStringLiteral("time_limit_s"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("press_targets.targets[1].force_mx_n"))) << error.toStdString();
    EXPECT_EQ(json(editor.panel.exercise()), before);
    EXPECT_EQ(editor.panel.currentPath().toStdString(), example);
    EXPECT_EQ(editor.panel.undoStack()->count(), steps);
    EXPECT_TRUE(editor.panel.isModified());
    EXPECT_TRUE(child<QLabel>(editor.panel, "messageLabel")->text().contains(QStringLiteral("time_limit_s")));

    EXPECT_FALSE(editor.panel.openExercise(write("broken.json", "{\"format\": ")).isEmpty());
    EXPECT_FALSE(editor.panel.openExercise(dir.filePath(QStringLiteral("missing.json"))).isEmpty());
    EXPECT_EQ(json(editor.panel.exercise()), before);
}

TEST(ExerciseEditor, TypingIntoAFieldIsOneStepAndUndoRestoresTheForm) {
    Editor editor;
    editor.panel.newExercise(ExerciseType::PressTargets);
    auto* name = child<QLineEdit>(editor.panel, "exerciseNameEdit");
    name->clear();  // by code: not an edit
    EXPECT_EQ(editor.panel.undoStack()->count(), 0);
    name->setFocus();
    QTest::keyClicks(name, QStringLiteral("Palpate"));
    EXPECT_EQ(editor.panel.exercise().name, "Palpate");
    EXPECT_EQ(editor.panel.undoStack()->count(), 1);

    auto* time = child<QDoubleSpinBox>(editor.panel, "timeLimitSpin");
    time->setValue(1.0);
    time->setValue(1.5);  // as typing "1.5" does
    EXPECT_EQ(editor.panel.undoStack()->count(), 2);
    EXPECT_EQ(editor.panel.exercise().timeLimitS, 1.5);
    emit time->editingFinished();  // leaving the field ends the step
    time->setValue(20.0);
    EXPECT_EQ(editor.panel.undoStack()->count(), 3);

    editor.panel.undoAction()->trigger();
    EXPECT_EQ(time->value(), 1.5);
    editor.panel.undoAction()->trigger();
    EXPECT_EQ(time->value(), Exercise{}.timeLimitS);
    EXPECT_EQ(editor.panel.exercise().timeLimitS, Exercise{}.timeLimitS);
    editor.panel.undoAction()->trigger();
    EXPECT_EQ(name->text(), QString::fromStdString(editor.panel.exercise().name));
    EXPECT_NE(editor.panel.exercise().name, "Palpate");
    EXPECT_FALSE(editor.panel.isModified());
    editor.panel.redoAction()->trigger();
    EXPECT_EQ(name->text(), QStringLiteral("Palpate"));

    // An empty name is named by its key and marks the field.
    name->selectAll();
    QTest::keyClick(name, Qt::Key_Backspace);
    EXPECT_TRUE(hasProblemStartingWith(editor.panel.problems(), QStringLiteral("name:")));
    EXPECT_TRUE(name->property("invalid").toBool());
}

// "Text in" chooses which language's name and description the two fields edit: a translation is
// typed like the exercise's own words (one undo step, shown again on undo), an empty translation
// shows the own words greyed, one emptied is dropped from the file, and all of it is saved.
TEST(ExerciseEditor, TheNameAndDescriptionAreEditedInEachLanguage) {
    Editor editor;
    const std::string shipped = findInSource("exercises/press_targets.json");
    ASSERT_EQ(editor.panel.openExercise(QString::fromStdString(shipped)), QString());
    auto* language = child<QComboBox>(editor.panel, "exerciseTextLanguageCombo");
    auto* name = child<QLineEdit>(editor.panel, "exerciseNameEdit");
    auto* description = child<QPlainTextEdit>(editor.panel, "exerciseDescriptionEdit");
    EXPECT_EQ(name->text(), QStringLiteral("Press three targets"));
    language->setCurrentIndex(language->findData(QStringLiteral("de")));
    EXPECT_EQ(name->text(), QStringLiteral("Drei Ziele drücken"));
    EXPECT_TRUE(description->toPlainText().startsWith(QStringLiteral("Drücken Sie")));
    EXPECT_EQ(editor.panel.undoStack()->count(), 0);  // choosing a language changes nothing

    name->selectAll();
    name->setFocus();
    QTest::keyClicks(name, QStringLiteral("Drei Punkte"));
    EXPECT_EQ(editor.panel.exercise().translations.at("de").name, "Drei Punkte");
    EXPECT_EQ(editor.panel.exercise().name, "Press three targets");
    EXPECT_EQ(editor.panel.undoStack()->count(), 1);
    language->setCurrentIndex(language->findData(QString()));
    EXPECT_EQ(name->text(), QStringLiteral("Press three targets"));
    language->setCurrentIndex(language->findData(QStringLiteral("de")));
    editor.panel.undoAction()->trigger();
    EXPECT_EQ(name->text(), QStringLiteral("Drei Ziele drücken"));
    editor.panel.redoAction()->trigger();
    EXPECT_EQ(name->text(), QStringLiteral("Drei Punkte"));

    // Emptied, the Malay translation is gone and the fields show the own words as placeholders.
    language->setCurrentIndex(language->findData(QStringLiteral("ms")));
    name->selectAll();
    QTest::keyClick(name, Qt::Key_Backspace);
    description->selectAll();
    QTest::keyClick(description, Qt::Key_Backspace);
    EXPECT_EQ(editor.panel.exercise().translations.count("ms"), 0u);
    EXPECT_EQ(name->placeholderText(), QStringLiteral("Press three targets"));
    EXPECT_FALSE(hasProblemStartingWith(editor.panel.problems(), QStringLiteral("translations")));

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("press.json"));
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    const auto loaded = loadExercise(file.toStdString());
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    EXPECT_EQ(exerciseTextIn(*loaded.exercise, "de").name, "Drei Punkte");
    EXPECT_EQ(exerciseTextIn(*loaded.exercise, "ms").name, "Press three targets");
    EXPECT_EQ(loaded.exercise->name, "Press three targets");
}

TEST(ExerciseEditor, UnsavedChangesAreNotDiscardedWithoutAsking) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::PressTargets);
    int asked = 0;
    ExerciseEditorPanel::DiscardAnswer answer = ExerciseEditorPanel::DiscardAnswer::Cancel;
    editor.panel.setDiscardQuestion([&](const QString&) {
        ++asked;
        return answer;
    });

    // Nothing to lose: no question.
    editor.panel.newAction(ExerciseType::Trace)->trigger();
    EXPECT_EQ(asked, 0);
    EXPECT_EQ(editor.panel.exercise().type, ExerciseType::Trace);

    QSignalSpy modified(&editor.panel, &ExerciseEditorPanel::modifiedChanged);
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor.panel.vertexPicked(3);
    editor.panel.vertexPicked(300);
    EXPECT_TRUE(editor.panel.isModified());
    ASSERT_EQ(modified.count(), 1);
    EXPECT_TRUE(modified.at(0).at(0).toBool());
    const std::string work = json(editor.panel.exercise());

    answer = ExerciseEditorPanel::DiscardAnswer::Cancel;
    editor.panel.newAction(ExerciseType::PressTargets)->trigger();
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(json(editor.panel.exercise()), work);  // kept
    EXPECT_TRUE(editor.panel.isModified());
    EXPECT_FALSE(editor.panel.confirmDiscard());
    EXPECT_EQ(asked, 2);

    // Save: an exercise with a file is saved there, then replaced.
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("path.json"));
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    editor.panel.vertexPicked(600);
    answer = ExerciseEditorPanel::DiscardAnswer::Save;
    editor.panel.newAction(ExerciseType::FindLump)->trigger();
    EXPECT_EQ(asked, 3);
    EXPECT_EQ(editor.panel.exercise().type, ExerciseType::FindLump);
    const auto saved = loadExercise(file.toStdString());
    ASSERT_TRUE(saved.exercise) << saved.error();
    EXPECT_EQ(saved.exercise->trace.path.size(), 3u);  // the last point was saved first

    // Discard: replaced without saving.
    child<QTableWidget>(editor.panel, "find_lump.inclusion")->item(0, 3)->setData(Qt::EditRole, 0.5);
    answer = ExerciseEditorPanel::DiscardAnswer::Discard;
    editor.panel.newAction(ExerciseType::PressTargets)->trigger();
    EXPECT_EQ(asked, 4);
    EXPECT_EQ(editor.panel.exercise().type, ExerciseType::PressTargets);
    EXPECT_FALSE(editor.panel.isModified());
}

TEST(ExerciseEditor, FitsANarrowDock) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    const QString out = qEnvironmentVariable("PALPATE_EDITOR_PNG_DIR");
    const std::pair<ExerciseType, const char*> types[] = {
        {ExerciseType::PressTargets, "press_targets"}, {ExerciseType::FindLump, "find_lump"}, {ExerciseType::Trace, "trace"}};
    for (const auto& [type, name] : types) {
        editor.panel.newExercise(type);
        if (type == ExerciseType::PressTargets) {
            editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
            for (VertexId v : {10u, 400u, 800u}) editor.panel.vertexPicked(v);
        } else if (type == ExerciseType::Trace) {
            editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
            editor.panel.vertexPicked(10);
        }
        editor.panel.resize(380, 900);
        editor.panel.show();
        QApplication::processEvents();
        // Nothing forces the dock wider than 380 px: the form scrolls vertically only.
        EXPECT_LE(editor.panel.minimumSizeHint().width(), 380) << name;
        auto* scroll = child<QScrollArea>(editor.panel, "exerciseEditorScroll");
        EXPECT_LE(scroll->widget()->minimumSizeHint().width(), scroll->viewport()->width()) << name;
        const QImage image = editor.panel.grab().toImage();
        EXPECT_EQ(image.width(), 380);
        if (!out.isEmpty()) {
            image.save(out + QStringLiteral("/exercise_editor_%1.png").arg(QLatin1String(name)));
            // The whole form, as if the dock were tall enough not to scroll.
            QWidget* form = scroll->widget();
            scroll->takeWidget();
            form->resize(scroll->viewport()->width(), form->sizeHint().height());
            form->grab().save(out + QStringLiteral("/exercise_editor_%1_form.png").arg(QLatin1String(name)));
            scroll->setWidget(form);
        }
    }
}

TEST(ExerciseEditor, LevelOfDetailTargetsAreOptionalUndoableAndSaved) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::PressTargets);
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor.panel.vertexPicked(10);
    auto* check = child<QCheckBox>(editor.panel, "needsCheck");
    auto* error = child<QDoubleSpinBox>(editor.panel, "needsErrorSpin");
    auto* budget = child<QDoubleSpinBox>(editor.panel, "needsBudgetSpin");
    EXPECT_FALSE(editor.panel.exercise().needs);
    EXPECT_FALSE(error->isEnabled());

    check->setChecked(true);
    ASSERT_TRUE(editor.panel.exercise().needs);
    EXPECT_TRUE(error->isEnabled());
    error->setValue(12.5);  // percent in the field, a fraction in the file
    budget->setValue(40.0);
    EXPECT_DOUBLE_EQ(editor.panel.exercise().needs->maxErrorFraction, 0.125);
    EXPECT_DOUBLE_EQ(editor.panel.exercise().needs->budgetUs, 40.0);

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("with_needs.json"));
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    const auto loaded = loadExercise(file.toStdString());
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    ASSERT_TRUE(loaded.exercise->needs);
    EXPECT_DOUBLE_EQ(loaded.exercise->needs->maxErrorFraction, 0.125);
    EXPECT_DOUBLE_EQ(loaded.exercise->needs->budgetUs, 40.0);

    // Undo back to no targets: the fields are off again and the file would carry none.
    while (editor.panel.exercise().needs && editor.panel.undoStack()->canUndo()) editor.panel.undoStack()->undo();
    EXPECT_FALSE(editor.panel.exercise().needs);
    EXPECT_FALSE(check->isChecked());
    EXPECT_FALSE(error->isEnabled());
}

// "mesh_unit" (docs/meshes.md, "Units"): a combo of the named units and "scale…" with a factor;
// each change one undo step, saved, and the drawn mesh is the exercise's only when read in its unit.
TEST(ExerciseEditor, TheMeshUnitIsAFieldWithUndoThatIsSavedAndChecksTheDrawnMesh) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::PressTargets);
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    editor.panel.vertexPicked(10);
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::None);
    auto* combo = child<QComboBox>(editor.panel, "meshUnitCombo");
    auto* scale = child<QDoubleSpinBox>(editor.panel, "meshScaleSpin");
    ASSERT_EQ(combo->count(), 5);
    EXPECT_EQ(combo->currentIndex(), 0);  // mm
    EXPECT_TRUE(scale->isHidden());
    EXPECT_TRUE(editor.panel.drawnMeshMatches());
    const int steps = editor.panel.undoStack()->count();

    combo->setCurrentIndex(1);
    emit combo->activated(1);  // as a user's choice
    EXPECT_EQ(editor.panel.exercise().meshUnit.name, "cm");
    EXPECT_EQ(editor.panel.exercise().meshUnit.mmPerUnit, 10.0);
    EXPECT_EQ(editor.panel.undoStack()->count(), steps + 1);
    // The viewport's sphere was read in mm: not this exercise's mesh any more, and it says why.
    EXPECT_FALSE(editor.panel.drawnMeshMatches());
    EXPECT_TRUE(hasProblemStartingWith(editor.panel.problems(), QStringLiteral("mesh_unit: ")))
        << editor.panel.problems().join('\n').toStdString();

    // "scale…": the factor typed is one step, however many values it went through.
    combo->setCurrentIndex(4);
    emit combo->activated(4);
    EXPECT_FALSE(scale->isHidden());
    EXPECT_EQ(scale->value(), 10.0);
    scale->setValue(2.5);
    scale->setValue(3.0);
    EXPECT_EQ(editor.panel.exercise().meshUnit.name, "");
    EXPECT_EQ(editor.panel.exercise().meshUnit.mmPerUnit, 3.0);
    EXPECT_EQ(editor.panel.undoStack()->count(), steps + 3);

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("scaled.json"));
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    QFile saved(file);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    EXPECT_EQ(nlohmann::json::parse(saved.readAll().toStdString()).value("mesh_unit", 0.0), 3.0);
    const auto loaded = loadExercise(file.toStdString());
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    EXPECT_EQ(loaded.exercise->meshUnit.mmPerUnit, 3.0);

    // Undo: back to cm, then mm, the form with it.
    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().meshUnit.mmPerUnit, 10.0);
    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().meshUnit.name, "cm");
    EXPECT_EQ(combo->currentIndex(), 1);
    EXPECT_TRUE(scale->isHidden());
    editor.panel.undoStack()->undo();
    EXPECT_TRUE(editor.panel.exercise().meshUnit.isMillimetres());
    EXPECT_EQ(combo->currentIndex(), 0);
    EXPECT_TRUE(editor.panel.drawnMeshMatches());
    editor.panel.undoStack()->redo();

    // The sphere drawn as read in cm is the cm exercise's mesh again.
    auto inCm = TissueMesh::load(drawn.path.toStdString(), MeshUnit{"cm", 10.0});
    ASSERT_TRUE(inCm.mesh) << inCm.error();
    editor.panel.setDrawnMesh(std::make_shared<const TissueMesh>(std::move(*inCm.mesh)), drawn.path);
    EXPECT_TRUE(editor.panel.drawnMeshMatches());
    EXPECT_FALSE(hasProblemStartingWith(editor.panel.problems(), QStringLiteral("mesh_unit: ")));
}

// ---- Reachable with the mouse (docs/scoring.md, "Reachable targets") ------------------------------

namespace {

/// The stomach drawn, a new press-targets exercise on it with its default tissue, one target placed.
struct StomachWithATarget {
    DrawnMesh drawn = loadMesh(kDefaultMesh);
    Editor editor;
    VertexId vertex = 1200;
    StomachWithATarget() {
        editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
        editor.panel.newExercise(ExerciseType::PressTargets);
        editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
        editor.panel.vertexPicked(vertex);
        editor.panel.setPlacing(ExerciseEditorPanel::Placing::None);
    }
    /// What the engine's check says of the exercise as it is now (the viewport's touch depths).
    std::vector<TargetReach> check() const {
        std::vector<std::string> errors;
        const auto assets = loadExerciseAssets(editor.panel.exercise(), findInSource, errors);
        EXPECT_TRUE(assets) << (errors.empty() ? "" : errors.front());
        std::string error;
        auto reach = assets ? checkTargetReachability(*assets, ExerciseEditorPanel::touchReach(), error)
                            : std::vector<TargetReach>{};
        EXPECT_EQ(error, "");
        return reach;
    }
};

}  // namespace

TEST(ExerciseEditor, ANewExercisesFirstTargetCanBeReachedWithTheMouse) {
    StomachWithATarget s;
    ASSERT_EQ(s.editor.panel.exercise().tissuePresetPath, "presets/tissues/stomach_wall.json");  // the default tissue
    ASSERT_EQ(s.editor.panel.exercise().pressTargets.targets.size(), 1u);
    const PressTarget& t = s.editor.panel.exercise().pressTargets.targets[0];
    std::printf("[ figures  ] the first target's window on the stomach wall: %.3g to %.3g N\n", t.forceMinN, t.forceMaxN);
    const auto reach = s.check();
    ASSERT_EQ(reach.size(), 1u);
    EXPECT_TRUE(reach[0].reachable) << "the deepest touch gives " << reach[0].maxForceN << " N";
    EXPECT_TRUE(shownWarnings(s.editor.panel).isEmpty()) << shownWarnings(s.editor.panel).join('\n').toStdString();
    EXPECT_FALSE(child<QLabel>(s.editor.panel, "warningsLabel")->isVisibleTo(&s.editor.panel));
}

TEST(ExerciseEditor, AWindowTheMouseCannotReachIsWarnedAboutUntilItIsFixed) {
    StomachWithATarget s;
    auto* table = child<QTableWidget>(s.editor.panel, "press_targets.targets");
    // 1-2 N on the stomach wall: far more than its deepest touch gives.
    table->item(0, 3)->setData(Qt::EditRole, 2.0);
    table->item(0, 2)->setData(Qt::EditRole, 1.0);
    const auto reach = s.check();
    ASSERT_EQ(reach.size(), 1u);
    ASSERT_FALSE(reach[0].reachable);
    const QStringList warnings = shownWarnings(s.editor.panel);
    ASSERT_EQ(warnings.size(), 1);
    EXPECT_TRUE(warnings[0].startsWith(QStringLiteral("press_targets.targets[0].force_min_n"))) << warnings[0].toStdString();
    const QString most = QLocale().toString(reach[0].maxForceN, 'g', 3);
    EXPECT_TRUE(warnings[0].contains(QStringLiteral("at most %1 N").arg(most))) << warnings[0].toStdString();
    EXPECT_TRUE(warnings[0].contains(QStringLiteral("stiffer tissue"))) << warnings[0].toStdString();
    auto* label = child<QLabel>(s.editor.panel, "warningsLabel");
    EXPECT_TRUE(label->isVisibleTo(&s.editor.panel));
    EXPECT_TRUE(label->text().contains(QStringLiteral("target 1")));
    EXPECT_TRUE(table->item(0, 2)->data(Qt::BackgroundRole).isValid());  // the cell to change is marked
    // A warning, not a problem: it is saved and tried (a device in the hand may press harder).
    EXPECT_TRUE(s.editor.panel.problems().isEmpty()) << s.editor.panel.problems().join('\n').toStdString();
    EXPECT_TRUE(s.editor.panel.previewAction()->isEnabled());

    // A stiffer tissue reaches 1 N: the warning goes.
    auto* preset = child<QComboBox>(s.editor.panel, "tissuePresetCombo");
    preset->setEditText(QStringLiteral("presets/tissues/skin.json"));
    emit preset->lineEdit()->editingFinished();
    ASSERT_EQ(s.editor.panel.exercise().tissuePresetPath, "presets/tissues/skin.json");
    EXPECT_TRUE(s.check()[0].reachable);
    EXPECT_TRUE(shownWarnings(s.editor.panel).isEmpty()) << shownWarnings(s.editor.panel).join('\n').toStdString();
    EXPECT_FALSE(label->isVisibleTo(&s.editor.panel));
    EXPECT_FALSE(table->item(0, 2)->data(Qt::BackgroundRole).isValid());

    // Back to the stomach wall (undo), then the window lowered as the warning says: it goes too.
    s.editor.panel.undoStack()->undo();
    ASSERT_EQ(shownWarnings(s.editor.panel).size(), 1);
    table->item(0, 2)->setData(Qt::EditRole, 0.5 * reach[0].maxForceN);
    table->item(0, 3)->setData(Qt::EditRole, reach[0].maxForceN);
    EXPECT_TRUE(s.check()[0].reachable);
    EXPECT_TRUE(shownWarnings(s.editor.panel).isEmpty()) << shownWarnings(s.editor.panel).join('\n').toStdString();
}

TEST(ExerciseEditor, ATraceBandTheMouseCannotReachIsWarnedAboutAndANewOneCan) {
    const DrawnMesh drawn = loadMesh(kDefaultMesh);
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newExercise(ExerciseType::Trace);
    ASSERT_EQ(editor.panel.exercise().tissuePresetPath, "presets/tissues/stomach_wall.json");
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::AddItem);
    for (VertexId v : {VertexId(1200), VertexId(1210), VertexId(1220)}) editor.panel.vertexPicked(v);
    ASSERT_EQ(editor.panel.exercise().trace.path.size(), 3u);
    EXPECT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();
    // The first point set a band the stomach wall reaches; the later ones kept it.
    EXPECT_LT(editor.panel.exercise().trace.forceMaxN, TraceDef{}.forceMinN);
    EXPECT_TRUE(shownWarnings(editor.panel).isEmpty()) << shownWarnings(editor.panel).join('\n').toStdString();

    // The engine's default band, 0.5-1.5 N, is more than the stomach wall gives.
    auto* low = child<QDoubleSpinBox>(editor.panel, "trace.force_min_n");
    auto* high = child<QDoubleSpinBox>(editor.panel, "trace.force_max_n");
    high->setValue(TraceDef{}.forceMaxN);
    low->setValue(TraceDef{}.forceMinN);
    ASSERT_EQ(shownWarnings(editor.panel).size(), 1);
    EXPECT_TRUE(shownWarnings(editor.panel)[0].startsWith(QStringLiteral("trace.force_min_n")))
        << shownWarnings(editor.panel)[0].toStdString();
    EXPECT_TRUE(shownWarnings(editor.panel)[0].contains(QStringLiteral("path point 1, 2, 3")))
        << shownWarnings(editor.panel)[0].toStdString();
    EXPECT_TRUE(child<QLabel>(editor.panel, "warningsLabel")->isVisibleTo(&editor.panel));
    // Muscle reaches it (the shipped trace's tissue).
    auto* preset = child<QComboBox>(editor.panel, "tissuePresetCombo");
    preset->setEditText(QStringLiteral("presets/tissues/muscle.json"));
    emit preset->lineEdit()->editingFinished();
    EXPECT_TRUE(shownWarnings(editor.panel).isEmpty()) << shownWarnings(editor.panel).join('\n').toStdString();
}

TEST(ExerciseEditor, EveryShippedExampleCanBeDoneWithTheMouse) {
    int targets = 0;
    for (const char* name : {"press_targets", "find_lump", "trace", "detect_lumps", "no_lump"}) {
        const std::string path = findInSource(std::string("exercises/") + name + ".json");
        const auto loaded = loadExercise(path);
        ASSERT_TRUE(loaded.exercise) << loaded.error();
        std::vector<std::string> errors;
        const auto assets = loadExerciseAssets(*loaded.exercise, findInSource, errors);
        ASSERT_TRUE(assets) << name << ": " << (errors.empty() ? "" : errors.front());
        std::string error;
        const auto reach = checkTargetReachability(*assets, ExerciseEditorPanel::touchReach(), error);
        ASSERT_EQ(error, "") << name;
        for (std::size_t i = 0; i < reach.size(); ++i) {
            ++targets;
            EXPECT_TRUE(reach[i].reachable) << name << " target " << i + 1 << ": "
                                            << reachAdvice(assets->geometry->targets()[i].def, reach[i]);
        }
        // The editor agrees.
        Editor editor;
        ASSERT_EQ(editor.panel.openExercise(QString::fromStdString(path)), QString());
        EXPECT_TRUE(shownWarnings(editor.panel).isEmpty())
            << name << ": " << shownWarnings(editor.panel).join('\n').toStdString();
    }
    EXPECT_GT(targets, 0);
}

// The mouse's default press (the viewport's depth before the wheel turns) examines: in every
// shipped examination it reaches the coverage force over most of the surface, so a trainee who
// sweeps without touching the wheel is credited with what they examined.
TEST(ExerciseEditor, TheDefaultPressExaminesInEveryShippedExamination) {
    for (const char* name : {"find_lump", "detect_lumps", "no_lump"}) {
        const std::string path = findInSource(std::string("exercises/") + name + ".json");
        const auto loaded = loadExercise(path);
        ASSERT_TRUE(loaded.exercise) << loaded.error();
        std::vector<std::string> errors;
        const auto assets = loadExerciseAssets(*loaded.exercise, findInSource, errors);
        ASSERT_TRUE(assets) << name << ": " << (errors.empty() ? "" : errors.front());
        const TouchReach defaultPress{Viewport::kDefaultTouchDepthMm, 0.0};  // that depth alone
        std::string error;
        auto probe = TouchForceProbe::create(*assets->mesh, assets->preset, assets->geometry.get(), defaultPress,
                                             error);
        ASSERT_TRUE(probe) << error;
        std::vector<std::vector<double>> forces;
        for (const VertexId v : examinePoints(assets->mesh->restPositionsMm())) forces.push_back(probe->forcesN(v));
        const auto reach = judgeExamining(forces, defaultPress, Viewport::kDefaultTouchDepthMm);
        ASSERT_TRUE(reach) << name;
        std::printf("[ figures  ] %s: the default %.1f mm press gives %.3g N, examining from %.3g N\n", name,
                    Viewport::kDefaultTouchDepthMm, reach->deepestN, loaded.exercise->coverage.minForceN);
        EXPECT_GE(reach->deepestN, loaded.exercise->coverage.minForceN) << name;
    }
}

// ---- In the main window: placing while touch mode is on, and Try it ---------------------------

namespace {

void sendMouse(QWidget& widget, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, widget.mapToGlobal(at), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(&widget, &event);
}

/// A stepped window on the stomach with the mouse device (touch mode on, as at start), the editor
/// on a new press-targets exercise.
class EditorInTheWindow : public ::testing::Test {
protected:
    void SetUp() override {
        window = std::make_unique<MainWindow>(RendererChoice::Software, LoopMode::Stepped);
        ASSERT_EQ(window->loadMesh(QString::fromStdString(findResource(kDefaultMesh))), QString());
        ASSERT_EQ(window->setDeviceUri(QLatin1String(HapticSession::kInteractiveDeviceUri)), QString());
        window->setMode(MainWindow::Mode::Instructor);
        window->resize(1100, 700);
        window->show();
        QApplication::processEvents();
        window->advanceTicks(10);
        editor = window->exerciseEditor();
        editor->newExercise(ExerciseType::PressTargets);
        viewport = window->viewport()->widget();
        centre = QPointF(viewport->width() / 2.0, viewport->height() / 2.0);
        const auto picked = window->viewport()->pickVertexAt(centre, viewport->size());
        ASSERT_TRUE(picked) << "the mesh is framed in the middle of the viewport";
        vertex = *picked;
    }
    void click() {
        sendMouse(*viewport, QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::LeftButton);
        sendMouse(*viewport, QEvent::MouseButtonRelease, centre, Qt::LeftButton, Qt::NoButton);
    }
    /// Adds a target at the middle of the viewport with Add by clicking, then Esc.
    void addTargetByClicking() {
        child<QToolButton>(*editor, "press_targets.targets.add")->click();
        click();
        editor->findChild<QAction*>(QStringLiteral("stopPlacingAction"))->trigger();
    }
    double force() const { return double(glm::length(window->session().observed().forceN)); }

    std::unique_ptr<MainWindow> window;
    ExerciseEditorPanel* editor = nullptr;
    QWidget* viewport = nullptr;
    QPointF centre;
    VertexId vertex = kNoVertex;
};

}  // namespace

// The Stiffening chart's Apply knots reaches the force the hand feels: pressed and held at one
// depth, the tissue pushes back harder once the knots are in, and the mesh and rings stay.
TEST_F(EditorInTheWindow, StiffeningKnotsFromTheChartsChangeTheForceAndNothingElse) {
    sendMouse(*viewport, QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::LeftButton);
    window->advanceTicks(800);
    const double linearN = force();
    ASSERT_GT(linearN, 0.01);
    const auto meshBefore = window->session().drawnMesh();
    const int ringsBefore = window->session().preset().model.slopeRing.ringCount;
    StiffeningCalibration knots;
    knots.knots = 1;
    knots.knotForceN = {0.3 * linearN};
    knots.knotCompliance = {0.25};
    knots.completed = true;
    emit window->chartsPanel()->stiffeningPanel()->applyKnotsRequested(knots);
    window->advanceTicks(800);
    const double stiffenedN = force();
    std::printf("[ figures  ] held press: %.3f N linear, %.3f N with a knot at %.3f N (compliance 0.25)\n", linearN,
                stiffenedN, knots.knotForceN[0]);
    EXPECT_GT(stiffenedN, 1.2 * linearN);  // the contact in series with the stiffer tissue
    EXPECT_EQ(window->session().preset().model.slopeRing.stiffeningKnots, 1);
    EXPECT_EQ(window->session().drawnMesh(), meshBefore) << "the mesh stays";
    EXPECT_EQ(window->session().preset().model.slopeRing.ringCount, ringsBefore) << "the rings stay";
    // One step to undo in Parameters; applied, the force is the linear one again.
    ParameterPanel* parameters = window->parameterPanel();
    EXPECT_EQ(parameters->undoStack()->undoText(), QStringLiteral("Apply stiffening knots"));
    parameters->undoStack()->undo();
    parameters->apply();
    window->advanceTicks(800);
    EXPECT_EQ(window->session().preset().model.slopeRing.stiffeningKnots, 0);
    EXPECT_NEAR(force(), linearN, 0.02 * linearN);
}

TEST_F(EditorInTheWindow, AddByClickingAddsATargetWhileTouchModeIsOn) {
    ASSERT_TRUE(window->touchMode());
    child<QToolButton>(*editor, "press_targets.targets.add")->click();
    ASSERT_EQ(editor->placing(), ExerciseEditorPanel::Placing::AddItem);
    // The editor says what to do.
    auto* hint = child<QLabel>(*editor, "placingLabel");
    EXPECT_TRUE(hint->isVisibleTo(editor));
    EXPECT_EQ(hint->text(), QStringLiteral("Click the tissue to place Target 1, and more after it; Esc to stop."));

    click();
    ASSERT_EQ(editor->exercise().pressTargets.targets.size(), 1u);
    EXPECT_EQ(editor->exercise().pressTargets.targets[0].at.vertex.value_or(~0u),
              window->session().drawnMesh()->originalIndex().empty() ? vertex
                                                                     : window->session().drawnMesh()->originalIndex()[vertex]);
    // The click placed; it did not press the tissue.
    EXPECT_FALSE(window->viewport()->touching());
    window->advanceTicks(200);
    EXPECT_FALSE(window->session().observed().contact);
    click();
    EXPECT_EQ(editor->exercise().pressTargets.targets.size(), 2u);  // stays on for more

    // Esc stops placing, and touch mode is back: a press presses again.
    editor->findChild<QAction*>(QStringLiteral("stopPlacingAction"))->trigger();
    EXPECT_EQ(editor->placing(), ExerciseEditorPanel::Placing::None);
    EXPECT_TRUE(window->touchMode());
    EXPECT_TRUE(window->touchModeAction()->isChecked());
    sendMouse(*viewport, QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::LeftButton);
    window->advanceTicks(300);
    EXPECT_TRUE(window->session().observed().contact);
    EXPECT_GT(force(), 0.0);
    sendMouse(*viewport, QEvent::MouseButtonRelease, centre, Qt::LeftButton, Qt::NoButton);
    EXPECT_EQ(editor->exercise().pressTargets.targets.size(), 2u);

    // Turning touch mode on (T) while placing ends the placing: the click is the tool's.
    child<QToolButton>(*editor, "press_targets.targets.add")->click();
    EXPECT_FALSE(window->touchMode());
    window->touchModeAction()->trigger();
    EXPECT_TRUE(window->touchMode());
    EXPECT_EQ(editor->placing(), ExerciseEditorPanel::Placing::None);
}

TEST_F(EditorInTheWindow, TryItLeavesTouchModeOnSoThatPressingPresses) {
    addTargetByClicking();
    ASSERT_EQ(editor->exercise().pressTargets.targets.size(), 1u);
    window->touchModeAction()->trigger();  // the instructor had turned touch mode off
    ASSERT_FALSE(window->touchMode());

    const int viewportWidthPx = viewport->width();
    child<QPushButton>(*editor, "previewButton")->click();
    ASSERT_TRUE(window->exercises().running());
    EXPECT_TRUE(window->touchMode());
    EXPECT_TRUE(window->touchModeAction()->isChecked());
    EXPECT_EQ(window->session().deviceUri(), HapticSession::kInteractiveDeviceUri);
    window->advanceTicks(200);
    // The Exercise dock opens beside the editor, not as a column of its own that squeezes the
    // tissue out of sight (at 1100 px it had left the viewport 255 px of 588).
    QApplication::processEvents();
    EXPECT_GE(viewport->width(), viewportWidthPx * 9 / 10);
    EXPECT_TRUE(window->tabifiedDockWidgets(window->findChild<QDockWidget*>(QStringLiteral("exerciseDock")))
                    .contains(window->findChild<QDockWidget*>(QStringLiteral("exerciseEditorDock"))));
    // The instructor presses where the tissue is now.
    const QPointF at(viewport->width() / 2.0, viewport->height() / 2.0);
    ASSERT_TRUE(window->viewport()->pickVertexAt(at, viewport->size()));
    sendMouse(*viewport, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
    window->advanceTicks(300);
    EXPECT_TRUE(window->session().observed().contact);
    EXPECT_GT(force(), 0.0);
    sendMouse(*viewport, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
}

TEST_F(EditorInTheWindow, TheExerciseDockGoesBackBesideHistoryForTheTrainee) {
    addTargetByClicking();
    child<QPushButton>(*editor, "previewButton")->click();
    ASSERT_TRUE(window->exercises().running());
    auto* exerciseDock = window->findChild<QDockWidget*>(QStringLiteral("exerciseDock"));
    auto* historyDock = window->findChild<QDockWidget*>(QStringLiteral("historyDock"));
    ASSERT_EQ(window->dockWidgetArea(exerciseDock), Qt::RightDockWidgetArea);
    window->exercises().stop();
    window->setMode(MainWindow::Mode::Trainee);
    QApplication::processEvents();
    EXPECT_EQ(window->dockWidgetArea(exerciseDock), Qt::LeftDockWidgetArea);
    EXPECT_TRUE(window->tabifiedDockWidgets(exerciseDock).contains(historyDock));
    EXPECT_TRUE(exerciseDock->isVisible());
}

TEST_F(EditorInTheWindow, TryItWithAScriptedDeviceHandsTheToolToTheMouse) {
    addTargetByClicking();
    ASSERT_EQ(window->setDeviceUri(QStringLiteral("sim:stroke")), QString());
    ASSERT_FALSE(window->touchMode());
    child<QPushButton>(*editor, "previewButton")->click();
    ASSERT_TRUE(window->exercises().running());
    EXPECT_EQ(window->session().deviceUri(), HapticSession::kInteractiveDeviceUri);
    EXPECT_TRUE(window->session().touchAvailable());
    EXPECT_TRUE(window->touchMode());
}

// A detection exercise is authored like the others: lumps placed by clicking, each with its
// radius, depth and contrast in the table; undo; saved and read back the same; drawn for the
// instructor (never for the trainee); a lump too deep for the mouse is warned about, naming it.
TEST(ExerciseEditor, DetectionExercisesAreAuthoredByClickingLumps) {
    const DrawnMesh drawn = loadMesh("meshes/sphere_1442.off");
    Editor editor;
    editor.panel.setDrawnMesh(drawn.mesh, drawn.path);
    editor.panel.newAction(ExerciseType::DetectLumps)->trigger();
    ASSERT_EQ(editor.panel.exercise().type, ExerciseType::DetectLumps);
    // No lumps is a valid exercise (healthy tissue): Try it is open.
    EXPECT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();
    EXPECT_TRUE(editor.panel.previewAction()->isEnabled());
    EXPECT_FALSE(child<QCheckBox>(editor.panel, "liveScoreCheck")->isChecked());  // hidden by default here
    // It examines with a force the mouse reaches on this tissue (the file's default, 1 N, is beyond
    // the stomach wall's deepest press): no warning; a force beyond the deepest press is warned about.
    const double examiningN = editor.panel.exercise().coverage.minForceN;
    std::printf("[ figures  ] a new detection exercise on %s examines from %.3g N\n",
                editor.panel.exercise().tissuePresetPath.c_str(), examiningN);
    EXPECT_GT(examiningN, 0.0);
    EXPECT_LT(examiningN, CoverageDef{}.minForceN);
    EXPECT_TRUE(shownWarnings(editor.panel).isEmpty()) << shownWarnings(editor.panel).join('\n').toStdString();
    auto* examinedFrom = child<QDoubleSpinBox>(*child<QWidget>(editor.panel, "detect_lumpsPage"),
                                               "coverage.min_force_n");
    examinedFrom->setValue(CoverageDef{}.minForceN);
    ASSERT_EQ(shownWarnings(editor.panel).size(), 1);
    EXPECT_TRUE(shownWarnings(editor.panel)[0].startsWith(QStringLiteral("coverage.min_force_n")))
        << shownWarnings(editor.panel)[0].toStdString();
    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().coverage.minForceN, examiningN);
    EXPECT_TRUE(shownWarnings(editor.panel).isEmpty()) << shownWarnings(editor.panel).join('\n').toStdString();

    child<QToolButton>(editor.panel, "detect_lumps.lumps.add")->click();
    ASSERT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::AddItem);
    const std::vector<VertexId> picks = spreadVertices(*drawn.mesh, 2);
    ASSERT_EQ(picks.size(), 2u);
    editor.panel.vertexPicked(picks[0]);
    editor.panel.vertexPicked(picks[1]);
    const auto& lumps = editor.panel.exercise().detectLumps.lumps;
    ASSERT_EQ(lumps.size(), 2u);
    EXPECT_EQ(lumps[0].at.vertex.value_or(~0u), drawn.mesh->originalIndex()[picks[0]]);
    EXPECT_EQ(lumps[1].at.vertex.value_or(~0u), drawn.mesh->originalIndex()[picks[1]]);
    EXPECT_EQ(editor.panel.placing(), ExerciseEditorPanel::Placing::AddItem);  // stays on for more
    EXPECT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();

    // The instructor sees both, at their surface points.
    ASSERT_EQ(editor.lastMarkers.markers.size(), 2u);
    EXPECT_EQ(editor.lastMarkers.markers[0].positionMm, drawn.mesh->restPositionsMm()[picks[0]]);
    EXPECT_EQ(editor.lastMarkers.markers[1].kind, ExerciseMarker::Kind::Inclusion);
    // And each lump inside the tissue, seen through it: a ball of its radius, its centre its depth
    // plus its radius below the surface point, drawn over the picture where the surface hides it.
    {
        const ExerciseMarker& lump = editor.lastMarkers.markers[0];
        const LumpDef& def = lumps[0];
        EXPECT_EQ(lump.bodyRadiusMm, def.radiusMm);
        EXPECT_NEAR(glm::distance(lump.bodyCentreMm, lump.positionMm), def.depthMm + def.radiusMm, 1e-3);
        EXPECT_LT(glm::dot(lump.bodyCentreMm - lump.positionMm, lump.normal), 0.0f) << "below the surface";
        OrbitCamera camera;
        camera.reset(drawn.mesh->restPositionsMm());
        const QSize size(400, 300);
        const auto centrePx = camera.projectToPixel(lump.bodyCentreMm, glm::vec2(400.0f, 300.0f));
        ASSERT_TRUE(centrePx);
        auto paint = [&](const ExerciseMarkers& markers) {
            QImage image(size, QImage::Format_ARGB32_Premultiplied);
            image.fill(Qt::transparent);
            QPainter painter(&image);
            paintExerciseMarkers(painter, markers, camera, size);
            painter.end();
            return image;
        };
        // (Without their labels: a label sits on the side away from its ball, so it moves with it.)
        ExerciseMarkers withBody = editor.lastMarkers;
        for (ExerciseMarker& m : withBody.markers) m.label.clear();
        ExerciseMarkers surfaceOnly = withBody;
        surfaceOnly.markers[0].bodyRadiusMm = 0.0;
        const QImage seeThrough = paint(withBody), surface = paint(surfaceOnly);
        // The ball (and its line up to the surface) adds opaque pixels around the centre's projection.
        int added = 0, nearCentre = 0;
        const float mmPerPx = camera.mmPerPixelAtTarget(glm::vec2(400.0f, 300.0f));
        const float reachPx = float(def.radiusMm + def.depthMm + def.radiusMm) / mmPerPx + 3.0f;
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x) {
                if (seeThrough.pixelColor(x, y).alphaF() < surface.pixelColor(x, y).alphaF() + 0.2) continue;
                ++added;
                nearCentre += glm::distance(glm::vec2(float(x), float(y)), *centrePx) < reachPx ? 1 : 0;
            }
        EXPECT_GT(added, 20);
        EXPECT_EQ(nearCentre, added);
    }

    // The second lump's depth (columns: number, vertex, radius, depth, contrast): one step.
    auto* table = child<QTableWidget>(editor.panel, "detect_lumps.lumps");
    ASSERT_EQ(table->rowCount(), 2);
    table->item(1, 3)->setData(Qt::EditRole, 3.5);
    EXPECT_EQ(editor.panel.exercise().detectLumps.lumps[1].depthMm, 3.5);
    EXPECT_TRUE(shownWarnings(editor.panel).isEmpty()) << shownWarnings(editor.panel).join('\n').toStdString();
    // Deeper than the mouse presses: warned, naming the lump's depth; it still saves (a device may feel it).
    table->item(1, 3)->setData(Qt::EditRole, Viewport::kMaxTouchDepthMm);
    ASSERT_FALSE(shownWarnings(editor.panel).isEmpty());
    EXPECT_TRUE(shownWarnings(editor.panel)[0].startsWith(QStringLiteral("detect_lumps.lumps[1].depth_mm")))
        << shownWarnings(editor.panel)[0].toStdString();
    EXPECT_TRUE(shownWarnings(editor.panel)[0].contains(QStringLiteral("lump 2")))
        << shownWarnings(editor.panel)[0].toStdString();
    // A contrast of 1 is no lump: a problem naming the cell's key.
    table->item(0, 4)->setData(Qt::EditRole, 1.0);
    EXPECT_TRUE(hasProblemStartingWith(editor.panel.problems(), QStringLiteral("detect_lumps.lumps[0].contrast")))
        << editor.panel.problems().join('\n').toStdString();
    editor.panel.undoStack()->undo();
    EXPECT_EQ(editor.panel.exercise().detectLumps.lumps[0].contrast, LumpDef{}.contrast);
    EXPECT_TRUE(editor.panel.problems().isEmpty()) << editor.panel.problems().join('\n').toStdString();

    // The section's numbers: where a mark counts and the examining force.
    // (Find the lump's page has a field of the same key: the page of the type is the one shown.)
    auto* page = child<QWidget>(editor.panel, "detect_lumpsPage");
    EXPECT_EQ(child<QStackedWidget>(editor.panel, "typePages")->currentWidget(), page);
    child<QDoubleSpinBox>(*page, "coverage.min_force_n")->setValue(0.3);
    EXPECT_EQ(editor.panel.exercise().coverage.minForceN, 0.3);
    child<QDoubleSpinBox>(*page, "detect_lumps.tolerance_mm")->setValue(4.0);
    EXPECT_EQ(editor.panel.exercise().detectLumps.toleranceMm, 4.0);
    child<QCheckBox>(editor.panel, "liveScoreCheck")->setChecked(true);
    EXPECT_EQ(editor.panel.exercise().showLiveScore, std::optional<bool>(true));

    // Remove the first: the second is lump 1 now.
    editor.panel.setPlacing(ExerciseEditorPanel::Placing::None);
    editor.panel.setSelectedIndex(0);
    child<QToolButton>(editor.panel, "detect_lumps.lumps.remove")->click();
    ASSERT_EQ(editor.panel.exercise().detectLumps.lumps.size(), 1u);
    EXPECT_EQ(editor.panel.exercise().detectLumps.lumps[0].depthMm, Viewport::kMaxTouchDepthMm);
    editor.panel.undoStack()->undo();
    ASSERT_EQ(editor.panel.exercise().detectLumps.lumps.size(), 2u);

    // Saved and read back: the same exercise.
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("detect.json"));
    ASSERT_EQ(editor.panel.saveExercise(file), QString());
    const auto loaded = loadExercise(file.toStdString());
    ASSERT_TRUE(loaded.exercise) << loaded.error();
    EXPECT_EQ(loaded.exercise->detectLumps.lumps.size(), 2u);
    EXPECT_EQ(loaded.exercise->detectLumps.lumps[1].depthMm, Viewport::kMaxTouchDepthMm);
    EXPECT_EQ(loaded.exercise->coverage.minForceN, 0.3);
    EXPECT_EQ(loaded.exercise->showLiveScore, std::optional<bool>(true));
    Editor reopened;
    reopened.panel.setDrawnMesh(drawn.mesh, drawn.path);
    ASSERT_EQ(reopened.panel.openExercise(file), QString());
    EXPECT_EQ(json(reopened.panel.exercise()), json(*loaded.exercise));
    EXPECT_EQ(child<QTableWidget>(reopened.panel, "detect_lumps.lumps")->rowCount(), 2);

    // Try it hands the exercise over as it is.
    QSignalSpy tried(&editor.panel, &ExerciseEditorPanel::previewRequested);
    EXPECT_TRUE(editor.panel.preview());
    EXPECT_EQ(tried.count(), 1);

    // The trainee never sees the lumps before the examination is over.
    std::string error;
    const auto geometry = ExerciseGeometry::build(*loaded.exercise, *drawn.mesh, error);
    ASSERT_TRUE(geometry) << error;
    EXPECT_TRUE(exerciseMarkers(*geometry, MarkerAudience::Trainee, nullptr, -1).markers.empty());
}

// The shipped detection exercise opens in the editor (it used to be refused) and has no problems.
TEST(ExerciseEditor, TheShippedDetectionExerciseOpens) {
    Editor editor;
    ASSERT_EQ(editor.panel.openExercise(QString::fromStdString(findInSource("exercises/detect_lumps.json"))),
              QString());
    EXPECT_EQ(editor.panel.exercise().type, ExerciseType::DetectLumps);
    EXPECT_EQ(child<QTableWidget>(editor.panel, "detect_lumps.lumps")->rowCount(), 3);
    // Only the mesh not being drawn is said.
    for (const QString& p : editor.panel.problems())
        EXPECT_TRUE(p.startsWith(QStringLiteral("mesh:"))) << p.toStdString();
}
