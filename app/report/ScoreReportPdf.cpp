#include "app/report/ScoreReportPdf.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QFont>
#include <QFontMetricsF>
#include <QLocale>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(palpate::ScoreReportPdf)
};

QString number(double v, int decimals) { return QLocale().toString(v, 'f', decimals); }

/// A tick step of 1, 2 or 5 times a power of ten giving about `count` ticks over `range`.
double niceStep(double range, int count) {
    if (!(range > 0.0)) return 1.0;
    const double raw = range / count;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * power) return m * power;
    return 10.0 * power;
}

void drawForcePlot(QPainter& p, const QRectF& area, const ScoreReport& report,
                   const std::vector<std::pair<double, double>>& series) {
    QFont font = p.font();
    const QFontMetricsF fm(font);
    const double lh = fm.height();
    // Room for the tick labels and the axis titles.
    const QRectF plot(area.left() + 5 * lh, area.top() + lh, area.width() - 6 * lh, area.height() - 4 * lh);

    double t0 = series.front().first, t1 = series.front().first, fMax = 0.0;
    for (const auto& [t, f] : series) {
        t0 = std::min(t0, t);
        t1 = std::max(t1, t);
        if (std::isfinite(f)) fMax = std::max(fMax, f);
    }
    const bool window = report.guidance.forceMaxN > report.guidance.forceMinN && report.guidance.forceMaxN > 0.0;
    if (window) fMax = std::max(fMax, report.guidance.forceMaxN);
    if (t1 <= t0) t1 = t0 + 1.0;
    if (fMax <= 0.0) fMax = 1.0;
    fMax *= 1.1;
    auto x = [&](double t) { return plot.left() + (t - t0) / (t1 - t0) * plot.width(); };
    auto y = [&](double f) { return plot.bottom() - f / fMax * plot.height(); };

    if (window) {
        const QRectF band(QPointF(plot.left(), y(report.guidance.forceMaxN)),
                          QPointF(plot.right(), y(report.guidance.forceMinN)));
        p.fillRect(band, QColor(120, 200, 120, 90));
        p.setPen(QColor(40, 120, 40));
        p.drawText(QPointF(plot.right() - fm.horizontalAdvance(Tr::tr("force window")) - lh * 0.3,
                           band.top() - lh * 0.2),
                   Tr::tr("force window"));
    }

    // Axes, ticks and grid.
    p.setPen(QPen(Qt::black, 0));
    p.drawRect(plot);
    const double tStep = niceStep(t1 - t0, 8), fStep = niceStep(fMax, 5);
    const int tDecimals = tStep < 1.0 ? 1 : 0, fDecimals = fStep < 1.0 ? (fStep < 0.1 ? 2 : 1) : 0;
    for (double t = std::ceil(t0 / tStep) * tStep; t <= t1 + 1e-9; t += tStep) {
        p.setPen(QPen(QColor(220, 220, 220), 0));
        p.drawLine(QPointF(x(t), plot.top()), QPointF(x(t), plot.bottom()));
        p.setPen(Qt::black);
        const QString label = number(t, tDecimals);
        p.drawText(QPointF(x(t) - fm.horizontalAdvance(label) / 2, plot.bottom() + lh), label);
    }
    for (double f = 0.0; f <= fMax + 1e-9; f += fStep) {
        p.setPen(QPen(QColor(220, 220, 220), 0));
        p.drawLine(QPointF(plot.left(), y(f)), QPointF(plot.right(), y(f)));
        p.setPen(Qt::black);
        const QString label = number(f, fDecimals);
        p.drawText(QPointF(plot.left() - fm.horizontalAdvance(label) - lh * 0.3, y(f) + fm.ascent() / 3), label);
    }
    const QString tTitle = Tr::tr("Time (s)"), fTitle = Tr::tr("|F| (N)");
    p.drawText(QPointF(plot.center().x() - fm.horizontalAdvance(tTitle) / 2, plot.bottom() + 2.3 * lh), tTitle);
    p.save();
    p.translate(area.left() + lh, plot.center().y() + fm.horizontalAdvance(fTitle) / 2);
    p.rotate(-90);
    p.drawText(QPointF(0, 0), fTitle);
    p.restore();

    QPainterPath curve;
    bool started = false;
    for (const auto& [t, f] : series) {
        if (!std::isfinite(t) || !std::isfinite(f)) continue;
        const QPointF pt(x(t), y(f));
        if (started)
            curve.lineTo(pt);
        else
            curve.moveTo(pt), started = true;
    }
    p.setPen(QPen(QColor(30, 80, 200), lh * 0.12));
    p.setClipRect(plot);
    p.drawPath(curve);
    p.setClipping(false);
}

}  // namespace

bool writeScoreReportPdf(const QString& path, const QString& traineeName, const QString& exerciseName,
                         const ScoreReport& report,
                         const std::vector<std::pair<double, double>>& forceTimeSeries, QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = Tr::tr("%1: %2").arg(QDir::toNativeSeparators(path), why);
        return false;
    };
    const QFileInfo folder(QFileInfo(path).absolutePath());
    if (!folder.isDir())
        return fail(Tr::tr("cannot be written: folder %1 does not exist")
                        .arg(QDir::toNativeSeparators(folder.absoluteFilePath())));

    QPdfWriter writer(path);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    writer.setResolution(300);
    writer.setTitle(Tr::tr("Palpate score report"));
    writer.setCreator(QStringLiteral("Palpate"));
    QPainter p;
    if (!p.begin(&writer)) return fail(Tr::tr("cannot be written (permission denied or disk full)"));

    const QRectF page(QPointF(0, 0), QSizeF(writer.width(), writer.height()));
    QFont body(QStringLiteral("DejaVu Sans"));
    body.setPointSizeF(10);
    QFont title = body, big = body, bold = body;
    title.setPointSizeF(18);
    title.setBold(true);
    big.setPointSizeF(40);
    big.setBold(true);
    bold.setBold(true);

    double yPos = 0;
    auto line = [&](const QFont& font, const QString& text, double x = 0) {
        p.setFont(font);
        const QFontMetricsF fm(font);
        yPos += fm.ascent();
        p.drawText(QPointF(x, yPos), text);
        yPos += fm.descent() + fm.leading() + fm.height() * 0.25;
    };

    p.setPen(Qt::black);
    line(title, Tr::tr("Palpate score report"));
    line(body, Tr::tr("Trainee: %1").arg(traineeName));
    line(body, Tr::tr("Exercise: %1").arg(exerciseName));
    line(body, Tr::tr("Date: %1").arg(QLocale().toString(QDateTime::currentDateTime(), QLocale::LongFormat)));
    QString state = report.guidance.completed ? Tr::tr("completed")
                    : report.guidance.timeUp  ? Tr::tr("time limit reached")
                                              : Tr::tr("not finished");
    line(body, Tr::tr("Result: %1").arg(state));
    yPos += QFontMetricsF(body).height() * 0.5;
    line(big, Tr::tr("Score: %1 / 100").arg(number(report.score, 1)));
    yPos += QFontMetricsF(body).height() * 0.5;

    // The breakdown table.
    const QFontMetricsF fm(body);
    const double rowH = fm.height() * 1.3;
    const double cols[] = {0.0, 0.36, 0.56, 0.72, 0.85};  // fractions of the page width
    auto cell = [&](int c, const QString& text, bool rightAlign) {
        const double left = cols[c] * page.width();
        const double right = (c + 1 < 5 ? cols[c + 1] : 1.0) * page.width() - fm.height() * 0.5;
        const double xText = rightAlign ? right - QFontMetricsF(p.font()).horizontalAdvance(text) : left;
        p.drawText(QPointF(xText, yPos + fm.ascent()), text);
    };
    p.setFont(bold);
    cell(0, Tr::tr("Metric"), false);
    cell(1, Tr::tr("Value"), true);
    cell(2, Tr::tr("Sub-score"), true);
    cell(3, Tr::tr("Weight"), true);
    cell(4, Tr::tr("Contribution"), true);
    yPos += rowH;
    p.drawLine(QPointF(0, yPos - rowH * 0.15), QPointF(page.width(), yPos - rowH * 0.15));
    p.setFont(body);
    for (const MetricResult& m : report.metrics) {
        const QString unit = QString::fromUtf8(metricUnit(m.metric).data(), qsizetype(metricUnit(m.metric).size()));
        const QString value = m.measured ? (number(m.value, 2) + (unit.isEmpty() ? QString() : QStringLiteral(" ") + unit))
                                         : Tr::tr("n/a");
        cell(0, QString::fromUtf8(metricName(m.metric).data(), qsizetype(metricName(m.metric).size())), false);
        cell(1, value, true);
        cell(2, number(m.subScore, 2), true);
        cell(3, number(m.weight, 2), true);
        cell(4, number(m.contribution, 1), true);
        yPos += rowH;
    }
    p.drawLine(QPointF(0, yPos - rowH * 0.15), QPointF(page.width(), yPos - rowH * 0.15));
    for (const std::string& w : report.warnings) {
        yPos += rowH * 0.2;
        line(body, Tr::tr("Warning: %1").arg(QString::fromStdString(w)));
    }
    yPos += rowH;

    // The force-time plot in what is left of the page (at least a third of it).
    if (!forceTimeSeries.empty()) {
        line(bold, Tr::tr("Force over time"));
        const double height = std::max(page.height() - yPos, page.height() / 3);
        if (page.height() - yPos < page.height() / 3) {
            writer.newPage();
            yPos = 0;
        }
        p.setFont(body);
        drawForcePlot(p, QRectF(0, yPos, page.width(), std::min(height, page.height() - yPos)), report,
                      forceTimeSeries);
    }
    if (!p.end()) return fail(Tr::tr("cannot be written"));
    if (QFileInfo(path).size() <= 0) return fail(Tr::tr("cannot be written (empty file)"));
    return true;
}

}  // namespace palpate
