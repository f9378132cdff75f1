#include "report/LearningCurveImage.h"

#include "report/ChartApplication.h"
#include "report/ChartImage.h"
#include "report/MetricText.h"

#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QGridLayout>
#include <QLabel>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>
#include <QVBoxLayout>
#include <QWidget>

#include <algorithm>
#include <cmath>

namespace palpate {

QString learningCurveMetricTitle(const LearningCurveMetric& m) {
    if (m.key == QLatin1String(kLearningCurveScoreKey)) return QObject::tr("Score (of 100)");
    return metricNameText(m.key.toStdString());
}

QChartView* learningCurveMetricChart(const LearningCurveMetric& m, const std::vector<bool>& passed, double textScale,
                                     QWidget* parent) {
    auto* chart = new QChart;
    chart->setTitle(learningCurveMetricTitle(m));
    chart->legend()->hide();
    const int sessions = int(m.values.size());
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& v : m.values)
        if (v) lo = std::min(lo, *v), hi = std::max(hi, *v);
    if (m.passMark) lo = std::min(lo, *m.passMark), hi = std::max(hi, *m.passMark);
    if (!std::isfinite(lo)) lo = 0.0, hi = 1.0;
    const double pad = hi > lo ? 0.1 * (hi - lo) : std::max(0.5, 0.1 * std::abs(hi));
    lo -= pad;
    hi += pad;
    const double x0 = 0.5, x1 = sessions + 0.5;
    auto* x = new QValueAxis;
    x->setRange(x0, x1);
    x->setLabelFormat(QStringLiteral("%d"));
    x->setTickInterval(1.0);
    x->setTickType(QValueAxis::TicksDynamic);
    x->setTickAnchor(1.0);
    x->setTitleText(QObject::tr("session"));
    auto* y = new QValueAxis;
    y->setRange(lo, hi);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    auto attach = [&](QAbstractSeries* s) {
        chart->addSeries(s);
        s->attachAxis(x);
        s->attachAxis(y);
    };
    if (m.passMark) {
        // The passing side of the mark, shaded; the mark as a line.
        auto* upper = new QLineSeries;
        auto* lower = new QLineSeries;
        const double from = *m.passMark, to = m.higherIsBetter ? hi : lo;
        upper->append(x0, std::max(from, to));
        upper->append(x1, std::max(from, to));
        lower->append(x0, std::min(from, to));
        lower->append(x1, std::min(from, to));
        auto* band = new QAreaSeries(upper, lower);
        // An area series does not own its edges: they go with it.
        upper->setParent(band);
        lower->setParent(band);
        band->setColor(QColor(120, 200, 120, 70));
        band->setBorderColor(Qt::transparent);
        attach(band);
        auto* mark = new QLineSeries;
        mark->append(x0, *m.passMark);
        mark->append(x1, *m.passMark);
        QPen pen(QColor(30, 120, 30));
        pen.setWidthF(2.0 * textScale);
        pen.setStyle(Qt::DashLine);
        mark->setPen(pen);
        attach(mark);
    }
    auto* line = new QLineSeries;
    auto* good = new QScatterSeries;
    auto* bad = new QScatterSeries;
    for (auto* s : {good, bad}) s->setMarkerSize(9.0 * textScale);
    good->setColor(QColor(40, 160, 40));
    bad->setColor(QColor(200, 40, 40));
    for (int i = 0; i < sessions; ++i) {
        if (!m.values[std::size_t(i)]) continue;
        const double v = *m.values[std::size_t(i)];
        line->append(i + 1, v);
        const bool ok = std::size_t(i) < passed.size() && passed[std::size_t(i)];
        (ok ? good : bad)->append(i + 1, v);
    }
    QPen pen(QColor(40, 70, 160));
    pen.setWidthF(1.5 * textScale);
    line->setPen(pen);
    attach(line);
    attach(good);
    attach(bad);
    QFont base;
    base.setPointSizeF(8.0);
    applyChartFonts(*chart, base, textScale);
    auto* view = new QChartView(chart, parent);
    view->setRenderHint(QPainter::Antialiasing);
    return view;
}

std::string renderLearningCurvePng(const LearningCurveData& data, const std::string& path, int widthPx, int heightPx) {
    if (const std::string problem = chartImageProblem(widthPx, heightPx, path); !problem.empty()) return problem;
    if (data.metrics.empty()) return "no metric to draw";
    const ChartApplication application;
    if (!application.problem().empty()) return application.problem();
    const double textScale = std::clamp(widthPx / 1200.0, 1.0, 3.0);
    QWidget page;
    auto* layout = new QVBoxLayout(&page);
    QString heading = data.title;
    if (data.proficientAtSession)
        heading += QObject::tr(" - proficient at session %1").arg(*data.proficientAtSession);
    else if (!data.passed.empty())
        heading += QObject::tr(" - not yet proficient");
    else
        heading += QObject::tr(" - no expert standard");
    auto* title = new QLabel(heading, &page);
    QFont f = title->font();
    f.setPointSizeF(12.0 * textScale);
    title->setFont(f);
    title->setAlignment(Qt::AlignCenter);
    layout->addWidget(title);
    auto* grid = new QGridLayout;
    const int n = int(data.metrics.size());
    const int columns = n <= 1 ? 1 : n <= 4 ? 2 : 3;
    for (int i = 0; i < n; ++i)
        grid->addWidget(learningCurveMetricChart(data.metrics[std::size_t(i)], data.passed, textScale, &page),
                        i / columns, i % columns);
    layout->addLayout(grid, 1);
    if (const std::string problem = renderWidgetPng(page, widthPx, heightPx, path); !problem.empty()) return problem;
    return {};
}

}  // namespace palpate
