#include "report/StabilityMapImage.h"

#include <QGuiApplication>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace palpate {

namespace {

/// An application for a process that has none: text needs fonts, fonts need a QGuiApplication.
/// Offscreen unless QT_QPA_PLATFORM says otherwise, so the PNG never needs a display.
std::unique_ptr<QGuiApplication> makeApplication() {
    static int argc = 1;
    static char name[] = "palpate-cli";
    static char platformFlag[] = "-platform";
    static char offscreen[] = "offscreen";
    static char* argv[] = {name, platformFlag, offscreen, nullptr};
    argc = qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") ? 3 : 1;
    return std::make_unique<QGuiApplication>(argc, argv);
}

/// While the CLI's own application draws: drops the offscreen platform's notices that say nothing
/// about the PNG (no XDG_RUNTIME_DIR); every other message passes.
void quietHandler(QtMsgType type, const QMessageLogContext& context, const QString& message);
QtMessageHandler sPreviousHandler = nullptr;
void quietHandler(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (type != QtCriticalMsg && type != QtFatalMsg && message.contains(QLatin1String("XDG_RUNTIME_DIR"))) return;
    if (sPreviousHandler) sPreviousHandler(type, context, message);
    else std::fprintf(stderr, "%s\n", qPrintable(message));
}

/// Position 0..1 of a value along an axis (log or linear).
double fraction(const StabilityAxis& axis, double v) {
    if (axis.logScale) return std::log(v / axis.minValue) / std::log(axis.maxValue / axis.minValue);
    return (v - axis.minValue) / (axis.maxValue - axis.minValue);
}

QString axisTitle(const StabilityAxis& axis) {
    QString t = QString::fromStdString(axis.name);
    if (!axis.unit.empty()) t += QStringLiteral(" (") + QString::fromStdString(axis.unit) + QStringLiteral(")");
    if (axis.logScale) t += QStringLiteral(", log");
    return t;
}

/// Tick values: decades (1, 2, 5 within) for a log axis, 5 even steps for a linear one.
std::vector<double> ticks(const StabilityAxis& axis) {
    std::vector<double> out;
    if (!axis.logScale) {
        // 1, 2 or 5 times a power of ten, about five steps over the range.
        const double raw = (axis.maxValue - axis.minValue) / 5.0;
        const double decade = std::pow(10.0, std::floor(std::log10(raw)));
        const double step = raw / decade < 1.5 ? decade : raw / decade < 3.5 ? 2 * decade : 5 * decade;
        for (double v = std::ceil(axis.minValue / step - 1e-9) * step; v <= axis.maxValue + 1e-9 * step; v += step)
            out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
        return out;
    }
    const double decades = std::log10(axis.maxValue / axis.minValue);
    for (int e = int(std::floor(std::log10(axis.minValue))); e <= int(std::ceil(std::log10(axis.maxValue))); ++e)
        for (double m : {1.0, 2.0, 5.0}) {
            if (decades > 3.5 && m != 1.0) continue;
            const double v = m * std::pow(10.0, e);
            if (v >= axis.minValue * 0.999 && v <= axis.maxValue * 1.001) out.push_back(v);
        }
    return out;
}

}  // namespace

std::string renderStabilityMapPng(const StabilityMap& map, const std::string& path, int widthPx, int heightPx) {
    if (widthPx < 300 || heightPx < 300 || widthPx > 8000 || heightPx > 8000) return "image size out of range";
    if (path.empty()) return "no file name";
    std::unique_ptr<QGuiApplication> ownApplication;
    if (!QCoreApplication::instance()) {
        sPreviousHandler = qInstallMessageHandler(&quietHandler);
        ownApplication = makeApplication();
    }

    QImage image(widthPx, heightPx, QImage::Format_RGB32);
    image.fill(Qt::white);
    {
        QPainter p(&image);
        p.setRenderHint(QPainter::Antialiasing);
        QFont font = p.font();
        font.setPixelSize(std::max(12, heightPx / 50));
        p.setFont(font);
        const int left = widthPx / 9, right = widthPx / 40, bottom = heightPx / 9;
        const int top = map.hasPassivity ? heightPx * 2 / 11 : heightPx * 2 / 13;  // one more legend line
        const QRectF plot(left, top, widthPx - left - right, heightPx - top - bottom);
        const auto px = [&](double x) { return plot.left() + fraction(map.x, x) * plot.width(); };
        const auto py = [&](double y) { return plot.bottom() - fraction(map.y, y) * plot.height(); };

        // Cells: each value is the centre of its cell; cells meet halfway between neighbours.
        std::vector<double> xs, ys;
        for (const auto& c : map.cells) {
            if (std::find(xs.begin(), xs.end(), c.x) == xs.end()) xs.push_back(c.x);
            if (std::find(ys.begin(), ys.end(), c.y) == ys.end()) ys.push_back(c.y);
        }
        std::sort(xs.begin(), xs.end());
        std::sort(ys.begin(), ys.end());
        const auto edges = [](const std::vector<double>& v, const auto& toPx, double lo, double hi) {
            std::vector<double> e;
            for (std::size_t i = 0; i <= v.size(); ++i) {
                if (i == 0) e.push_back(toPx(v.front()) - (v.size() > 1 ? (toPx(v[1]) - toPx(v[0])) / 2 : 0));
                else if (i == v.size()) e.push_back(toPx(v.back()) + (v.size() > 1 ? (toPx(v.back()) - toPx(v[v.size() - 2])) / 2 : 0));
                else e.push_back((toPx(v[i - 1]) + toPx(v[i])) / 2);
            }
            for (double& x : e) x = std::clamp(x, std::min(lo, hi), std::max(lo, hi));
            return e;
        };
        const auto xe = edges(xs, px, plot.left(), plot.right());
        const auto ye = edges(ys, py, plot.bottom(), plot.top());
        const QColor boundedColour(170, 220, 170), divergentColour(240, 165, 155);
        for (const auto& c : map.cells) {
            const auto i = std::size_t(std::find(xs.begin(), xs.end(), c.x) - xs.begin());
            const auto j = std::size_t(std::find(ys.begin(), ys.end(), c.y) - ys.begin());
            const QRectF r(QPointF(xe[i], ye[j + 1]), QPointF(xe[i + 1], ye[j]));
            p.fillRect(r.normalized(), c.bounded ? boundedColour : divergentColour);
        }

        // Passivity: the part of the plane the device cannot render passively, hatched, and its
        // boundary (where K_eq crosses the device's passive stiffness) as a dashed line along the
        // fine grid's cell edges.
        const QColor passivityColour(200, 90, 0);
        if (map.hasPassivity && map.passivity.columns > 1 && map.passivity.rows > 1) {
            const PassivityGrid& g = map.passivity;
            std::vector<double> gx, gy;
            for (int i = 0; i < g.columns; ++i) gx.push_back(axisValue(map.x, i, g.columns));
            for (int j = 0; j < g.rows; ++j) gy.push_back(axisValue(map.y, j, g.rows));
            const auto gxe = edges(gx, px, plot.left(), plot.right());
            const auto gye = edges(gy, py, plot.bottom(), plot.top());
            const auto beyond = [&](int i, int j) { return !(g.ratio[std::size_t(j * g.columns + i)] < 1.0); };
            QPainterPath region;
            for (int j = 0; j < g.rows; ++j)
                for (int i = 0; i < g.columns; ++i)
                    if (beyond(i, j))
                        region.addRect(QRectF(QPointF(gxe[std::size_t(i)], gye[std::size_t(j + 1)]),
                                              QPointF(gxe[std::size_t(i + 1)], gye[std::size_t(j)]))
                                           .normalized());
            p.setPen(Qt::NoPen);
            p.setBrush(QBrush(QColor(passivityColour.red(), passivityColour.green(), passivityColour.blue(), 150),
                              Qt::BDiagPattern));
            p.drawPath(region.simplified());
            p.setBrush(Qt::NoBrush);
            p.setPen(QPen(passivityColour, 2.5, Qt::DashLine));
            for (int j = 0; j < g.rows; ++j)
                for (int i = 0; i < g.columns; ++i) {
                    const auto x0 = gxe[std::size_t(i)], x1 = gxe[std::size_t(i + 1)];
                    const auto y0 = gye[std::size_t(j)], y1 = gye[std::size_t(j + 1)];
                    if (i + 1 < g.columns && beyond(i, j) != beyond(i + 1, j))
                        p.drawLine(QPointF(x1, y0), QPointF(x1, y1));
                    if (j + 1 < g.rows && beyond(i, j) != beyond(i, j + 1))
                        p.drawLine(QPointF(x0, y1), QPointF(x1, y1));
                }
        }

        // Grid and axes.
        p.setPen(QPen(QColor(255, 255, 255, 160), 1));
        for (double v : ticks(map.x)) p.drawLine(QPointF(px(v), plot.top()), QPointF(px(v), plot.bottom()));
        for (double v : ticks(map.y)) p.drawLine(QPointF(plot.left(), py(v)), QPointF(plot.right(), py(v)));
        p.setPen(QPen(Qt::black, 1.5));
        p.drawRect(plot);
        const QFontMetrics fm(p.font());
        for (double v : ticks(map.x)) {
            const QString label = QString::number(v, 'g', 3);
            p.drawLine(QPointF(px(v), plot.bottom()), QPointF(px(v), plot.bottom() + 5));
            p.drawText(QPointF(px(v) - fm.horizontalAdvance(label) / 2.0, plot.bottom() + 6 + fm.ascent()), label);
        }
        for (double v : ticks(map.y)) {
            const QString label = QString::number(v, 'g', 3);
            p.drawLine(QPointF(plot.left() - 5, py(v)), QPointF(plot.left(), py(v)));
            p.drawText(QPointF(plot.left() - 8 - fm.horizontalAdvance(label), py(v) + fm.ascent() / 2.5), label);
        }
        const QString xTitle = axisTitle(map.x);
        p.drawText(QPointF(plot.center().x() - fm.horizontalAdvance(xTitle) / 2.0, heightPx - fm.descent() - 8), xTitle);
        p.save();
        p.translate(fm.height(), plot.center().y());
        p.rotate(-90);
        const QString yTitle = axisTitle(map.y);
        p.drawText(QPointF(-fm.horizontalAdvance(yTitle) / 2.0, fm.ascent() / 2.0), yTitle);
        p.restore();

        // The derived boundary (sampled finely by the runner), clipped to the plot.
        p.setClipRect(plot);
        if (map.hasDerivedBoundary) {
            QPainterPath line;
            bool started = false;
            for (const auto& [x, y] : map.derivedCurve) {
                if (!std::isfinite(y) || y <= 0.0) {
                    started = false;
                    continue;
                }
                const QPointF q(px(x), py(std::clamp(y, map.y.minValue * 1e-3, map.y.maxValue * 1e3)));
                if (!started) line.moveTo(q);
                else line.lineTo(q);
                started = true;
            }
            p.setPen(QPen(Qt::black, 3));
            p.drawPath(line);
        }
        p.setPen(QPen(QColor(20, 60, 200), 2));
        p.setBrush(QColor(20, 60, 200));
        for (const auto& b : map.boundary)
            if (std::isfinite(b.measuredY)) p.drawEllipse(QPointF(px(b.x), py(b.measuredY)), 5, 5);
        p.setClipping(false);

        // Title, what was run, and the legend, each on its own line above the plot.
        QFont titleFont = font;
        titleFont.setBold(true);
        titleFont.setPixelSize(font.pixelSize() * 5 / 4);
        p.setFont(titleFont);
        p.setPen(Qt::black);
        const QString gap = map.hasDerivedBoundary
                                ? QStringLiteral("largest gap measured vs derived: %1 %").arg(100.0 * map.relativeGap, 0, 'f', 2)
                                : QStringLiteral("no boundary: bounded in every cell");
        const double lineHeight = fm.height() * 1.15;
        double ly = QFontMetrics(titleFont).ascent() + 6;
        p.drawText(QPointF(left, ly), QString::fromStdString(map.model) + QStringLiteral(" - ") + gap);
        p.setFont(font);
        ly += lineHeight;
        p.drawText(QPointF(left, ly), fm.elidedText(QString::fromStdString(map.description), Qt::ElideRight,
                                                     int(widthPx - left - right)));
        ly += lineHeight;
        double lx = left;
        const auto swatch = [&](const QColor& c, const QString& text) {
            p.fillRect(QRectF(lx, ly - fm.ascent() + 2, 18, fm.ascent() - 2), c);
            p.drawText(QPointF(lx + 24, ly), text);
            lx += 24 + fm.horizontalAdvance(text) + 24;
        };
        swatch(boundedColour, QStringLiteral("bounded"));
        swatch(divergentColour, QStringLiteral("divergent"));
        p.setBrush(QColor(20, 60, 200));
        p.setPen(QPen(QColor(20, 60, 200), 2));
        p.drawEllipse(QPointF(lx + 6, ly - fm.ascent() / 2.5), 5, 5);
        p.setPen(Qt::black);
        p.drawText(QPointF(lx + 18, ly), QStringLiteral("measured boundary (bisection per column)"));
        ly += lineHeight;
        lx = left;
        p.setPen(QPen(Qt::black, 3));
        p.drawLine(QPointF(lx, ly - fm.ascent() / 2.5), QPointF(lx + 18, ly - fm.ascent() / 2.5));
        p.setPen(Qt::black);
        p.drawText(QPointF(lx + 24, ly),
                   fm.elidedText(QStringLiteral("derived: ") + QString::fromStdString(map.derivedFormula), Qt::ElideRight,
                                 int(widthPx - left - right - 24)));
        if (map.hasPassivity) {
            ly += lineHeight;
            const QRectF swatchRect(lx, ly - fm.ascent() + 2, 18, fm.ascent() - 2);
            p.fillRect(swatchRect, QBrush(passivityColour, Qt::BDiagPattern));
            p.setPen(QPen(passivityColour, 2.5, Qt::DashLine));
            p.setBrush(Qt::NoBrush);
            p.drawRect(swatchRect);
            p.setPen(Qt::black);
            p.drawText(QPointF(lx + 24, ly),
                       fm.elidedText(QStringLiteral("not passive: ") + QString::fromStdString(map.passivityFormula),
                                     Qt::ElideRight, int(widthPx - left - right - 24)));
        }
    }
    QImageWriter writer(QString::fromStdString(path), "png");
    const bool written = writer.write(image);
    if (ownApplication) {
        ownApplication.reset();
        qInstallMessageHandler(sPreviousHandler);
    }
    if (!written) return "cannot be written (" + writer.errorString().toStdString() + ")";
    return {};
}

}  // namespace palpate
