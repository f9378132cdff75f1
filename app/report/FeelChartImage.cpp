#include "app/report/FeelChartImage.h"

#include "app/report/ChartApplication.h"
#include "app/report/FeelChart.h"

#include <QCoreApplication>
#include <QImage>
#include <QImageWriter>
#include <QPainter>

#include <algorithm>

namespace palpate {

namespace {

constexpr int kMinSidePx = 200;
constexpr int kMaxSidePx = 16000;

}  // namespace

bool renderFeelChartPng(const std::vector<FeelRow>& rows, const std::string& path, std::string* error, int widthPx,
                        int heightPx) {
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
        FeelChart chart;
        chart.setAttribute(Qt::WA_DontShowOnScreen);
        chart.setFrameShape(QFrame::NoFrame);
        chart.setEmptyHint(QObject::tr("No feel bench rows to draw"));
        chart.setTextScale(std::clamp(widthPx / 1000.0, 1.0, 3.0));
        chart.setRows(rows);
        chart.resize(widthPx, heightPx);
        chart.show();  // not on screen: lays out and sends the resize events
        QCoreApplication::processEvents();
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        chart.render(&painter);
    }
    QImageWriter writer(QString::fromStdString(path), "png");
    if (!writer.write(image)) return fail("cannot be written (" + writer.errorString().toStdString() + ")");
    return true;
}

}  // namespace palpate
