// File > Import Mesh… and a mesh's unit in the window (docs/meshes.md, "Units", "Importing a mesh"):
// the import dialog previews a mesh written in cm and suggests cm with the reason, the unit chosen
// changes the size it shows, Import never writes over its input, and writes a mesh in mm that the
// window opens (its status bar says the size); Open Mesh asks once about an implausible size and
// the answer is used when the file is opened again. Own main().
#include "base/resources/ShippedResources.h"
#include "tests/support/IsolatedSettings.h"
#include "app/gui/MainWindow.h"
#include "engine/core/TissueMesh.h"
#include "engine/meshimport/MeshImport.h"
#include "widgets/MeshImportDialog.h"
#include "widgets/MeshSizeText.h"

#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QCryptographicHash>
#include <QDeadlineTimer>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>

#include <glm/geometric.hpp>

#include <fstream>
#include <memory>
#include <optional>

using namespace palpate;

namespace {

/// The bundled sphere's mesh (about 86 mm across).
TissueMesh sphere() {
    auto loaded = TissueMesh::load(findResource("meshes/sphere_1442.off"));
    EXPECT_TRUE(loaded.mesh) << loaded.error();
    return std::move(*loaded.mesh);
}

/// `mesh` written as OFF with every coordinate times `fileUnitsPerMm` (0.1: a file in cm); with
/// `flipped` > 0, that many triangles reversed (a mis-oriented patch: the loader refuses it).
QString writeScaled(const QTemporaryDir& dir, const QString& name, const TissueMesh& mesh, double fileUnitsPerMm,
                    int flipped = 0) {
    const QString path = dir.filePath(name);
    std::ofstream out(path.toStdString());
    out.precision(9);
    out << "OFF\n" << mesh.vertexCount() << ' ' << mesh.triangleCount() << " 0\n";
    for (const glm::vec3& p : mesh.restPositionsMm())
        out << p.x * fileUnitsPerMm << ' ' << p.y * fileUnitsPerMm << ' ' << p.z * fileUnitsPerMm << '\n';
    int index = 0;
    for (const auto& t : mesh.triangles()) {
        if (index++ < flipped) out << "3 " << t[0] << ' ' << t[2] << ' ' << t[1] << '\n';
        else out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    return path;
}

glm::dvec3 sizeOf(const TissueMesh& mesh) { return glm::dvec3(mesh.boundsMaxMm() - mesh.boundsMinMm()); }

void expectSize(const glm::dvec3& actual, const glm::dvec3& expected, double relative = 1e-4) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], relative * expected[i]) << "axis " << i;
}

QByteArray fileHash(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return QCryptographicHash::hash(file.readAll(), QCryptographicHash::Sha256);
}

/// Answers the next modal message box by clicking its button named `buttonName`; records its text.
void answerNextBox(const QString& buttonName, bool& asked, QString* text = nullptr) {
    QTimer::singleShot(0, [buttonName, &asked, text] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) return;
        asked = true;
        if (text) *text = box->text() + QLatin1Char('\n') + box->informativeText();
        for (QAbstractButton* button : box->buttons())
            if (button->objectName() == buttonName) {
                button->click();
                return;
            }
        box->reject();
    });
}

std::unique_ptr<MainWindow> makeWindow() {
    auto window = std::make_unique<MainWindow>(RendererChoice::Software, LoopMode::Stepped);
    EXPECT_EQ(window->setDeviceUri(QStringLiteral("sim:press")), QString());
    window->resize(1024, 700);
    window->show();
    return window;
}

QString meshStatus(const MainWindow& window) {
    const auto* label = window.findChild<QLabel*>(QStringLiteral("meshStatus"));
    return label ? label->text() : QString();
}

class MeshImportTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        ASSERT_TRUE(mDir.isValid());
        mSphere = sphere();
        mSizeMm = sizeOf(mesh());
        mCmFile = writeScaled(mDir, QStringLiteral("organ_cm.off"), mesh(), 0.1);
    }
    void TearDown() override { QSettings().clear(); }

    QTemporaryDir mDir;
    std::optional<TissueMesh> mSphere;
    const TissueMesh& mesh() const { return *mSphere; }
    glm::dvec3 mSizeMm{0.0};
    QString mCmFile;
};

TEST_F(MeshImportTest, PreviewOfACentimetreMeshSuggestsCmWithTheReason) {
    MeshImportDialog dialog;
    dialog.setInputPath(mCmFile);
    ASSERT_TRUE(dialog.waitForPreview());
    ASSERT_TRUE(dialog.suggestion().has_value()) << dialog.previewText().toStdString();
    EXPECT_EQ(dialog.suggestion()->unit.text(), "cm");
    // The unit is preset to the suggestion, the reason is beside it, and the preview is in cm.
    EXPECT_EQ(dialog.unit().text(), "cm");
    ASSERT_FALSE(dialog.suggestion()->reason.empty());
    EXPECT_TRUE(dialog.reasonText().contains(QString::fromStdString(dialog.suggestion()->reason)))
        << dialog.reasonText().toStdString();
    ASSERT_NE(dialog.result(), nullptr);
    EXPECT_EQ(dialog.result()->unit.text(), "cm");
    expectSize(dialog.result()->sizeMm, mSizeMm);
    EXPECT_TRUE(dialog.sizeText().contains(meshSizeText(mSizeMm))) << dialog.sizeText().toStdString();
    EXPECT_TRUE(dialog.sizeText().contains(QStringLiteral("cm"))) << dialog.sizeText().toStdString();
    EXPECT_TRUE(dialog.importEnabled());
    // Vertex and triangle counts are shown.
    EXPECT_TRUE(dialog.previewText().contains(QString::number(mesh().vertexCount())))
        << dialog.previewText().toStdString();
}

TEST_F(MeshImportTest, ChoosingTheUnitChangesTheSizeShown) {
    MeshImportDialog dialog;
    dialog.setInputPath(mCmFile);
    ASSERT_TRUE(dialog.waitForPreview());
    const QString inCm = dialog.sizeText();

    dialog.setUnit(kMillimetres);
    ASSERT_TRUE(dialog.waitForPreview());
    ASSERT_NE(dialog.result(), nullptr);
    EXPECT_TRUE(dialog.result()->unit.isMillimetres());
    expectSize(dialog.result()->sizeMm, mSizeMm * 0.1);
    EXPECT_NE(dialog.sizeText(), inCm);
    EXPECT_TRUE(dialog.sizeText().contains(meshSizeText(mSizeMm * 0.1))) << dialog.sizeText().toStdString();

    std::string error;
    dialog.setUnit(*parseMeshUnit("in", error));
    ASSERT_TRUE(dialog.waitForPreview());
    expectSize(dialog.result()->sizeMm, mSizeMm * 0.1 * 25.4);
    EXPECT_TRUE(dialog.sizeText().contains(QStringLiteral("in"))) << dialog.sizeText().toStdString();

    dialog.setUnit(*parseMeshUnit("2.5", error));  // Scale…: a factor of its own
    ASSERT_TRUE(dialog.waitForPreview());
    expectSize(dialog.result()->sizeMm, mSizeMm * 0.1 * 2.5);
}

TEST_F(MeshImportTest, ImportRefusesTheInputAsItsOutput) {
    MeshImportDialog dialog;
    dialog.setInputPath(mCmFile);
    ASSERT_TRUE(dialog.waitForPreview());
    ASSERT_TRUE(dialog.importEnabled());
    const QByteArray before = fileHash(mCmFile);
    QSignalSpy imported(&dialog, &MeshImportDialog::imported);
    // Spelled as given, and through another spelling of the same file.
    for (const QString& output : {mCmFile, mDir.filePath(QStringLiteral("./sub/../organ_cm.off"))}) {
        QDir(mDir.path()).mkpath(QStringLiteral("sub"));
        const QString error = dialog.importTo(output);
        EXPECT_FALSE(error.isEmpty()) << output.toStdString();
        EXPECT_TRUE(error.contains(QStringLiteral("organ_cm.off"))) << error.toStdString();
    }
    EXPECT_EQ(fileHash(mCmFile), before);
    EXPECT_EQ(imported.count(), 0);
    EXPECT_NE(dialog.defaultOutputPath(), mCmFile);
    EXPECT_TRUE(dialog.defaultOutputPath().endsWith(QStringLiteral("organ_cm-imported.off")));
}

TEST_F(MeshImportTest, ImportWritesAMeshInMmAndTheWindowOpensIt) {
    auto window = makeWindow();
    MeshImportDialog* dialog = window->openImportDialog(mCmFile);
    ASSERT_NE(dialog, nullptr);
    ASSERT_TRUE(dialog->waitForPreview());
    ASSERT_EQ(dialog->unit().text(), "cm");
    const QString output = dialog->defaultOutputPath();
    ASSERT_EQ(dialog->importTo(output), QString());

    // Written in mm: it loads at the sphere's size as a plain mm file.
    auto loaded = TissueMesh::load(output.toStdString());
    ASSERT_TRUE(loaded.mesh) << loaded.error();
    expectSize(sizeOf(*loaded.mesh), mSizeMm);
    // ... and is the window's mesh now, at that size, with the size in the status bar.
    EXPECT_EQ(QString::fromStdString(window->session().drawnPath()), output);
    ASSERT_NE(window->session().drawnMesh(), nullptr);
    expectSize(sizeOf(*window->session().drawnMesh()), mSizeMm);
    const QString status = meshStatus(*window);
    EXPECT_TRUE(status.contains(QStringLiteral("organ_cm-imported.off"))) << status.toStdString();
    EXPECT_TRUE(status.contains(meshSizeText(mSizeMm))) << status.toStdString();
    EXPECT_FALSE(status.contains(QStringLiteral("file in"))) << status.toStdString();
}

TEST_F(MeshImportTest, FaultsAreShownAndRepairMakesAMesh) {
    const QString faulty = writeScaled(mDir, QStringLiteral("faulty.off"), mesh(), 1.0, 12);
    MeshImportDialog dialog;
    dialog.setInputPath(faulty);
    ASSERT_TRUE(dialog.waitForPreview());
    ASSERT_NE(dialog.result(), nullptr);
    ASSERT_TRUE(dialog.result()->faults.hasErrors()) << dialog.previewText().toStdString();
    EXPECT_FALSE(dialog.importEnabled());  // faults without repair: no mesh
    const std::vector<std::string> faults = dialog.result()->faults.errorTexts();
    ASSERT_FALSE(faults.empty());
    EXPECT_TRUE(dialog.previewText().contains(QString::fromStdString(faults.front())))
        << dialog.previewText().toStdString();
    EXPECT_NE(dialog.importTo(mDir.filePath(QStringLiteral("out.off"))), QString());
    EXPECT_FALSE(QFile::exists(mDir.filePath(QStringLiteral("out.off"))));

    auto* repair = dialog.findChild<QCheckBox*>(QStringLiteral("importRepair"));
    ASSERT_NE(repair, nullptr);
    repair->setChecked(true);
    ASSERT_TRUE(dialog.waitForPreview());
    ASSERT_TRUE(dialog.result()->ok()) << dialog.previewText().toStdString();
    EXPECT_TRUE(dialog.importEnabled());
    ASSERT_FALSE(dialog.result()->changes.empty());
    EXPECT_TRUE(dialog.previewText().contains(QString::fromStdString(dialog.result()->changes.front())));
    // Roundness before and after: ring 1..3 and the edge lengths.
    auto* table = dialog.findChild<QTableWidget*>(QStringLiteral("importRoundness"));
    ASSERT_NE(table, nullptr);
    EXPECT_EQ(table->rowCount(), 4);
}

TEST_F(MeshImportTest, CancelStopsAPreviewAndLeavesNoMeshToImport) {
    MeshImportDialog dialog;
    dialog.setInputPath(mCmFile);
    ASSERT_TRUE(dialog.waitForPreview());
    ASSERT_TRUE(dialog.importEnabled());
    // A fine remeshing: long enough to be cancelled while it runs.
    dialog.findChild<QDoubleSpinBox*>(QStringLiteral("importEdge"))->setValue(0.3);
    dialog.findChild<QCheckBox*>(QStringLiteral("importRemesh"))->setChecked(true);
    QDeadlineTimer started(60000);
    while (!dialog.previewRunning() && !started.hasExpired()) QApplication::processEvents(QEventLoop::AllEvents, 20);
    ASSERT_TRUE(dialog.previewRunning());
    EXPECT_FALSE(dialog.importEnabled());
    auto* cancel = dialog.findChild<QPushButton*>(QStringLiteral("importCancel"));
    ASSERT_NE(cancel, nullptr);
    ASSERT_TRUE(cancel->isEnabled());
    cancel->click();
    ASSERT_TRUE(dialog.waitForPreview(300000));
    ASSERT_NE(dialog.result(), nullptr);
    EXPECT_FALSE(dialog.result()->ok());
    ASSERT_FALSE(dialog.result()->errors.empty());
    EXPECT_NE(dialog.result()->errors.front().find("cancelled"), std::string::npos) << dialog.result()->errors.front();
    EXPECT_FALSE(dialog.importEnabled());
}

TEST_F(MeshImportTest, ClosingTheDialogCancelsItsPreview) {
    MeshImportDialog dialog;
    dialog.show();
    dialog.setInputPath(mCmFile);
    ASSERT_TRUE(dialog.waitForPreview());
    dialog.findChild<QDoubleSpinBox*>(QStringLiteral("importEdge"))->setValue(0.3);
    dialog.findChild<QCheckBox*>(QStringLiteral("importRemesh"))->setChecked(true);
    QDeadlineTimer started(60000);
    while (!dialog.previewRunning() && !started.hasExpired()) QApplication::processEvents(QEventLoop::AllEvents, 20);
    ASSERT_TRUE(dialog.previewRunning());
    dialog.reject();  // Close
    ASSERT_TRUE(dialog.waitForPreview(300000));
    ASSERT_NE(dialog.result(), nullptr);
    EXPECT_FALSE(dialog.result()->ok());
    ASSERT_FALSE(dialog.result()->errors.empty());
    EXPECT_NE(dialog.result()->errors.front().find("cancelled"), std::string::npos) << dialog.result()->errors.front();
}

TEST_F(MeshImportTest, OpenAsksOnceAboutTheUnitAndRemembersTheAnswer) {
    auto window = makeWindow();
    bool asked = false;
    QString question;
    answerNextBox(QStringLiteral("openInSuggestedUnit"), asked, &question);
    EXPECT_EQ(window->openMeshFile(mCmFile), QString());
    EXPECT_TRUE(asked);
    EXPECT_TRUE(question.contains(QStringLiteral("organ_cm.off"))) << question.toStdString();
    ASSERT_NE(window->session().drawnMesh(), nullptr);
    expectSize(sizeOf(*window->session().drawnMesh()), mSizeMm);
    EXPECT_TRUE(meshStatus(*window).contains(QStringLiteral("file in cm"))) << meshStatus(*window).toStdString();
    ASSERT_TRUE(MainWindow::rememberedMeshUnit(mCmFile).has_value());
    EXPECT_EQ(MainWindow::rememberedMeshUnit(mCmFile)->text(), "cm");

    // Another mesh, then this one again: no question, read in cm.
    ASSERT_EQ(window->loadMesh(QString::fromStdString(findResource("meshes/stomach_1442.off"))), QString());
    asked = false;
    answerNextBox(QStringLiteral("openAsMillimetres"), asked);
    EXPECT_EQ(window->openMeshFile(mCmFile), QString());
    EXPECT_FALSE(asked);
    expectSize(sizeOf(*window->session().drawnMesh()), mSizeMm);
    QApplication::processEvents();  // the pending answer finds no box

    // A new window (the next start) reads it in cm too, from the settings.
    window.reset();
    auto next = makeWindow();
    ASSERT_EQ(next->loadMesh(mCmFile), QString());
    expectSize(sizeOf(*next->session().drawnMesh()), mSizeMm);
}

TEST_F(MeshImportTest, OpenAsMmIsRememberedToo) {
    auto window = makeWindow();
    bool asked = false;
    answerNextBox(QStringLiteral("openAsMillimetres"), asked);
    EXPECT_EQ(window->openMeshFile(mCmFile), QString());
    EXPECT_TRUE(asked);
    ASSERT_NE(window->session().drawnMesh(), nullptr);
    expectSize(sizeOf(*window->session().drawnMesh()), mSizeMm * 0.1);
    ASSERT_TRUE(MainWindow::rememberedMeshUnit(mCmFile).has_value());
    EXPECT_TRUE(MainWindow::rememberedMeshUnit(mCmFile)->isMillimetres());
    asked = false;
    answerNextBox(QStringLiteral("openInSuggestedUnit"), asked);
    EXPECT_EQ(window->openMeshFile(mCmFile), QString());
    EXPECT_FALSE(asked);
    QApplication::processEvents();
}

TEST_F(MeshImportTest, OpenOffersImportForAnImplausibleSizeAndForFaults) {
    auto window = makeWindow();
    bool asked = false;
    answerNextBox(QStringLiteral("openInImportDialog"), asked);
    EXPECT_EQ(window->openMeshFile(mCmFile), QString());
    EXPECT_TRUE(asked);
    ASSERT_NE(window->importDialog(), nullptr);
    EXPECT_EQ(window->importDialog()->inputPath(), mCmFile);
    EXPECT_FALSE(MainWindow::rememberedMeshUnit(mCmFile).has_value());  // nothing chosen yet
    window->importDialog()->waitForPreview();
    window->importDialog()->close();

    const QString faulty = writeScaled(mDir, QStringLiteral("faulty.off"), mesh(), 1.0, 12);
    asked = false;
    QString text;
    answerNextBox(QStringLiteral("openInImportDialog"), asked, &text);
    EXPECT_NE(window->openMeshFile(faulty), QString());
    EXPECT_TRUE(asked);
    EXPECT_TRUE(text.contains(QStringLiteral("faulty.off"))) << text.toStdString();
    EXPECT_EQ(window->importDialog()->inputPath(), faulty);
    window->importDialog()->waitForPreview();
}

}  // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // QSettings are not the user's
    palpate::test::isolateSettings();
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("palpate-import-dialog-tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
