#include "report/ChartImage.h"

#include <QChart>
#include <QCoreApplication>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QPalette>

namespace palpate {

std::string chartImageProblem(int widthPx, int heightPx, const std::string& path) {
    if (widthPx < kChartImageMinSidePx || heightPx < kChartImageMinSidePx || widthPx > kChartImageMaxSidePx ||
        heightPx > kChartImageMaxSidePx)
        return "image size " + std::to_string(widthPx) + "x" + std::to_string(heightPx) + " px is outside " +
               std::to_string(kChartImageMinSidePx) + ".." + std::to_string(kChartImageMaxSidePx) + " px";
    if (path.empty()) return "no file name";
    return {};
}

void applyChartFonts(QChart& chart, const QFont& base, double textScale) {
    auto sized = [&](double factor, bool bold) {
        QFont f = base;
        f.setPointSizeF(base.pointSizeF() * factor * textScale);
        f.setBold(bold);
        return f;
    };
    chart.setTitleFont(sized(1.25, false));
    chart.legend()->setFont(sized(1.0, false));
    for (QAbstractAxis* axis : chart.axes()) {
        axis->setLabelsFont(sized(1.0, false));
        axis->setTitleFont(sized(1.05, true));
    }
}

std::string renderWidgetPng(QWidget& widget, int widthPx, int heightPx, const std::string& path) {
    QImage image(widthPx, heightPx, QImage::Format_RGB32);
    image.fill(Qt::white);
    widget.setAttribute(Qt::WA_DontShowOnScreen);
    widget.setAutoFillBackground(true);
    widget.setPalette(QPalette(Qt::white));
    widget.resize(widthPx, heightPx);
    widget.show();  // not on screen (WA_DontShowOnScreen): lays out and sends the resize events
    QCoreApplication::processEvents();
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        widget.render(&painter);
    }
    QImageWriter writer(QString::fromStdString(path), "png");
    if (!writer.write(image)) return "cannot be written (" + writer.errorString().toStdString() + ")";
    return {};
}

}  // namespace palpate
