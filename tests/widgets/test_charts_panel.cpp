// The speed-vs-accuracy chart and the Charts dock under QT_QPA_PLATFORM=offscreen: one series per
// model with the Pareto points marked and the configuration in use highlighted; the PNG the CLI
// writes; a real (tiny) sweep run off the GUI thread to completion, and cancelled; the dock in the
// main window, loading a sweep CSV when first shown.
#include "app/gui/MainWindow.h"
#include "engine/accuracy/OrganSweep.h"
#include "engine/accuracy/SweepCsv.h"
#include "widgets/ChartsPanel.h"
#include "widgets/ParameterPanel.h"
#include "widgets/StiffeningPanel.h"
#include "report/SpeedAccuracyChart.h"
#include "report/SweepChartImage.h"

#include <QAbstractButton>
#include <QApplication>
#include <QChartView>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QMenuBar>
#include <QProgressBar>
#include <QPushButton>
#include <QSet>
#include <QSettings>
#include <QStandardPaths>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

using namespace palpate;

namespace {

SweepPoint point(const std::string& series, const std::string& model, int rings, GeneratedShape shape,
                 std::size_t vertices, double tickUs, double error) {
    SweepPoint p;
    p.series = series;
    p.model = model;
    p.rings = rings;
    p.shape = shape;
    p.vertices = vertices;
    p.tickUs = tickUs;
    p.error.displacementError = error;
    p.error.forceError = 0.01;
    p.error.indentationMm = 2.5;
    p.error.forceN = 0.5;
    p.error.referenceForceN = 0.5;
    p.error.verticesCompared = 120;
    return p;
}

/// Two shapes, three slope-ring series and one of the paper's, at two resolutions; Pareto marked
/// by the engine's own rule.
std::vector<SweepPoint> samplePoints() {
    std::vector<SweepPoint> points;
    for (GeneratedShape shape : {GeneratedShape::Sphere, GeneratedShape::Stomach})
        for (std::size_t vertices : {std::size_t(1442), std::size_t(3970)}) {
            const double grow = vertices == 1442 ? 1.0 : 1.2;
            points.push_back(point("slope-ring 1 ring", "coherent", 1, shape, vertices, 0.02 * grow, 0.30));
            points.push_back(point("slope-ring 2 rings", "coherent", 2, shape, vertices, 0.03 * grow, 0.20));
            points.push_back(point("slope-ring 3 rings", "coherent", 3, shape, vertices, 0.05 * grow, 0.10));
            points.push_back(point("previous (paper)", "previous", 2, shape, vertices, 8.0 * grow, 0.20));
        }
    markParetoFront(points);
    return points;
}

int paretoCount(const std::vector<SweepPoint>& points, GeneratedShape shape) {
    int n = 0;
    for (const SweepPoint& p : points) n += p.shape == shape && p.pareto;
    return n;
}

/// Counts distinct colours on a coarse grid: a blank or one-colour image has one.
int distinctColours(const QImage& image) {
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 7)
        for (int x = 0; x < image.width(); x += 7) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

}  // namespace

TEST(SpeedAccuracyChart, OneSeriesPerModelAndTheParetoPointsMarked) {
    const std::vector<SweepPoint> points = samplePoints();
    SpeedAccuracyChart chart;
    chart.setPoints(points);
    chart.setShape(GeneratedShape::Sphere);
    EXPECT_EQ(chart.seriesNames(), (QStringList{QStringLiteral("slope-ring 1 ring"), QStringLiteral("slope-ring 2 rings"),
                                                QStringLiteral("slope-ring 3 rings"), QStringLiteral("previous (paper)")}));
    const int expectedPareto = paretoCount(points, GeneratedShape::Sphere);
    ASSERT_GT(expectedPareto, 0);
    EXPECT_EQ(chart.paretoMarkCount(), expectedPareto);
    // The previous method costs 8 us for the error 2 rings give at 0.03 us: never on the front.
    for (const SweepPoint& p : points) {
        if (p.model == "previous") {
            EXPECT_FALSE(p.pareto);
        }
    }
    EXPECT_EQ(chart.shapesPresent().size(), 2u);
    EXPECT_TRUE(chart.chart()->title().contains(QStringLiteral("Sphere")));

    chart.setShape(GeneratedShape::Stomach);
    EXPECT_EQ(chart.shownShape(), GeneratedShape::Stomach);
    EXPECT_EQ(chart.seriesNames().size(), 4);
    EXPECT_EQ(chart.paretoMarkCount(), paretoCount(points, GeneratedShape::Stomach));
    EXPECT_TRUE(chart.chart()->title().contains(QStringLiteral("Stomach")));
}

TEST(SpeedAccuracyChart, HighlightMarksTheConfigurationInUseAndTheTitleNamesTheTissue) {
    SpeedAccuracyChart chart;
    chart.setPoints(samplePoints());
    chart.setShape(GeneratedShape::Sphere);
    EXPECT_EQ(chart.highlightMarkCount(), 0);
    chart.setHighlight("slope-ring 2 rings", 3970);
    EXPECT_EQ(chart.highlightMarkCount(), 1);
    chart.setHighlight("slope-ring 2 rings", 5000);  // not measured at that size
    EXPECT_EQ(chart.highlightMarkCount(), 0);
    chart.clearHighlight();
    EXPECT_EQ(chart.highlightMarkCount(), 0);

    ToolContact contact;
    contact.material = {5.4e-3, 0.49};
    contact.toolRadiusMm = 4.0;
    chart.setToolContact(contact);
    const QString title = chart.chart()->title();
    EXPECT_TRUE(title.contains(QStringLiteral("5.4 kPa"))) << title.toStdString();
    EXPECT_TRUE(title.contains(QStringLiteral("0.49"))) << title.toStdString();
    EXPECT_TRUE(title.contains(QStringLiteral("4 mm"))) << title.toStdString();
}

TEST(SweepChartImage, WritesAPngOfTheRequestedSizeThatIsNotOneColour) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::string path = dir.filePath(QStringLiteral("sweep.png")).toStdString();
    std::string error;
    ASSERT_TRUE((error = renderSweepChartPng(samplePoints(), path, 900, 600)).empty()) << error;
    EXPECT_TRUE(error.empty());
    EXPECT_GT(QFile(QString::fromStdString(path)).size(), 1000);
    QImage image;
    ASSERT_TRUE(image.load(QString::fromStdString(path), "PNG"));
    EXPECT_EQ(image.size(), QSize(900, 600));
    EXPECT_GT(distinctColours(image), 20);  // axes, text, several series colours
    EXPECT_EQ(image.pixel(2, 2), qRgb(255, 255, 255));  // white background

    // A file that cannot be written: false, and a message.
    EXPECT_FALSE((error = renderSweepChartPng(samplePoints(),
                                              dir.filePath(QStringLiteral("no/such/dir/x.png")).toStdString()))
                     .empty());
    EXPECT_FALSE(error.empty());
    EXPECT_FALSE((error = renderSweepChartPng(samplePoints(), path, 10, 10)).empty());
    EXPECT_NE(error.find("size"), std::string::npos) << error;
}

namespace {

/// The smallest real sweep: the 1442-vertex sphere, slope-ring 1 and 2, no paper methods.
SweepDef tinySweep() {
    SweepDef def;
    def.shapes = {GeneratedShape::Sphere};
    def.sizes = {1442};
    def.maxRings = 2;
    def.paperMethods = false;
    def.otherModels = false;
    def.timingRepeats = 1;
    def.minMeasureMs = 1.0;
    def.contact = ParameterPanel::toolContactOf(TissuePreset{});  // the tissue the tests apply
    return def;
}

}  // namespace

TEST(ChartsPanel, RunsATinySweepOffTheGuiThreadToCompletion) {
    ChartsPanel panel;
    TissuePreset applied;
    applied.model.slopeRing.ringCount = 2;
    panel.setCurrentConfiguration(applied, ParameterPanel::toolContactOf(applied), 1442);
    QSignalSpy finished(&panel, &ChartsPanel::sweepFinished);
    QSignalSpy failed(&panel, &ChartsPanel::sweepFailed);

    const auto started = std::chrono::steady_clock::now();
    ASSERT_TRUE(panel.startSweep(tinySweep()));
    const auto returnedAfter = std::chrono::steady_clock::now() - started;
    EXPECT_LT(returnedAfter, std::chrono::milliseconds(200));  // nothing measured on this thread
    EXPECT_TRUE(panel.isRunning());
    EXPECT_FALSE(panel.findChild<QPushButton*>(QStringLiteral("runSweepButton"))->isEnabled());
    EXPECT_TRUE(panel.findChild<QPushButton*>(QStringLiteral("cancelSweepButton"))->isEnabled());
    EXPECT_FALSE(panel.startSweep(tinySweep()));  // one at a time

    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    EXPECT_EQ(failed.count(), 0);
    EXPECT_FALSE(finished.at(0).at(0).toBool());  // not cancelled
    EXPECT_EQ(finished.at(0).at(1).toInt(), 2);
    EXPECT_FALSE(panel.isRunning());
    ASSERT_EQ(panel.points().size(), 2u);
    EXPECT_EQ(panel.points()[0].series, "slope-ring 1 ring");
    EXPECT_EQ(panel.points()[1].series, "slope-ring 2 rings");
    EXPECT_EQ(panel.chart()->seriesNames().size(), 2);
    EXPECT_GT(panel.chart()->paretoMarkCount(), 0);
    // The configuration in use (2 rings on 1442 vertices) is on the chart.
    EXPECT_EQ(panel.chart()->highlightMarkCount(), 1);
    EXPECT_EQ(panel.findChild<QProgressBar*>(QStringLiteral("sweepProgress"))->value(),
              panel.findChild<QProgressBar*>(QStringLiteral("sweepProgress"))->maximum());
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("2 points"))) << panel.statusText().toStdString();
    EXPECT_TRUE(panel.findChild<QPushButton*>(QStringLiteral("saveSweepCsvButton"))->isEnabled());

    // Another tissue in use: the sweep says nothing of it, so nothing is ringed "in use", and the
    // label says what the chart shows instead.
    TissuePreset softer = applied;
    softer.tissue = TissueProperties{};
    softer.tissue->youngsModulusKPa = 1.9;
    panel.setCurrentConfiguration(softer, ParameterPanel::toolContactOf(softer), 1442);
    EXPECT_EQ(panel.chart()->highlightMarkCount(), 0);
    const QString label = panel.findChild<QLabel*>(QStringLiteral("currentConfigurationLabel"))->text();
    EXPECT_TRUE(label.contains(QStringLiteral("another tissue")) && label.contains(QStringLiteral("1.9")))
        << label.toStdString();
    panel.setCurrentConfiguration(applied, ParameterPanel::toolContactOf(applied), 1442);
    EXPECT_EQ(panel.chart()->highlightMarkCount(), 1);
}

TEST(ChartsPanel, HighlightsAModelOtherThanSlopeRingByItsName) {
    ChartsPanel panel;
    SweepDef def = tinySweep();
    def.maxRings = 1;
    def.otherModels = true;  // 1 slope-ring point and one per other model
    QSignalSpy finished(&panel, &ChartsPanel::sweepFinished);
    ASSERT_TRUE(panel.startSweep(def));
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 120000);
    TissuePreset applied;
    setPresetModel(applied, *modelDefForName("radius-of-influence"));
    panel.setCurrentConfiguration(applied, ParameterPanel::toolContactOf(applied), 1442);
    EXPECT_EQ(panel.chart()->highlightMarkCount(), 1);
    EXPECT_EQ(panel.chart()->chart()->axes().size(), 2);  // one pair of axes, however often it is redrawn
    EXPECT_TRUE(panel.chart()->seriesNames().contains(QStringLiteral("radius-of-influence")));
}

TEST(ChartsPanel, CancelRightAfterStartFinishesCancelledWithFewerPoints) {
    ChartsPanel panel;
    QSignalSpy finished(&panel, &ChartsPanel::sweepFinished);
    SweepDef def = tinySweep();
    def.sizes = {1442, 3970};
    def.maxRings = 8;
    def.paperMethods = true;  // 22 points if it ran to the end
    ASSERT_TRUE(panel.startSweep(def));
    panel.cancelSweep();
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    EXPECT_TRUE(finished.at(0).at(0).toBool());
    EXPECT_LT(finished.at(0).at(1).toInt(), 22);
    EXPECT_FALSE(panel.isRunning());
    EXPECT_TRUE(panel.findChild<QPushButton*>(QStringLiteral("runSweepButton"))->isEnabled());
    EXPECT_TRUE(panel.statusText().startsWith(QStringLiteral("Cancelled"))) << panel.statusText().toStdString();
}

TEST(ChartsPanel, DestroyedWhileRunningStopsTheSweep) {
    auto panel = std::make_unique<ChartsPanel>();
    SweepDef def = tinySweep();
    def.sizes = {1442, 3970};
    def.maxRings = 8;
    ASSERT_TRUE(panel->startSweep(def));
    panel.reset();  // cancels and joins: nothing is posted to a dead panel
    QApplication::processEvents();
    SUCCEED();
}

TEST(ChartsPanel, CsvSavesAndLoadsBackWithTheTissue) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    ChartsPanel panel;
    QSignalSpy finished(&panel, &ChartsPanel::sweepFinished);
    TissuePreset applied;
    applied.tissue = TissueProperties{.youngsModulusKPa = 5.4, .poissonRatio = 0.49, .toolRadiusMm = 5.0, .source = "test", .stiffeningSource = ""};
    panel.setCurrentConfiguration(applied, ParameterPanel::toolContactOf(applied), 1442);
    SweepDef def = tinySweep();
    def.contact = ParameterPanel::toolContactOf(applied);
    ASSERT_TRUE(panel.startSweep(def));
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
    const QString path = dir.filePath(QStringLiteral("sweep.csv"));
    QString error;
    ASSERT_TRUE(panel.saveCsv(path, &error)) << error.toStdString();
    EXPECT_TRUE(QFile::exists(dir.filePath(QStringLiteral("sweep.json"))));

    ChartsPanel other;
    ASSERT_TRUE(other.loadCsv(path, &error)) << error.toStdString();
    ASSERT_EQ(other.points().size(), panel.points().size());
    for (std::size_t i = 0; i < other.points().size(); ++i) EXPECT_EQ(other.points()[i].series, panel.points()[i].series);
    EXPECT_TRUE(other.chart()->chart()->title().contains(QStringLiteral("5.4 kPa"))) << other.chart()->chart()->title().toStdString();

    // A broken file: the chart keeps its points and the message names the line.
    QFile broken(dir.filePath(QStringLiteral("broken.csv")));
    ASSERT_TRUE(broken.open(QIODevice::WriteOnly));
    broken.write(QByteArray::fromStdString(sweepToCsv(panel.points())) + "sphere,1442,x,palpate,1,abc,0.1,0,0,0,0,0,0,,,\n");
    broken.close();
    EXPECT_FALSE(other.loadCsv(broken.fileName(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("line 4"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("tick_us"))) << error.toStdString();
    EXPECT_EQ(other.points().size(), panel.points().size());
}

TEST(MainWindowCharts, ChartsDockIsTabbedTogglesFromTheViewMenuAndLoadsTheSweepWhenShown) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::vector<SweepPoint> points = samplePoints();
    const QString csv = dir.filePath(QStringLiteral("sweep.csv"));
    {
        QFile file(csv);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(QByteArray::fromStdString(sweepToCsv(points)));
    }

    QSettings().clear();  // no window state from an earlier run: the default dock layout
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ASSERT_EQ(window.loadMesh(QString::fromStdString(PALPATE_SOURCE_DIR "/resources/meshes/stomach_3970.off")), QString());
    ChartsPanel* charts = window.chartsPanel();
    ASSERT_NE(charts, nullptr);
    charts->setDefaultCsv(csv);
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("chartsDock"));
    ASSERT_NE(dock, nullptr);
    auto* parameters = window.findChild<QDockWidget*>(QStringLiteral("parametersDock"));
    EXPECT_TRUE(window.tabifiedDockWidgets(parameters).contains(dock));
    // The View menu toggles it like the other docks.
    bool inViewMenu = false;
    for (QAction* menu : window.menuBar()->actions())
        if (menu->menu())
            for (QAction* action : menu->menu()->actions()) inViewMenu |= action == dock->toggleViewAction();
    EXPECT_TRUE(inViewMenu);

    window.resize(1400, 900);
    window.show();
    EXPECT_TRUE(charts->points().empty());  // the Parameters tab is in front: not loaded yet
    dock->raise();
    QTRY_COMPARE(charts->points().size(), points.size());
    // Applied: default preset (2 rings, ours) on the 3970-vertex mesh: measured in the sample.
    EXPECT_EQ(charts->chart()->highlightMarkCount(), 1);
    // Another ring count applied: the highlight follows.
    TissuePreset preset = window.parameterPanel()->preset();
    preset.model.slopeRing.ringCount = 3;
    ASSERT_EQ(window.applyPreset(preset), QString());
    EXPECT_EQ(charts->chart()->highlightMarkCount(), 1);
    EXPECT_TRUE(charts->findChild<QLabel*>(QStringLiteral("currentConfigurationLabel"))->text().contains(QStringLiteral("3 rings")));

    QApplication::processEvents();
    const QImage shot = window.grab().toImage();
    if (const QByteArray out = qgetenv("PALPATE_TEST_SCREENSHOTS"); !out.isEmpty())
        shot.save(QString::fromLocal8Bit(out) + QStringLiteral("/charts_dock.png"));
    const QRect chartBox(charts->chart()->mapTo(&window, QPoint(0, 0)), charts->chart()->size());
    EXPECT_GT(distinctColours(shot.copy(chartBox)), 10);
    window.close();
}

TEST(MainWindowCharts, ChartsTabInFrontAtTheFirstShowLoadsTheSweep) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString csv = dir.filePath(QStringLiteral("sweep.csv"));
    {
        QFile file(csv);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(QByteArray::fromStdString(sweepToCsv(samplePoints())));
    }
    QSettings().clear();
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    window.chartsPanel()->setDefaultCsv(csv);
    window.findChild<QDockWidget*>(QStringLiteral("chartsDock"))->raise();  // as a restored window state may
    window.show();
    QTRY_COMPARE(window.chartsPanel()->points().size(), samplePoints().size());
    window.close();
}

int main(int argc, char** argv) {
    // Before QApplication: the platform is chosen in its constructor. No GPU, no display needed.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // QSettings of these tests never touch the user's
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

// The organ sweep's points carry a site: the shape list offers each site, and the chart draws one
// site's points with its reference named in the title.
TEST(ChartsPanel, OrganSweepSitesAreChosenInTheShapeList) {
    ChartsPanel panel;
    QTemporaryDir dir;
    std::vector<SweepPoint> points;
    for (const char* site : {"thin", "thick", "curved"})
        for (int rings : {1, 2}) {
            SweepPoint p = point("slope-ring " + std::to_string(rings) + (rings == 1 ? " ring" : " rings"), "coherent", rings,
                                 GeneratedShape::Stomach, 1442, 0.1 * rings, 0.1 + 0.05 * rings);
            p.site = site;
            p.hyperelasticDisplacementError = 0.2;
            points.push_back(p);
        }
    SweepPoint unmeasured = points.back();
    unmeasured.series = "proposed (paper)";
    unmeasured.error.displacementError = std::nan("");
    points.push_back(unmeasured);
    markParetoFront(points);
    EXPECT_FALSE(points.back().pareto);  // an unmeasured point is on no front
    const QString path = dir.filePath(QStringLiteral("organ.csv"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QByteArray::fromStdString(sweepToCsv(points)));
    file.close();
    QString error;
    ASSERT_TRUE(panel.loadCsv(path, &error)) << error.toStdString();
    auto* combo = panel.findChild<QComboBox*>(QStringLiteral("sweepShapeCombo"));
    ASSERT_NE(combo, nullptr);
    ASSERT_EQ(combo->count(), 3);
    EXPECT_EQ(combo->itemText(0), QStringLiteral("Stomach, thin site"));
    EXPECT_TRUE(combo->isEnabled());
    EXPECT_TRUE(panel.chart()->chart()->title().contains(QStringLiteral("thin site"))) << panel.chart()->chart()->title().toStdString();
    combo->setCurrentIndex(2);
    EXPECT_EQ(panel.chart()->shownSite(), "curved");
    EXPECT_TRUE(panel.chart()->chart()->title().contains(QStringLiteral("curved"))) << panel.chart()->chart()->title().toStdString();
    // One pair of axes, however often the chart is drawn again.
    EXPECT_EQ(panel.chart()->chart()->axes().size(), 2);
    // The unmeasured point is not drawn: two slope-ring series only.
    EXPECT_EQ(panel.chart()->seriesNames().filter(QStringLiteral("proposed")).size(), 0);
}

// The stiffening tab solves the hyperelastic reference for the tissue in use off the GUI thread and
// draws it beside the linear and the knotted model; another tissue clears it.
TEST(ChartsPanel, StiffeningTabDrawsTheReferenceBesideBothModels) {
    ChartsPanel panel;
    ASSERT_EQ(panel.tabs()->count(), 3);
    StiffeningPanel* stiff = panel.stiffeningPanel();
    ASSERT_NE(stiff, nullptr);
    TissuePreset applied;
    applied.tissue = TissueProperties{};
    applied.tissue->stiffeningExponent = 5.0;
    const ToolContact contact = ParameterPanel::toolContactOf(applied);
    EXPECT_EQ(contact.stiffeningExponent, 5.0);
    applied.model.slopeRing.slopeMagnitudeMmPerN[0] = punchFirstSlopeMmPerN(contact);
    panel.setCurrentConfiguration(applied, contact, 1442);
    EXPECT_TRUE(stiff->seriesNames().isEmpty());
    EXPECT_TRUE(stiff->statusText().contains(QStringLiteral("Compute"))) << stiff->statusText().toStdString();
    QSignalSpy computed(stiff, &StiffeningPanel::computed);
    auto* depth = stiff->findChild<QDoubleSpinBox*>(QStringLiteral("stiffeningDepthSpin"));
    ASSERT_NE(depth, nullptr);
    depth->setValue(2.0);  // a short solve
    const auto started = std::chrono::steady_clock::now();
    ASSERT_TRUE(stiff->compute());
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::milliseconds(200));  // solved elsewhere
    EXPECT_FALSE(stiff->compute());  // one at a time
    QTRY_COMPARE_WITH_TIMEOUT(computed.count(), 1, 120000);
    EXPECT_TRUE(computed.at(0).at(0).toBool()) << stiff->statusText().toStdString();
    ASSERT_TRUE(stiff->reference());
    EXPECT_NEAR(stiff->reference()->curve.back().depthMm, 2.0, 1e-9);
    EXPECT_GT(stiff->reference()->curve.back().ratio, 1.05);  // b = 5 stiffens
    EXPECT_EQ(stiff->seriesNames().size(), 3);
    EXPECT_TRUE(stiff->statusText().contains(QStringLiteral("times the linear force"))) << stiff->statusText().toStdString();

    // With the preset's own knots a fourth curve shows them.
    SlopeRingParams knotted = applied.model.slopeRing;
    applyStiffening(*stiff->reference(), knotted);
    applied.model.slopeRing = knotted;
    panel.setCurrentConfiguration(applied, contact, 1442);
    EXPECT_EQ(stiff->seriesNames().size(), 4);

    applied.tissue->stiffeningExponent = 0.0;
    panel.setCurrentConfiguration(applied, ParameterPanel::toolContactOf(applied), 1442);
    EXPECT_FALSE(stiff->reference());
    EXPECT_TRUE(stiff->seriesNames().isEmpty());
    EXPECT_TRUE(stiff->statusText().contains(QStringLiteral("changed"))) << stiff->statusText().toStdString();
}

// Run sweep against the organ's FEM from the dock: off the GUI thread, its sites in the shape list.
TEST(ChartsPanel, RunsTheOrganSweepOffTheGuiThread) {
    ChartsPanel panel;
    auto* reference = panel.findChild<QComboBox*>(QStringLiteral("sweepReferenceCombo"));
    ASSERT_NE(reference, nullptr);
    ASSERT_EQ(reference->count(), 2);
    EXPECT_EQ(reference->itemData(1).toString(), QStringLiteral("fem"));
    OrganSweepDef def;
    def.sweep.contact.material = {4.34e-3, 0.45};
    def.sweep.maxRings = 1;
    def.sweep.paperMethods = false;
    def.sweep.otherModels = false;
    def.sweep.timingRepeats = 1;
    def.sweep.minMeasureMs = 0.5;
    def.sizes = {1442};
    def.reference.maxDepthMm = 1.0;
    def.reference.hyperelasticSteps = 2;
    QSignalSpy finished(&panel, &ChartsPanel::sweepFinished);
    const auto started = std::chrono::steady_clock::now();
    ASSERT_TRUE(panel.startOrganSweep(def));
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::milliseconds(200));
    EXPECT_FALSE(reference->isEnabled());  // not while it runs
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 180000);
    EXPECT_FALSE(finished.at(0).at(0).toBool());
    EXPECT_EQ(finished.at(0).at(1).toInt(), 6);  // 1 ring and 1 ring with knots, at 3 sites
    EXPECT_TRUE(reference->isEnabled());
    auto* combo = panel.findChild<QComboBox*>(QStringLiteral("sweepShapeCombo"));
    ASSERT_EQ(combo->count(), 3);
    EXPECT_TRUE(combo->itemText(1).contains(QStringLiteral("thick")));
}
