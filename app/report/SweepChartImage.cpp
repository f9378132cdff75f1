#include "app/report/SweepChartImage.h"

#include "app/report/ChartApplication.h"
#include "app/report/SpeedAccuracyChart.h"

#include <QApplication>
#include <QVBoxLayout>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QWidget>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace palpate {

namespace {

constexpr int kMinSidePx = 200;
constexpr int kMaxSidePx = 16000;

}  // namespace

bool renderSweepChartPng(const std::vector<SweepPoint>& points, const std::string& path, std::string* error, int widthPx,
                         int heightPx) {
    return renderSweepChartPng(points, std::nullopt, path, error, widthPx, heightPx);
}

bool renderSweepChartPng(const std::vector<SweepPoint>& points, const std::optional<ToolContact>& contact,
                         const std::string& path, std::string* error, int widthPx, int heightPx) {
    auto fail = [&](const std::string& message) {
        if (error) *error = message;
        return false;
    };
    if (widthPx < kMinSidePx || heightPx < kMinSidePx || widthPx > kMaxSidePx || heightPx > kMaxSidePx)
        return fail("image size " + std::to_string(widthPx) + "x" + std::to_string(heightPx) + " px is outside " +
                    std::to_string(kMinSidePx) + ".." + std::to_string(kMaxSidePx) + " px");
    if (path.empty()) return fail("no file name");
    const ChartApplication application;
    if (!application.problem().empty()) return fail(application.problem());

    QImage image(widthPx, heightPx, QImage::Format_RGB32);
    image.fill(Qt::white);
    {
        // One chart per shape, one above the other (the log tick axis needs the width); the axes span
        // every point, so the two compare directly.
        QWidget canvas;
        canvas.setAttribute(Qt::WA_DontShowOnScreen);
        canvas.setAutoFillBackground(true);
        canvas.setPalette(QPalette(Qt::white));
        auto* layout = new QVBoxLayout(&canvas);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(0);
        std::vector<GeneratedShape> shapes;
        for (const SweepPoint& p : points)
            if (std::find(shapes.begin(), shapes.end(), p.shape) == shapes.end()) shapes.push_back(p.shape);
        if (shapes.empty()) shapes.push_back(GeneratedShape::Sphere);
        for (std::size_t i = 0; i < shapes.size(); ++i) {
            auto* chart = new SpeedAccuracyChart(&canvas);
            chart->setEmptyHint(QObject::tr("No sweep points to draw"));
            chart->setPoints(points);
            chart->setShape(shapes[i]);
            chart->setToolContact(contact);
            chart->setFrameShape(QFrame::NoFrame);
            chart->setTextScale(std::clamp(widthPx / 1000.0, 1.0, 3.0));
            layout->addWidget(chart, 1);
        }
        canvas.resize(widthPx, heightPx);
        canvas.show();  // not on screen (WA_DontShowOnScreen): lays out and sends the resize events
        QCoreApplication::processEvents();
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        canvas.render(&painter);
    }
    QImageWriter writer(QString::fromStdString(path), "png");
    if (!writer.write(image)) return fail("cannot be written (" + writer.errorString().toStdString() + ")");
    return true;
}

}  // namespace palpate
