#include "report/FeelChart.h"

#include "report/ChartImage.h"

#include "report/SpeedAccuracyChart.h"

#include <QChart>
#include <QCursor>
#include <QEvent>
#include <QFont>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QLogValueAxis>
#include <QPen>
#include <QScatterSeries>
#include <QToolTip>

#include <algorithm>
#include <cmath>
#include <map>

namespace palpate {

namespace {

constexpr qreal kMarkerSize = 11.0;
constexpr int kNarrowBelowPx = 720;
constexpr double kFloorPct = 1e-3;  ///< a step of 0 (a perfectly steady force) is drawn here: log axis
const QColor kGoalColor(0xc6, 0x28, 0x28);

/// Legend order: the slope-ring methods (ours first, then the paper's), then the others in the
/// registry's order.
int modelRank(const std::string& model) {
    const std::vector<std::string> names = modelNames();
    static const char* const kFirst[] = {"coherent", "proposed", "hybrid", "previous"};
    for (int i = 0; i < 4; ++i)
        if (model == kFirst[i]) return i;
    const auto it = std::find(names.begin(), names.end(), model);
    return it == names.end() ? 1000 : 10 + int(it - names.begin());
}

double stepOf(const FeelRow& r) { return std::max(r.metrics.maxStepPct, kFloorPct); }

bool drawable(const FeelRow& r) {
    return std::isfinite(r.metrics.maxStepPct) && std::isfinite(r.tickNs) && r.tickNs > 0.0;
}

}  // namespace

FeelChart::FeelChart(QWidget* parent) : QChartView(parent) {
    setObjectName(QStringLiteral("feelChart"));
    setRenderHint(QPainter::Antialiasing);
    chart()->setAnimationOptions(QChart::NoAnimation);
    chart()->legend()->setAlignment(Qt::AlignRight);
    chart()->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
    chart()->setBackgroundBrush(Qt::white);
    chart()->setBackgroundRoundness(0.0);
    chart()->setMargins(QMargins(6, 6, 6, 6));
    mEmptyHint = tr("No feel bench yet");
    rebuild();
}

FeelChart::~FeelChart() = default;

void FeelChart::setRows(std::vector<FeelRow> rows) {
    mRows = std::move(rows);
    rebuild();
}

void FeelChart::setXAxis(XAxis axis) {
    if (axis == mXAxis) return;
    mXAxis = axis;
    rebuild();
}

void FeelChart::setEmptyHint(const QString& hint) {
    mEmptyHint = hint;
    chart()->setTitle(titleText());
}

void FeelChart::setLegendShown(bool shown) {
    mLegendShown = shown;
    chart()->legend()->setVisible(shown && mPointCount > 0);
}

void FeelChart::setTextScale(double scale) {
    mTextScale = std::clamp(scale, 0.5, 4.0);
    rebuild();
}

QColor FeelChart::modelColor(const std::string& model) {
    if (model == "coherent") return QColor(0x21, 0x21, 0x21);  // ours, in black: no other model uses it
    return SpeedAccuracyChart::seriesColor(model);
}

double FeelChart::xOf(const FeelRow& row) const {
    if (mXAxis == XAxis::TickMicroseconds) return row.tickNs / 1000.0;
    return row.previousTickNs > 0.0 ? row.tickNs / row.previousTickNs : 0.0;
}

void FeelChart::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) rebuild();
    QChartView::changeEvent(event);
}

void FeelChart::applyFonts() { applyChartFonts(*chart(), font(), mTextScale); }

bool FeelChart::narrow() const { return width() < kNarrowBelowPx; }

void FeelChart::resizeEvent(QResizeEvent* event) {
    QChartView::resizeEvent(event);
    applyWidth();
}

void FeelChart::applyWidth() {
    const bool small = narrow();
    chart()->setTitle(titleText());
    for (QAbstractAxis* axis : chart()->axes()) {
        auto* log = qobject_cast<QLogValueAxis*>(axis);
        if (log) log->setMinorTickCount(small ? 0 : 8);
        if (axis->objectName() == QLatin1String("feelTickAxis")) {
            if (mXAxis == XAxis::RatioToPrevious)
                axis->setTitleText(small ? tr("Tick cost (× previous, log)")
                                         : tr("Tick cost (× the paper's previous method, log scale)"));
            else axis->setTitleText(small ? tr("Tick cost (µs, log)") : tr("Tick cost (µs, log scale)"));
        } else {
            axis->setTitleText(small ? tr("Largest step (% of mean force)")
                                     : tr("Largest force step (% of the mean force, log scale)"));
        }
    }
}

QString FeelChart::titleText() const {
    if (mRows.empty()) return mEmptyHint;
    const FeelRow& first = mRows.front();
    const QString depth = QLocale().toString(first.depthMm, 'g', 3),
                  speed = QLocale().toString(first.speedMmPerS, 'g', 3),
                  goal = QLocale().toString(kFeelStepGoalPct, 'g', 3);
    const QString title = narrow() ? tr("Feel: force step against tick cost")
                                   : tr("What the hand feels: force step against tick cost");
    const QString detail =
        narrow() ? tr("slide %1 mm deep at %2 mm/s; goal: step ≤ %3 % (dashed)").arg(depth, speed, goal)
                 : tr("a slide at %1 mm depth, %2 mm/s (circles: sphere, squares: stomach); goal: step ≤ %3 % of "
                      "the mean force (dashed)")
                       .arg(depth, speed, goal);
    return QStringLiteral("<b>%1</b><br><span style=\"font-size:small; font-weight:normal\">%2</span>")
        .arg(title.toHtmlEscaped(), detail.toHtmlEscaped());
}

QStringList FeelChart::seriesNames() const {
    QStringList names;
    for (QAbstractSeries* s : chart()->series())
        if (s->property("modelSeries").toBool() && !names.contains(s->name())) names << s->name();
    return names;
}

QString FeelChart::legendHtml() const {
    auto mark = [](const QColor& color, const QString& marker, const QString& text) {
        return QStringLiteral("<span style=\"color:%1\">%2</span>&nbsp;%3")
            .arg(color.name(), marker, text.toHtmlEscaped().replace(QLatin1Char(' '), QStringLiteral("&nbsp;")));
    };
    QStringList items;
    for (const QString& name : seriesNames()) items << mark(modelColor(name.toStdString()), QStringLiteral("●"), name);
    if (mPointCount > 0) {
        items << mark(QColor(0x42, 0x42, 0x42), QStringLiteral("●"), tr("sphere")) + QStringLiteral("&nbsp;") +
                     mark(QColor(0x42, 0x42, 0x42), QStringLiteral("■"), tr("stomach"));
        items << mark(kGoalColor, QStringLiteral("- -"), tr("goal"));
    }
    return items.join(QStringLiteral(" &nbsp; "));
}

void FeelChart::rebuild() {
    QChart* c = chart();
    c->removeAllSeries();
    for (QAbstractAxis* axis : c->axes()) {
        c->removeAxis(axis);
        delete axis;
    }
    mPointCount = 0;
    mAboveGoal = 0;

    double xLo = 0.0, xHi = 0.0, yLo = kFeelStepGoalPct, yHi = kFeelStepGoalPct;
    bool any = false;
    for (const FeelRow& r : mRows) {
        if (!drawable(r) || !(xOf(r) > 0.0)) continue;
        xLo = any ? std::min(xLo, xOf(r)) : xOf(r);
        xHi = any ? std::max(xHi, xOf(r)) : xOf(r);
        yLo = std::min(yLo, stepOf(r));
        yHi = std::max(yHi, stepOf(r));
        any = true;
    }
    auto* x = new QLogValueAxis;
    x->setObjectName(QStringLiteral("feelTickAxis"));
    x->setBase(10.0);
    x->setLabelFormat(QStringLiteral("%g"));
    x->setMinorTickCount(8);
    // Whole decades, a hair wider so that both end labels are drawn: a log axis labels only its decades.
    const double xMin = 0.999 * (any ? std::pow(10.0, std::floor(std::log10(xLo * 0.8))) : 1e-4),
                 xMax = 1.001 * (any ? std::pow(10.0, std::ceil(std::log10(xHi * 1.25))) : 10.0);
    x->setRange(xMin, xMax);
    auto* y = new QLogValueAxis;
    y->setObjectName(QStringLiteral("feelStepAxis"));
    y->setBase(10.0);
    y->setLabelFormat(QStringLiteral("%g"));
    y->setMinorTickCount(8);
    // The same for the steps, with the goal's decade inside.
    y->setRange(0.999 * std::pow(10.0, std::floor(std::log10(std::min(yLo * 0.8, kFeelStepGoalPct * 0.5)))),
                1.001 * std::pow(10.0, std::ceil(std::log10(std::max(yHi * 1.25, kFeelStepGoalPct * 2.0)))));
    c->addAxis(x, Qt::AlignBottom);
    c->addAxis(y, Qt::AlignLeft);
    c->setTitle(titleText());
    applyFonts();

    auto attach = [&](QAbstractSeries* s) {
        c->addSeries(s);
        s->attachAxis(x);
        s->attachAxis(y);
    };
    auto hideFromLegend = [&](QAbstractSeries* s) {
        for (QLegendMarker* marker : c->legend()->markers(s)) marker->setVisible(false);
    };

    // The goal first, under the points.
    auto* goal = new QLineSeries;
    goal->setObjectName(QStringLiteral("stepGoal"));
    goal->setName(tr("goal: step ≤ %1 %").arg(QLocale().toString(kFeelStepGoalPct, 'g', 3)));
    goal->setPen(QPen(kGoalColor, 2.0, Qt::DashLine));
    goal->append(xMin, kFeelStepGoalPct);
    goal->append(xMax, kFeelStepGoalPct);
    attach(goal);

    // The drawable rows by (model, shape), each in order of resolution.
    std::map<std::pair<std::pair<int, std::string>, int>, std::vector<const FeelRow*>> groups;
    for (const FeelRow& r : mRows)
        if (drawable(r) && xOf(r) > 0.0) groups[{{modelRank(r.model), r.model}, int(r.shape)}].push_back(&r);
    auto tip = [this](const FeelRow& r) {
        return tr("%1, %2 %3 vertices\nlargest step %4 % (normal %5 %), ripple %6 %\ntick %7 µs, %8x faster than previous")
            .arg(QString::fromStdString(r.model), SpeedAccuracyChart::shapeTitle(r.shape).toLower())
            .arg(r.vertices)
            .arg(QLocale().toString(r.metrics.maxStepPct, 'g', 3),
                 QLocale().toString(r.metrics.maxNormalStepPct, 'g', 3),
                 QLocale().toString(r.metrics.ripplePct, 'g', 3), QLocale().toString(r.tickNs / 1000.0, 'g', 3),
                 QLocale().toString(r.speedupVsPrevious(), 'g', 4));
    };
    for (auto& [key, rows] : groups) {
        std::stable_sort(rows.begin(), rows.end(),
                         [](const FeelRow* a, const FeelRow* b) { return a->vertices < b->vertices; });
        if (rows.size() < 2) continue;
        auto* line = new QLineSeries;
        line->setPen(QPen(modelColor(key.first.second), 1.4));
        for (const FeelRow* r : rows) line->append(xOf(*r), stepOf(*r));
        attach(line);
        hideFromLegend(line);
    }
    std::vector<std::string> named;  // one legend entry per model
    for (auto& [key, rows] : groups) {
        const std::string& model = key.first.second;
        auto* scatter = new QScatterSeries;
        scatter->setName(QString::fromStdString(model));
        scatter->setProperty("modelSeries", true);
        const bool stomach = GeneratedShape(key.second) == GeneratedShape::Stomach;
        scatter->setMarkerShape(stomach ? QScatterSeries::MarkerShapeRectangle : QScatterSeries::MarkerShapeCircle);
        scatter->setMarkerSize(kMarkerSize);
        const QColor color = modelColor(model);
        scatter->setColor(color);
        scatter->setBorderColor(color.darker(150));
        std::vector<FeelRow> copies;
        for (const FeelRow* r : rows) {
            scatter->append(xOf(*r), stepOf(*r));
            copies.push_back(*r);
            ++mPointCount;
            if (r->metrics.maxStepPct > kFeelStepGoalPct) ++mAboveGoal;
        }
        attach(scatter);
        if (std::find(named.begin(), named.end(), model) != named.end()) hideFromLegend(scatter);
        else named.push_back(model);
        connect(scatter, &QScatterSeries::hovered, this, [this, copies, tip](const QPointF& where, bool state) {
            if (!state) {
                QToolTip::hideText();
                return;
            }
            const auto distance = [&](const FeelRow& r) {
                return std::abs(std::log(xOf(r) / where.x())) + std::abs(std::log(stepOf(r) / where.y()));
            };
            const auto nearest = std::min_element(copies.begin(), copies.end(),
                                                  [&](const FeelRow& a, const FeelRow& b) {
                                                      return distance(a) < distance(b);
                                                  });
            if (nearest != copies.end()) QToolTip::showText(QCursor::pos(), tip(*nearest));
        });
    }
    c->legend()->setVisible(mLegendShown && mPointCount > 0);
    applyWidth();
    emit rebuilt();
}

}  // namespace palpate
