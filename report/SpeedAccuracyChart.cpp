#include "report/SpeedAccuracyChart.h"

#include "report/ChartImage.h"

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
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <map>

namespace palpate {

namespace {

constexpr qreal kMarkerSize = 10.0;
constexpr int kLegendRightMinWidthPx = 720;
constexpr qreal kParetoRingSize = 17.0;
constexpr qreal kHighlightRingSize = 26.0;
const QColor kParetoColor(0x21, 0x21, 0x21);
const QColor kHighlightColor(0xe4, 0x00, 0x7c);  // magenta: no series uses it

/// The other models (engine/models), in legend order, with their colours.
struct OtherModelStyle {
    const char* name;
    QRgb color;
};
constexpr OtherModelStyle kOtherModels[] = {
    {"mass-spring-local", 0x1f77b4},    {"mass-spring-symplectic", 0x17becf}, {"mass-spring-rk4", 0x9467bd},
    {"mass-spring-implicit", 0xe377c2}, {"radius-of-influence", 0xbcbd22},    {"ffd", 0x7f7f7f},
    {"volumetric-rings", 0x2ca02c},
};

/// Legend order: slope-ring by ring count, then the paper's methods (proposed, hybrid, previous),
/// then the other models (200 and up).
int seriesRank(const SweepPoint& p) {
    if (p.model == "coherent") return p.rings;
    if (p.model == "proposed") return 100;
    if (p.model == "hybrid") return 101;
    if (p.model == "previous") return 102;
    for (int i = 0; i < int(std::size(kOtherModels)); ++i)
        if (p.model == kOtherModels[i].name) return 200 + i;
    return 300;
}

/// The largest of 1, 2, 5 x 10^k at or below `v` (round = false) or the smallest at or above it.
double niceLogBound(double v, bool up) {
    const double decade = std::pow(10.0, std::floor(std::log10(v)));
    const double steps[] = {1.0, 2.0, 5.0, 10.0};
    if (up) {
        for (double s : steps)
            if (s * decade >= v * (1.0 - 1e-9)) return s * decade;
        return 10.0 * decade;
    }
    double best = decade;
    for (double s : steps)
        if (s * decade <= v * (1.0 + 1e-9)) best = s * decade;
    return best;
}

/// "E = 4.34 kPa": enough digits for a preset's value, no trailing zeros.
QString compact(double value) { return QLocale().toString(value, 'g', 4); }

}  // namespace

SpeedAccuracyChart::SpeedAccuracyChart(QWidget* parent) : QChartView(parent) {
    setObjectName(QStringLiteral("speedAccuracyChart"));
    setRenderHint(QPainter::Antialiasing);
    chart()->setAnimationOptions(QChart::NoAnimation);
    chart()->legend()->setAlignment(Qt::AlignRight);
    chart()->legend()->setShowToolTips(true);
    chart()->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
    chart()->setBackgroundBrush(Qt::white);
    chart()->setBackgroundRoundness(0.0);
    chart()->setMargins(QMargins(6, 6, 6, 6));  // a dock is narrow: the plot gets the pixels
    mEmptyHint = tr("No sweep yet");
    rebuild();
}

SpeedAccuracyChart::~SpeedAccuracyChart() = default;

void SpeedAccuracyChart::setPoints(std::vector<SweepPoint> points) {
    mPoints = std::move(points);
    rebuild();
}

void SpeedAccuracyChart::setToolContact(const std::optional<ToolContact>& contact) {
    mContact = contact;
    chart()->setTitle(titleText());
}

void SpeedAccuracyChart::setShape(std::optional<GeneratedShape> shape) {
    mShape = shape;
    rebuild();
}

std::vector<GeneratedShape> SpeedAccuracyChart::shapesPresent() const {
    std::vector<GeneratedShape> shapes;
    for (const SweepPoint& p : mPoints)
        if (std::find(shapes.begin(), shapes.end(), p.shape) == shapes.end()) shapes.push_back(p.shape);
    return shapes;
}

std::vector<std::string> SpeedAccuracyChart::sitesPresent(GeneratedShape shape) const {
    std::vector<std::string> sites;
    for (const SweepPoint& p : mPoints)
        if (p.shape == shape && std::find(sites.begin(), sites.end(), p.site) == sites.end()) sites.push_back(p.site);
    return sites;
}

void SpeedAccuracyChart::setSite(const std::string& site) {
    mSite = site;
    rebuild();
}

std::string SpeedAccuracyChart::shownSite() const {
    const auto present = sitesPresent(shownShape());
    if (std::find(present.begin(), present.end(), mSite) != present.end()) return mSite;
    return present.empty() ? std::string() : present.front();
}

GeneratedShape SpeedAccuracyChart::shownShape() const {
    const auto present = shapesPresent();
    if (mShape && (present.empty() || std::find(present.begin(), present.end(), *mShape) != present.end()))
        return *mShape;
    return present.empty() ? GeneratedShape::Sphere : present.front();
}

void SpeedAccuracyChart::setHighlight(const std::string& series, std::size_t vertices) {
    if (series == mHighlightSeries && vertices == mHighlightVertices) return;
    mHighlightSeries = series;
    mHighlightVertices = vertices;
    rebuild();
}

void SpeedAccuracyChart::setEmptyHint(const QString& hint) {
    mEmptyHint = hint;
    chart()->setTitle(titleText());
}

void SpeedAccuracyChart::setLegendShown(bool shown) {
    mLegendShown = shown;
    chart()->legend()->setVisible(shown);
}

void SpeedAccuracyChart::setTextScale(double scale) {
    mTextScale = std::clamp(scale, 0.5, 4.0);
    rebuild();
}

void SpeedAccuracyChart::applyFonts() { applyChartFonts(*chart(), font(), mTextScale); }

QStringList SpeedAccuracyChart::seriesNames() const {
    QStringList names;
    for (QAbstractSeries* s : chart()->series())
        if (s->property("modelSeries").toBool()) names << s->name();
    return names;
}

QString SpeedAccuracyChart::legendHtml() const {
    // Compact: "slope-ring, rings: ● 1 ● 2 …  paper: ◆ proposed …  ◯ Pareto front  ◯ in use"; items
    // never break inside, groups wrap as the dock narrows.
    auto mark = [](const QColor& color, const QString& marker, const QString& text) {
        return QStringLiteral("<span style=\"color:%1\">%2</span>&nbsp;%3")
            .arg(color.name(), marker, text.toHtmlEscaped().replace(QLatin1Char(' '), QStringLiteral("&nbsp;")));
    };
    QStringList rings, paper, others;
    for (QAbstractSeries* s : chart()->series()) {
        if (!s->property("modelSeries").toBool()) continue;
        const QString name = s->name();
        const QColor color = seriesColor(name.toStdString());
        if (name.startsWith(QLatin1String("slope-ring ")) && name.endsWith(QLatin1String("(stiffening)")))
            rings << mark(color, QStringLiteral("●"), tr("%1 stiffening").arg(name.mid(11).section(QLatin1Char(' '), 0, 0)));
        else if (name.startsWith(QLatin1String("slope-ring ")))
            rings << mark(color, QStringLiteral("●"), name.mid(11).section(QLatin1Char(' '), 0, 0));
        else if (name.endsWith(QLatin1String(" (paper)")))
            paper << mark(color, QStringLiteral("◆"), name.chopped(8));
        else
            others << mark(color, QStringLiteral("▲"), name);
    }
    QStringList groups;
    if (!rings.isEmpty()) groups << tr("Slope&#8209;ring, rings:") + QStringLiteral("&nbsp;") + rings.join(QLatin1Char(' '));
    if (!paper.isEmpty())
        groups << tr("Paper (2 rings):").replace(QLatin1Char(' '), QStringLiteral("&nbsp;")) + QStringLiteral("&nbsp;") +
                      paper.join(QLatin1Char(' '));
    if (!others.isEmpty())
        groups << tr("Other models:").replace(QLatin1Char(' '), QStringLiteral("&nbsp;")) + QStringLiteral("&nbsp;") +
                      others.join(QLatin1Char(' '));
    if (mParetoMarks > 0) groups << mark(kParetoColor, QStringLiteral("◯"), tr("Pareto front (dashed)"));
    if (mHighlightMarks > 0) groups << mark(kHighlightColor, QStringLiteral("◯"), tr("in use"));
    return groups.join(QStringLiteral(" &nbsp;&nbsp; "));
}

int SpeedAccuracyChart::paretoMarkCount() const { return mParetoMarks; }
int SpeedAccuracyChart::highlightMarkCount() const { return mHighlightMarks; }

QColor SpeedAccuracyChart::seriesColor(const std::string& series) {
    // Viridis sampled at 8 steps, light (1 ring) to dark (8 rings), skipping its palest yellow.
    static const QColor kRings[] = {QColor(0xb5, 0xde, 0x2b), QColor(0x6e, 0xce, 0x58), QColor(0x35, 0xb7, 0x79),
                                    QColor(0x1f, 0x9e, 0x89), QColor(0x26, 0x82, 0x8e), QColor(0x31, 0x68, 0x8e),
                                    QColor(0x3e, 0x49, 0x89), QColor(0x48, 0x28, 0x78)};
    // The slope-ring model with stiffening knots (the organ sweep): near-black, apart from the scale.
    if (series.rfind("slope-ring ", 0) == 0 && series.find("(stiffening)") != std::string::npos) return QColor(0x20, 0x20, 0x20);
    if (series.rfind("slope-ring ", 0) == 0) {
        const int rings = std::atoi(series.c_str() + 11);
        return kRings[std::clamp(rings, 1, 8) - 1];
    }
    if (series.rfind("proposed", 0) == 0) return QColor(0xd6, 0x27, 0x28);  // red
    if (series.rfind("hybrid", 0) == 0) return QColor(0xff, 0x7f, 0x0e);    // orange
    if (series.rfind("previous", 0) == 0) return QColor(0x8c, 0x56, 0x4b);  // brown
    for (const OtherModelStyle& other : kOtherModels)
        if (series == other.name) return QColor(other.color);
    return QColor(0x7f, 0x7f, 0x7f);
}

QString SpeedAccuracyChart::shapeTitle(GeneratedShape shape) {
    return shape == GeneratedShape::Sphere ? tr("Sphere") : tr("Stomach");
}

void SpeedAccuracyChart::resizeEvent(QResizeEvent* event) {
    QChartView::resizeEvent(event);
    applyLegendLabels();
}

void SpeedAccuracyChart::applyLegendLabels() {
    // Narrow (a dock): short legend labels ("3 rings", "proposed") and axis title, so that the
    // legend leaves the log axis its width; the series keep their full names (tooltips, tests).
    const bool narrow = width() < kLegendRightMinWidthPx;
    for (QLegendMarker* marker : chart()->legend()->markers()) {
        const QString full = marker->series()->name();
        QString shortName = full;
        if (full.startsWith(QLatin1String("slope-ring "))) shortName = full.mid(11);
        else if (full.endsWith(QLatin1String(" (paper)"))) shortName = full.chopped(8);
        else if (marker->series()->objectName() == QLatin1String("paretoFront")) shortName = tr("Pareto");
        else if (marker->series()->objectName() == QLatin1String("highlightMarks")) shortName = tr("in use");
        marker->setLabel(narrow ? shortName : full);
    }
    for (QAbstractAxis* axis : chart()->axes(Qt::Horizontal)) {
        axis->setTitleText(narrow ? tr("Tick cost (µs, log)") : tr("Haptic tick cost (µs, log scale)"));
        // Minor lines at 2..9 of each decade help a wide plot and clutter a narrow one.
        if (auto* log = qobject_cast<QLogValueAxis*>(axis)) log->setMinorTickCount(narrow ? 0 : 8);
    }
}

void SpeedAccuracyChart::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) rebuild();
    QChartView::changeEvent(event);
}

QString SpeedAccuracyChart::titleText() const {
    if (mPoints.empty()) return mEmptyHint;
    // Rich text: the shape in bold, then the tissue and what the error is measured against, smaller
    // and on lines short enough for a dock.
    const std::string site = shownSite();
    QStringList lines = site.empty() ? QStringList{tr("error vs. the flat punch: RMS / peak over r ≤ 5a")}
                                     : QStringList{tr("error vs. the filled organ's linear FEM at its %1 site:")
                                                       .arg(QString::fromStdString(site)),
                                                   tr("RMS / peak over r ≤ 5a")};
    if (mContact)
        lines.prepend(tr("E = %1 kPa, ν = %2, tool radius a = %3 mm")
                          .arg(compact(mContact->material.youngsModulusNPerMm2 * 1000.0),
                               compact(mContact->material.poissonRatio), compact(mContact->toolRadiusMm)));
    for (QString& line : lines) line = line.toHtmlEscaped();
    return QStringLiteral("<b>%1</b><br><span style=\"font-size:small; font-weight:normal\">%2</span>")
        .arg(tr("%1: speed against accuracy").arg(shapeTitle(shownShape()) +
                                                       (site.empty() ? QString() : QStringLiteral(" (%1)").arg(QString::fromStdString(site))))
                 .toHtmlEscaped(),
             lines.join(QStringLiteral("<br>")));
}

void SpeedAccuracyChart::rebuild() {
    QChart* c = chart();
    c->removeAllSeries();
    mParetoMarks = 0;
    mHighlightMarks = 0;

    // Axes span every shape's points, so that switching shapes (or the PNG's two charts side by
    // side) compares like with like.
    double tickLo = 0.0, tickHi = 0.0, errorHi = 0.0;
    bool any = false;
    for (const SweepPoint& p : mPoints) {
        if (!(p.tickUs > 0.0) || !std::isfinite(p.error.displacementError)) continue;
        tickLo = any ? std::min(tickLo, p.tickUs) : p.tickUs;
        tickHi = any ? std::max(tickHi, p.tickUs) : p.tickUs;
        errorHi = std::max(errorHi, p.error.displacementError * 100.0);
        any = true;
    }
    // The two axes are made once and kept: axes removed and made anew while the chart is hidden
    // (a dock's tab behind another) leave their old labels painted in Qt Charts 6.4.
    if (c->axes().isEmpty()) {
        auto* tick = new QLogValueAxis;
        tick->setObjectName(QStringLiteral("tickAxis"));
        tick->setBase(10.0);
        tick->setLabelFormat(QStringLiteral("%g"));
        c->addAxis(tick, Qt::AlignBottom);
        auto* error = new QValueAxis;
        error->setObjectName(QStringLiteral("errorAxis"));
        error->setLabelFormat(QStringLiteral("%.0f"));
        c->addAxis(error, Qt::AlignLeft);
    }
    auto* x = qobject_cast<QLogValueAxis*>(c->axes(Qt::Horizontal).front());
    auto* y = qobject_cast<QValueAxis*>(c->axes(Qt::Vertical).front());
    x->setMinorTickCount(8);
    x->setTitleText(tr("Haptic tick cost (µs, log scale)"));
    // Bounds at 1, 2, 5 x 10^k: a whole decade either side would squeeze the points together.
    x->setRange(any ? niceLogBound(tickLo * 0.9, false) : 0.1, any ? niceLogBound(tickHi * 1.1, true) : 100.0);
    y->setTitleText(tr("Displacement error (%)"));
    y->setRange(0.0, any ? std::max(errorHi * 1.08, 1.0) : 100.0);
    y->applyNiceNumbers();
    y->setMinorTickCount(1);
    c->setTitle(titleText());
    c->legend()->setVisible(mLegendShown && any);
    applyFonts();

    const GeneratedShape shape = shownShape();
    const std::string site = shownSite();
    // The shown shape's (and site's) points by series, each series in order of resolution.
    std::map<std::pair<int, std::string>, std::vector<const SweepPoint*>> bySeries;
    std::vector<const SweepPoint*> pareto;
    std::vector<const SweepPoint*> highlighted;
    for (const SweepPoint& p : mPoints) {
        if (p.shape != shape || p.site != site || !(p.tickUs > 0.0) || !std::isfinite(p.error.displacementError)) continue;
        bySeries[{seriesRank(p), p.series}].push_back(&p);
        if (p.pareto) pareto.push_back(&p);
        if (!mHighlightSeries.empty() && p.series == mHighlightSeries && p.vertices == mHighlightVertices)
            highlighted.push_back(&p);
    }
    auto at = [](const SweepPoint* p) { return QPointF(p->tickUs, p->error.displacementError * 100.0); };
    auto attach = [&](QAbstractSeries* s) {
        c->addSeries(s);
        s->attachAxis(x);
        s->attachAxis(y);
    };
    auto hideFromLegend = [&](QAbstractSeries* s) {
        for (QLegendMarker* marker : c->legend()->markers(s)) marker->setVisible(false);
    };
    auto tip = [](const SweepPoint& p) {
        return tr("%1, %2 %3 vertices\ntick %4 µs, displacement error %5 %, force error %6 %%7")
            .arg(QString::fromStdString(p.series), shapeTitle(p.shape).toLower())
            .arg(p.vertices)
            .arg(QLocale().toString(p.tickUs, 'g', 3), QLocale().toString(p.error.displacementError * 100.0, 'f', 1),
                 QLocale().toString(p.error.forceError * 100.0, 'f', 1),
                 p.pareto ? QLatin1Char('\n') + tr("on the Pareto front") : QString());
    };

    // Lines first (under the markers), then the markers, the Pareto rings and the highlight.
    for (auto& [key, points] : bySeries) {
        std::stable_sort(points.begin(), points.end(),
                         [](const SweepPoint* a, const SweepPoint* b) { return a->vertices < b->vertices; });
        if (points.size() < 2) continue;
        auto* line = new QLineSeries;
        line->setPen(QPen(seriesColor(key.second), 1.6));
        for (const SweepPoint* p : points) line->append(at(p));
        attach(line);
        hideFromLegend(line);
    }
    for (const auto& [key, points] : bySeries) {
        auto* scatter = new QScatterSeries;
        scatter->setName(QString::fromStdString(key.second));
        scatter->setProperty("modelSeries", true);
        const bool paper = key.first >= 100 && key.first < 200;
        const bool other = key.first >= 200;
        scatter->setMarkerShape(paper   ? QScatterSeries::MarkerShapeRotatedRectangle
                                : other ? QScatterSeries::MarkerShapeTriangle
                                        : QScatterSeries::MarkerShapeCircle);
        scatter->setMarkerSize(paper || other ? kMarkerSize + 3.0 : kMarkerSize);
        const QColor color = seriesColor(key.second);
        scatter->setColor(color);
        scatter->setBorderColor(color.darker(140));
        for (const SweepPoint* p : points) scatter->append(at(p));
        attach(scatter);
        std::vector<SweepPoint> copies;
        for (const SweepPoint* p : points) copies.push_back(*p);
        connect(scatter, &QScatterSeries::hovered, this, [copies, tip](const QPointF& where, bool state) {
            if (!state) {
                QToolTip::hideText();
                return;
            }
            const auto nearest = std::min_element(copies.begin(), copies.end(), [&](const SweepPoint& a, const SweepPoint& b) {
                return std::abs(std::log(a.tickUs / where.x())) + std::abs(a.error.displacementError * 100.0 - where.y()) <
                       std::abs(std::log(b.tickUs / where.x())) + std::abs(b.error.displacementError * 100.0 - where.y());
            });
            if (nearest != copies.end()) QToolTip::showText(QCursor::pos(), tip(*nearest));
        });
    }
    if (!pareto.empty()) {
        std::sort(pareto.begin(), pareto.end(), [](const SweepPoint* a, const SweepPoint* b) {
            return a->tickUs < b->tickUs || (a->tickUs == b->tickUs && a->error.displacementError > b->error.displacementError);
        });
        auto* front = new QLineSeries;
        front->setName(tr("Pareto front"));
        front->setObjectName(QStringLiteral("paretoFront"));
        QPen pen(kParetoColor, 1.6, Qt::DashLine);
        front->setPen(pen);
        for (const SweepPoint* p : pareto) front->append(at(p));
        attach(front);
        auto* rings = new QScatterSeries;
        rings->setObjectName(QStringLiteral("paretoMarks"));
        rings->setMarkerShape(QScatterSeries::MarkerShapeCircle);
        rings->setMarkerSize(kParetoRingSize);
        rings->setBrush(Qt::NoBrush);
        rings->setPen(QPen(kParetoColor, 1.5));
        for (const SweepPoint* p : pareto) rings->append(at(p));
        attach(rings);
        hideFromLegend(rings);
        mParetoMarks = int(pareto.size());
    }
    if (!highlighted.empty()) {
        auto* mark = new QScatterSeries;
        mark->setObjectName(QStringLiteral("highlightMarks"));
        mark->setName(tr("current configuration"));
        mark->setMarkerShape(QScatterSeries::MarkerShapeCircle);
        mark->setMarkerSize(kHighlightRingSize);
        mark->setBrush(Qt::NoBrush);
        mark->setPen(QPen(kHighlightColor, 3.0));
        for (const SweepPoint* p : highlighted) mark->append(at(p));
        attach(mark);
        mHighlightMarks = int(highlighted.size());
    }
    applyLegendLabels();
    emit rebuilt();
}

}  // namespace palpate
