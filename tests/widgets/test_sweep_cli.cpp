// palpate-cli sweep with the chart (a build with Qt Charts), run as a separate process: a tiny
// sweep writes a PNG and a CSV with a header and rows, and exits 0.
#include "engine/accuracy/SweepCsv.h"

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace palpate;

TEST(SweepCli, QuickSweepWritesAPngAndACsv) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString png = dir.filePath(QStringLiteral("sweep chart.png"));  // a space, on purpose
    const QString csv = dir.filePath(QStringLiteral("sweep.csv"));
    QProcess cli;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));  // the CLI chooses offscreen itself
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    cli.setProcessEnvironment(env);
    cli.start(QStringLiteral(PALPATE_CLI_PATH),
              {QStringLiteral("sweep"), QStringLiteral("--quick"), QStringLiteral("--no-paper"), QStringLiteral("--no-others"), QStringLiteral("--max-rings"),
               QStringLiteral("2"), QStringLiteral("--sizes"), QStringLiteral("1442"), QStringLiteral("--png"), png,
               QStringLiteral("--csv"), csv});
    ASSERT_TRUE(cli.waitForFinished(120000));
    const QString output = QString::fromLocal8Bit(cli.readAllStandardOutput() + cli.readAllStandardError());
    ASSERT_EQ(cli.exitStatus(), QProcess::NormalExit) << output.toStdString();
    ASSERT_EQ(cli.exitCode(), 0) << output.toStdString();
    EXPECT_FALSE(output.contains(QStringLiteral("propagateSizeHints"))) << output.toStdString();

    QFile pngFile(png);
    ASSERT_TRUE(pngFile.open(QIODevice::ReadOnly));
    EXPECT_TRUE(pngFile.read(8).startsWith("\x89PNG")) << "not a PNG";
    QImage image;
    ASSERT_TRUE(image.load(png, "PNG"));
    EXPECT_EQ(image.size(), QSize(1400, 1500));  // tall enough for two charts and every model in the legend

    QFile csvFile(csv);
    ASSERT_TRUE(csvFile.open(QIODevice::ReadOnly));
    const std::string text = csvFile.readAll().toStdString();
    EXPECT_EQ(text.rfind("shape,vertices,series,model,rings,tick_us,displacement_error", 0), 0u) << text;
    std::string error;
    const auto points = parseSweepCsv(text, &error);
    EXPECT_TRUE(error.empty()) << error;
    EXPECT_EQ(points.size(), 2u);  // sphere 1442: slope-ring 1 and 2 rings
}
