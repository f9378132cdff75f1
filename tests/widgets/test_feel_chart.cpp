// The feel chart (report/FeelChart.h) and the Charts dock's Feel tab under
// QT_QPA_PLATFORM=offscreen: one series per model with the points above the goal counted, the
// goal line, both x axes; the PNG; the panel reading a feel bench CSV (and refusing a bad one,
// keeping what it showed); palpate-cli bench feel --png run as a process (PALPATE_CLI_PATH). Shares
// chart_tests' main() in test_charts_panel.cpp.
#include "app/gui/MainWindow.h"
#include "report/FeelChart.h"
#include "report/FeelChartImage.h"
#include "engine/bench/FeelCsv.h"
#include "widgets/ChartsPanel.h"
#include "widgets/FeelPanel.h"

#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QLogValueAxis>
#include <QProcess>
#include <QSet>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace palpate;

namespace {

FeelRow row(const std::string& model, GeneratedShape shape, std::size_t vertices, double stepPct, double tickNs,
            double previousNs) {
    FeelRow r;
    r.model = model;
    r.shape = shape;
    r.vertices = vertices;
    r.depthMm = 1.0;
    r.speedMmPerS = 25.0;
    r.metrics.ticks = 1500;
    r.metrics.meanForceN = 0.6;
    r.metrics.maxStepPct = stepPct;
    r.tickNs = tickNs;
    r.previousTickNs = previousNs;
    return r;
}

/// Three models on both shapes at two sizes: coherent above the goal on the coarse meshes only.
std::vector<FeelRow> sampleRows() {
    std::vector<FeelRow> rows;
    for (GeneratedShape shape : {GeneratedShape::Sphere, GeneratedShape::Stomach})
        for (std::size_t n : {std::size_t(1442), std::size_t(8664)}) {
            const double previous = n == 1442 ? 6000.0 : 37000.0;
            rows.push_back(row("coherent", shape, n, n == 1442 ? 4.0 : 0.8, 45.0, previous));
            rows.push_back(row("previous", shape, n, n == 1442 ? 10.0 : 3.0, previous, previous));
            rows.push_back(row("mass-spring-local", shape, n, 0.0, 20000.0,
                               previous));  // a steady force: drawn at the floor
        }
    return rows;
}

int distinctColoursIn(const QImage& image) {
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

QString writeCsv(const QTemporaryDir& dir, const QString& name, const std::string& text) {
    const QString path = dir.filePath(name);
    QFile file(path);
    file.open(QIODevice::WriteOnly);
    file.write(QByteArray::fromStdString(text));
    return path;
}

}  // namespace

TEST(FeelChart, OneSeriesPerModelThePointsAboveTheGoalAndTheGoalLine) {
    FeelChart chart;
    chart.resize(900, 600);
    EXPECT_EQ(chart.pointCount(), 0);
    chart.setRows(sampleRows());
    EXPECT_EQ(chart.pointCount(), 12);
    EXPECT_EQ(chart.pointsAboveGoal(), 6);  // coherent at 1442 (2) and previous everywhere (4)
    EXPECT_EQ(chart.seriesNames(), (QStringList{QStringLiteral("coherent"), QStringLiteral("previous"),
                                                QStringLiteral("mass-spring-local")}));
    bool goal = false;
    for (QAbstractSeries* s : chart.chart()->series()) goal |= s->objectName() == QLatin1String("stepGoal");
    EXPECT_TRUE(goal);
    EXPECT_TRUE(chart.legendHtml().contains(QStringLiteral("coherent")));

    // Ratio to previous: previous itself at 1; in microseconds: 6 and 37.
    auto range = [&] {
        for (QAbstractAxis* axis : chart.chart()->axes(Qt::Horizontal))
            if (auto* log = qobject_cast<QLogValueAxis*>(axis)) return std::make_pair(log->min(), log->max());
        return std::make_pair(0.0, 0.0);
    };
    EXPECT_LE(range().first, 45.0 / 37000.0);
    EXPECT_GE(range().second, 20000.0 / 6000.0);
    chart.setXAxis(FeelChart::XAxis::TickMicroseconds);
    EXPECT_LE(range().first, 0.045);
    EXPECT_GE(range().second, 20.0);
    EXPECT_EQ(chart.pointCount(), 12);

    // A row without figures (a model that could not be built) is not drawn.
    std::vector<FeelRow> rows = sampleRows();
    rows.push_back(row("ffd", GeneratedShape::Sphere, 1442, std::nan(""), std::nan(""), 6000.0));
    chart.setRows(rows);
    EXPECT_EQ(chart.pointCount(), 12);
}

TEST(FeelChartImage, WritesAPngOfTheRequestedSize) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::string path = dir.filePath(QStringLiteral("feel.png")).toStdString();
    std::string error;
    ASSERT_TRUE((error = renderFeelChartPng(sampleRows(), path, 1000, 700)).empty()) << error;
    QImage image;
    ASSERT_TRUE(image.load(QString::fromStdString(path), "PNG"));
    EXPECT_EQ(image.size(), QSize(1000, 700));
    EXPECT_GT(distinctColoursIn(image), 20);
    EXPECT_EQ(image.pixel(2, 2), qRgb(255, 255, 255));
    EXPECT_FALSE((error = renderFeelChartPng(sampleRows(), path, 10, 10)).empty());
    EXPECT_NE(error.find("size"), std::string::npos) << error;
}

TEST(FeelPanel, LoadsAFeelCsvAndKeepsItOnABadOne) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    FeelPanel panel;
    const QString good = writeCsv(dir, QStringLiteral("feel.csv"), feelToCsv(sampleRows()));
    QString error;
    ASSERT_TRUE(panel.loadCsv(good, &error)) << error.toStdString();
    EXPECT_EQ(panel.rows().size(), sampleRows().size());
    EXPECT_TRUE(panel.statusText().contains(QStringLiteral("6 of 12"))) << panel.statusText().toStdString();

    const QString bad = writeCsv(dir, QStringLiteral("bad.csv"), "shape,vertices,model\nsphere,1442,coherent\n");
    EXPECT_FALSE(panel.loadCsv(bad, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("max_step_pct"))) << error.toStdString();
    EXPECT_EQ(panel.rows().size(), sampleRows().size());  // still the good one
    EXPECT_FALSE(panel.loadCsv(dir.filePath(QStringLiteral("missing.csv")), &error));
    EXPECT_FALSE(panel.loadCsv(writeCsv(dir, QStringLiteral("empty.csv"), feelToCsv({})), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no rows"))) << error.toStdString();

    // The x axis follows the combo.
    auto* combo = panel.findChild<QComboBox*>(QStringLiteral("feelAxisCombo"));
    ASSERT_NE(combo, nullptr);
    combo->setCurrentIndex(1);
    EXPECT_EQ(panel.chart()->xAxis(), FeelChart::XAxis::TickMicroseconds);
}

TEST(MainWindowCharts, TheFeelTabLoadsTheFeelCsvWhenTheDockIsFirstShown) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString csv = writeCsv(dir, QStringLiteral("feel.csv"), feelToCsv(sampleRows()));
    QSettings().clear();
    MainWindow window(RendererChoice::Software, LoopMode::Stepped);
    ChartsPanel* charts = window.chartsPanel();
    charts->feelPanel()->setDefaultCsv(csv);
    ASSERT_EQ(charts->tabs()->count(), 3);  // the sweep, the feel, the stiffening
    EXPECT_EQ(charts->tabs()->widget(1), charts->feelPanel());
    window.resize(1400, 900);
    window.show();
    EXPECT_TRUE(charts->feelPanel()->rows().empty());  // the Parameters tab is in front: not loaded yet
    window.findChild<QDockWidget*>(QStringLiteral("chartsDock"))->raise();
    QTRY_COMPARE(charts->feelPanel()->rows().size(), sampleRows().size());
    charts->tabs()->setCurrentIndex(1);
    QApplication::processEvents();
    const QImage shot = window.grab().toImage();
    const QRect chartBox(charts->feelPanel()->chart()->mapTo(&window, QPoint(0, 0)),
                         charts->feelPanel()->chart()->size());
    EXPECT_GT(distinctColoursIn(shot.copy(chartBox)), 10);
    window.close();
}

TEST(FeelCli, QuickBenchWritesAPng) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString png = dir.filePath(QStringLiteral("feel chart.png"));  // a space, on purpose
    QProcess cli;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));  // the CLI chooses offscreen itself
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    cli.setProcessEnvironment(env);
    cli.start(QStringLiteral(PALPATE_CLI_PATH),
              {QStringLiteral("bench"), QStringLiteral("feel"), QStringLiteral("--quick"), QStringLiteral("--models"),
               QStringLiteral("coherent,previous"), QStringLiteral("--loop-models"), QStringLiteral("none"),
               QStringLiteral("--png"), png});
    ASSERT_TRUE(cli.waitForFinished(120000));
    const QString output = QString::fromLocal8Bit(cli.readAllStandardOutput() + cli.readAllStandardError());
    ASSERT_EQ(cli.exitStatus(), QProcess::NormalExit) << output.toStdString();
    ASSERT_EQ(cli.exitCode(), 0) << output.toStdString();
    EXPECT_FALSE(output.contains(QStringLiteral("propagateSizeHints"))) << output.toStdString();
    QImage image;
    ASSERT_TRUE(image.load(png, "PNG"));
    EXPECT_EQ(image.size(), QSize(1400, 900));
}
