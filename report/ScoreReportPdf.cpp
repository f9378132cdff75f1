#include "report/ScoreReportPdf.h"

#include "report/HeatColour.h"
#include "report/MetricText.h"
#include "report/PalpationSummaryText.h"

#include "report/ChartApplication.h"
#include "base/io/AtomicFile.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QFont>
#include <QFontMetricsF>
#include <QLinearGradient>
#include <QLocale>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(palpate::ScoreReportPdf)
};

QString number(double v, int decimals) { return QLocale().toString(v, 'f', decimals); }

/// A name (exercise, trainee, device) as the report prints it: on one line (line breaks and other
/// control characters are spaces), composed (NFC) and then at most one combining mark on a letter
/// (stacks of marks reach into the lines above and below; real names compose to one), at most
/// kMaxNameChars characters (then an ellipsis): whatever a file or a database holds, a name takes
/// a few lines of the page, never the page.
QString shownName(const QString& name) {
    constexpr qsizetype kMaxNameChars = 240;
    QString out;
    int marks = 0;
    for (const QChar c : name.normalized(QString::NormalizationForm_C)) {
        const QChar::Category category = c.category();
        const bool mark = category == QChar::Mark_NonSpacing || category == QChar::Mark_SpacingCombining ||
                          category == QChar::Mark_Enclosing;
        marks = mark ? marks + 1 : 0;
        if (mark && marks > 1) continue;
        const bool control = category == QChar::Other_Control || category == QChar::Separator_Line ||
                             category == QChar::Separator_Paragraph || category == QChar::Other_Format;
        out += control ? QChar(QLatin1Char(' ')) : c;
    }
    out = out.simplified();
    if (out.size() > kMaxNameChars) {
        qsizetype cut = kMaxNameChars;
        if (out[cut - 1].isHighSurrogate()) --cut;
        out = out.left(cut) + QChar(0x2026);
    }
    return out;
}
/// A force with one decimal, or two when it has them (a window of 0.65 – 1.65 N).
QString forceText(double n) { return number(n, std::abs(n * 10.0 - std::round(n * 10.0)) < 1e-6 ? 1 : 2); }
QString window(double minN, double maxN) { return Tr::tr("%1 – %2 N").arg(forceText(minN), forceText(maxN)); }

/// A tick step of 1, 2 or 5 times a power of ten giving about `count` ticks over `range`.
double niceStep(double range, int count) {
    if (!(range > 0.0)) return 1.0;
    const double raw = range / count;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * power) return m * power;
    return 10.0 * power;
}

/// One table cell: its text and, below it in small grey type, an optional note.
struct Cell {
    QString text;
    QString note;
};

struct Column {
    QString title;
    double widthFraction = 0.0;  ///< of the page's width
    bool alignRight = false;
};

/// Lays the report out top to bottom on A4 pages and starts a new page when the next piece does
/// not fit. Every size comes from the font metrics of the PDF device itself: metrics taken for the
/// screen are a fraction of the PDF's at its resolution, which once put every line on the last.
class ReportLayout {
public:
    /// `pageCount`: the document's pages, for the footer (0: not known yet, the first pass).
    ReportLayout(QPdfWriter& writer, int pageCount) : mWriter(writer), mPageCount(pageCount) {
        mBody.setFamily(QStringLiteral("DejaVu Sans"));
        mBody.setPointSizeF(9.5);
        mSmall = mBody;
        mSmall.setPointSizeF(7.5);
        mBold = mBody;
        mBold.setBold(true);
        mHeading = mBody;
        mHeading.setPointSizeF(12);
        mHeading.setBold(true);
        mTitle = mBody;
        mTitle.setPointSizeF(18);
        mTitle.setBold(true);
        mScore = mBody;
        mScore.setPointSizeF(30);
        mScore.setBold(true);
    }

    bool begin() {
        if (!mPainter.begin(&mWriter)) return false;
        const QFontMetricsF small(mSmall, &mWriter);
        mFooterH = small.height() * 1.8;
        mPage = QRectF(0, 0, mWriter.width(), mWriter.height() - mFooterH);
        drawFooter();
        return true;
    }
    bool end() { return mPainter.end(); }
    int pageNumber() const { return mPageNumber; }

    double mm(double v) const { return v * mWriter.resolution() / 25.4; }
    QPainter& painter() { return mPainter; }
    const QRectF& page() const { return mPage; }
    double y() const { return mY; }
    double spaceLeft() const { return mPage.bottom() - mY; }
    void skip(double height) { mY += height; }
    QFontMetricsF metrics(const QFont& font) const { return QFontMetricsF(font, &mWriter); }
    const QFont& body() const { return mBody; }
    const QFont& small() const { return mSmall; }
    const QFont& bold() const { return mBold; }
    const QFont& heading() const { return mHeading; }
    const QFont& title() const { return mTitle; }
    const QFont& score() const { return mScore; }

    void newPage() {
        mWriter.newPage();
        ++mPageNumber;
        mY = 0;
        drawFooter();
    }
    /// A new page unless `height` fits below the current position (a piece taller than a page
    /// starts at the top of one).
    void ensure(double height) {
        if (mY > 0 && mY + height > mPage.bottom()) newPage();
    }

    /// The text with a break opportunity (a zero-width space) between the letters of each word
    /// wider than `width` (a long file name), so that word wrap breaks only those anywhere.
    QString wrappable(const QFont& font, double width, const QString& text) const {
        const QFontMetricsF fm = metrics(font);
        QStringList words = text.split(QLatin1Char(' '));
        for (QString& word : words) {
            if (fm.horizontalAdvance(word) <= width) continue;
            QString broken;
            for (qsizetype i = 0; i < word.size(); ++i) {
                broken += word[i];
                if (i + 1 < word.size() && !word[i].isHighSurrogate()) broken += QChar(0x200B);
            }
            word = broken;
        }
        return words.join(QLatin1Char(' '));
    }
    /// `font`, made smaller (to 70 % at most) until every word of the cells fits its column: a
    /// header's word ("Abweichung" in a narrow column) is not broken between its letters.
    QFont fittingFont(const QFont& font, const std::vector<Cell>& cells, const std::vector<double>& widths) const {
        QFont fitted = font;
        const double smallest = 0.7 * font.pointSizeF();
        auto fits = [&] {
            const QFontMetricsF fm = metrics(fitted);
            for (std::size_t c = 0; c < cells.size() && c < widths.size(); ++c)
                for (const QString& word : cells[c].text.split(QLatin1Char(' ')))
                    if (fm.horizontalAdvance(word) > widths[c]) return false;
            return true;
        };
        while (!fits() && fitted.pointSizeF() - 0.25 >= smallest) fitted.setPointSizeF(fitted.pointSizeF() - 0.25);
        return fitted;
    }
    double textHeight(const QFont& font, double width, const QString& text) const {
        if (text.isEmpty()) return 0.0;
        return metrics(font).boundingRect(QRectF(0, 0, width, 1e9), Qt::TextWordWrap, wrappable(font, width, text)).height();
    }
    /// Draws wrapped text in [x, x + width] from `top`; returns its height.
    double drawText(const QFont& font, double x, double top, double width, const QString& text, bool alignRight = false,
                    const QColor& color = Qt::black) {
        if (text.isEmpty()) return 0.0;
        const double height = textHeight(font, width, text);
        mPainter.setFont(font);
        mPainter.setPen(color);
        mPainter.drawText(QRectF(x, top, width, height),
                          Qt::TextWordWrap | (alignRight ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignTop,
                          wrappable(font, width, text));
        return height;
    }
    /// A paragraph across the page, on a new page when it does not fit.
    void paragraph(const QFont& font, const QString& text, const QColor& color = Qt::black) {
        const double height = textHeight(font, mPage.width(), text);
        ensure(height);
        mY += drawText(font, 0, mY, mPage.width(), text, false, color);
    }

    /// "Label: value" rows, the labels in a column of their own, the values wrapped beside them.
    void fields(const std::vector<std::pair<QString, QString>>& rows) {
        double labelW = 0.0;
        for (const auto& [label, value] : rows) labelW = std::max(labelW, metrics(mBold).horizontalAdvance(label));
        labelW += mm(3);
        const double gap = metrics(mBody).height() * 0.25;
        for (const auto& [label, value] : rows) {
            const double valueW = mPage.width() - labelW;
            const double height = std::max(textHeight(mBold, labelW, label), textHeight(mBody, valueW, value));
            ensure(height);
            drawText(mBold, 0, mY, labelW, label);
            drawText(mBody, labelW, mY, valueW, value);
            mY += height + gap;
        }
    }

    /// A table under its heading, with a header row, each cell wrapped in its column: on the next
    /// page when it fits on a page but not on what is left of this one; continued (heading and
    /// header again) on the next page when it is longer than a page.
    void table(const QString& heading, const std::vector<Column>& columns, const std::vector<std::vector<Cell>>& rows) {
        const double pad = mm(1.2);
        std::vector<double> left, width;
        double x = 0.0;
        for (const Column& c : columns) {
            left.push_back(x + pad);
            width.push_back(c.widthFraction * mPage.width() - 2 * pad);
            x += c.widthFraction * mPage.width();
        }
        auto rowHeight = [&](const std::vector<Cell>& row, const QFont& font) {
            double h = 0.0;
            for (std::size_t c = 0; c < row.size() && c < columns.size(); ++c) {
                double cell = textHeight(font, width[c], row[c].text);
                if (!row[c].note.isEmpty()) cell += pad * 0.4 + textHeight(mSmall, width[c], row[c].note);
                h = std::max(h, cell);
            }
            return h + 2 * pad;
        };
        std::vector<Cell> header;
        for (const Column& c : columns) header.push_back({c.title, {}});
        const QFont headerFont = fittingFont(mBold, header, width);
        const double headerH = rowHeight(header, headerFont);
        const double headingH = textHeight(mHeading, mPage.width(), heading) + metrics(mBody).height() * 0.3;
        double total = headingH + headerH;
        for (const auto& row : rows) total += rowHeight(row, mBody);
        if (total <= mPage.height() && total > spaceLeft()) newPage();
        auto drawHeader = [&](const QString& title) {
            mY += drawText(mHeading, 0, mY, mPage.width(), title) + metrics(mBody).height() * 0.3;
            for (std::size_t c = 0; c < columns.size(); ++c)
                drawText(headerFont, left[c], mY + pad, width[c], header[c].text, columns[c].alignRight);
            mY += headerH;
            mPainter.setPen(QPen(Qt::black, mm(0.3)));
            mPainter.drawLine(QPointF(0, mY), QPointF(mPage.width(), mY));
        };
        ensure(headingH + headerH + (rows.empty() ? 0.0 : rowHeight(rows.front(), mBody)));
        drawHeader(heading);
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const double height = rowHeight(rows[r], mBody);
            if (mY + height > mPage.bottom()) {
                newPage();
                drawHeader(Tr::tr("%1 (continued)").arg(heading));
            }
            if (r % 2 == 1) mPainter.fillRect(QRectF(0, mY, mPage.width(), height), QColor(243, 243, 243));
            for (std::size_t c = 0; c < rows[r].size() && c < columns.size(); ++c) {
                const double h = drawText(mBody, left[c], mY + pad, width[c], rows[r][c].text, columns[c].alignRight);
                drawText(mSmall, left[c], mY + pad + h + (h > 0 ? pad * 0.4 : 0.0), width[c], rows[r][c].note,
                         columns[c].alignRight, QColor(90, 90, 90));
            }
            mY += height;
        }
        mPainter.setPen(QPen(Qt::black, mm(0.3)));
        mPainter.drawLine(QPointF(0, mY), QPointF(mPage.width(), mY));
    }

private:
    void drawFooter() {
        const QFontMetricsF fm = metrics(mSmall);
        mPainter.setFont(mSmall);
        mPainter.setPen(QColor(90, 90, 90));
        const QString text = mPageCount > 0 ? Tr::tr("Palpate score report, page %1 of %2").arg(mPageNumber).arg(mPageCount)
                                            : Tr::tr("Palpate score report, page %1").arg(mPageNumber);
        mPainter.drawText(QPointF(mWriter.width() - fm.horizontalAdvance(text), mWriter.height() - fm.descent()), text);
    }

    QPdfWriter& mWriter;
    QPainter mPainter;
    QFont mBody, mSmall, mBold, mHeading, mTitle, mScore;
    QRectF mPage;
    double mFooterH = 0.0;
    double mY = 0.0;
    int mPageNumber = 1;
    int mPageCount = 0;
};

/// Colours for the force windows of consecutive targets (so that two side by side differ).
QColor windowColor(int index, int alpha) {
    static const QColor colors[] = {QColor(90, 180, 90), QColor(230, 160, 40), QColor(80, 150, 220), QColor(200, 90, 170)};
    QColor c = colors[std::size_t(std::max(index, 0)) % std::size(colors)];
    c.setAlpha(alpha);
    return c;
}

/// The force over time in `area`: time and force axes, each force window shaded over its own
/// stretch of time and labelled with its target, the curve on top.
/// The coverage heat map as two views of the rest surface, from the side examined most and from
/// the opposite one: each vertex facing the view a dot, grey where nothing examined it, else
/// coloured by the largest force there (the viewport's scale), far dots first.
void drawHeatMap(ReportLayout& layout, const QRectF& area, const ScoreReportContent& content) {
    QPainter& p = layout.painter();
    const PalpationSummary& palpation = *content.report.palpation;
    const auto& rest = content.surfaceMm;
    const auto& normals = content.normals;
    const std::size_t n = std::min({rest.size(), normals.size(), palpation.peakForceN.size()});
    double maxN = palpation.coverage.minForceN;
    glm::dvec3 centre(0.0), examined(0.0);
    for (std::size_t v = 0; v < n; ++v) {
        centre += glm::dvec3(rest[v]);
        examined += double(palpation.peakForceN[v]) * glm::dvec3(normals[v]);
        maxN = std::max(maxN, double(palpation.peakForceN[v]));
    }
    if (n == 0) return;
    centre /= double(n);
    glm::dvec3 view = glm::length(examined) > 1e-9 ? glm::normalize(examined) : glm::dvec3(1.0, 0.0, 0.0);
    const double small = layout.metrics(layout.small()).height();
    const double gap = layout.mm(6);
    const double side = std::min((area.width() - gap) / 2.0, area.height() - 1.6 * small);
    for (int k = 0; k < 2; ++k) {
        const glm::dvec3 towards = k == 0 ? view : -view;  // from the eye to the surface: -towards
        const glm::dvec3 helper = std::abs(towards.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
        const glm::dvec3 right = glm::normalize(glm::cross(helper, towards)), up = glm::cross(towards, right);
        double extent = 1e-9;
        for (std::size_t v = 0; v < n; ++v) {
            const glm::dvec3 d = glm::dvec3(rest[v]) - centre;
            extent = std::max({extent, std::abs(glm::dot(d, right)), std::abs(glm::dot(d, up))});
        }
        const QRectF box(area.left() + k * (side + gap), area.top(), side, side);
        const double scale = 0.48 * side / extent;
        std::vector<std::pair<double, std::size_t>> order;
        for (std::size_t v = 0; v < n; ++v)
            if (glm::dot(glm::dvec3(normals[v]), towards) > 0.0)
                order.emplace_back(glm::dot(glm::dvec3(rest[v]) - centre, towards), v);
        std::sort(order.begin(), order.end());
        p.setPen(Qt::NoPen);
        const double dot = std::max(layout.mm(0.5), 0.9 * scale * std::sqrt(4.0 * extent * extent / double(n)));
        for (const auto& [depth, v] : order) {
            const glm::dvec3 d = glm::dvec3(rest[v]) - centre;
            const QPointF at(box.center().x() + scale * glm::dot(d, right), box.center().y() - scale * glm::dot(d, up));
            const float f = palpation.peakForceN[v];
            p.setBrush(f > 0.0f ? coverageHeatColour(f, palpation.coverage.minForceN, maxN) : QColor(200, 200, 200));
            p.drawEllipse(at, dot, dot);
        }
        p.setPen(QColor(90, 90, 90));
        p.setFont(layout.small());
        p.drawText(QRectF(box.left(), box.bottom() + 0.2 * small, box.width(), small), Qt::AlignCenter,
                   k == 0 ? Tr::tr("the side examined most") : Tr::tr("the opposite side"));
    }
    // The scale.
    const QRectF bar(area.left(), area.top() + side + 1.6 * small, layout.mm(40), small * 0.6);
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    gradient.setColorAt(0.0, coverageHeatColour(palpation.coverage.minForceN, palpation.coverage.minForceN, maxN));
    gradient.setColorAt(1.0, coverageHeatColour(maxN, palpation.coverage.minForceN, maxN));
    p.setBrush(gradient);
    p.setPen(QPen(QColor(90, 90, 90), layout.mm(0.1)));
    p.drawRect(bar);
    p.drawText(QRectF(bar.right() + layout.mm(2), bar.top() - 0.3 * small, area.width() - bar.width(), small),
               Qt::AlignLeft | Qt::AlignVCenter,
               Tr::tr("examined at %1 to %2 N (largest force); grey: not examined")
                   .arg(number(palpation.coverage.minForceN, 1), number(maxN, 1)));
}

void drawForcePlot(ReportLayout& layout, const QRectF& area, const ScoreReportContent& content) {
    QPainter& p = layout.painter();
    const QFont& font = layout.small();
    const QFontMetricsF fm = layout.metrics(font);
    const double lh = fm.height();
    const QString fTitle = Tr::tr("|F| (N)"), tTitle = Tr::tr("Time (s)");
    const auto& series = content.force;

    double t0 = series.front().timeS, t1 = series.front().timeS, fMax = 0.0;
    for (const ForceSample& s : series) {
        t0 = std::min(t0, s.timeS);
        t1 = std::max(t1, s.timeS);
        if (std::isfinite(s.forceN)) fMax = std::max(fMax, s.forceN);
    }
    for (const ForceWindowSpan& w : content.windows) fMax = std::max(fMax, w.forceMaxN);
    if (t1 <= t0) t1 = t0 + 1.0;
    if (fMax <= 0.0) fMax = 1.0;
    fMax *= 1.05;
    const double fStep = niceStep(fMax, 5), tStep = niceStep(t1 - t0, 10);
    fMax = std::ceil(fMax / fStep - 1e-9) * fStep;
    const int tDecimals = tStep < 1.0 ? 1 : 0, fDecimals = fStep < 1.0 ? (fStep < 0.1 ? 2 : 1) : 0;

    // Room for the force labels at the left, the time labels and title below, the force title
    // above; and a line inside the top of the plot for the window labels.
    double labelW = fm.horizontalAdvance(fTitle);
    for (double f = 0.0; f <= fMax + 1e-9; f += fStep) labelW = std::max(labelW, fm.horizontalAdvance(number(f, fDecimals)));
    const QRectF plot(area.left() + labelW + lh * 0.5, area.top() + lh * 1.5, area.width() - labelW - lh * 1.0,
                      area.height() - lh * 4.0);
    const double headroom = lh * 1.4;
    auto x = [&](double t) { return plot.left() + (t - t0) / (t1 - t0) * plot.width(); };
    auto y = [&](double f) { return plot.bottom() - f / fMax * (plot.height() - headroom); };

    // Grid.
    p.setPen(QPen(QColor(225, 225, 225), 0));
    for (double t = std::ceil(t0 / tStep) * tStep; t <= t1 + 1e-9; t += tStep)
        p.drawLine(QPointF(x(t), plot.top()), QPointF(x(t), plot.bottom()));
    for (double f = 0.0; f <= fMax + 1e-9; f += fStep) p.drawLine(QPointF(plot.left(), y(f)), QPointF(plot.right(), y(f)));

    // Each window over its own stretch, its label above it where it fits (the target table
    // lists every window in full).
    double labelRight = plot.left();
    for (const ForceWindowSpan& w : content.windows) {
        const double left = std::max(plot.left(), x(w.startS)), right = std::min(plot.right(), x(w.endS));
        if (right <= left) continue;
        const QRectF band(QPointF(left, y(w.forceMaxN)), QPointF(right, y(w.forceMinN)));
        p.fillRect(band, windowColor(w.targetIndex, 70));
        p.setPen(QPen(windowColor(w.targetIndex, 255).darker(140), layout.mm(0.25)));
        p.drawLine(band.topLeft(), band.topRight());
        p.drawLine(band.bottomLeft(), band.bottomRight());
        const QString name = w.targetIndex >= 0 ? Tr::tr("Target %1").arg(w.targetIndex + 1) : Tr::tr("Force band");
        const QString shortName = w.targetIndex >= 0 ? Tr::tr("T%1").arg(w.targetIndex + 1) : QString();
        const QString range = window(w.forceMinN, w.forceMaxN);
        const double room = right - std::max(left, labelRight) - lh * 0.4;
        QString label;
        for (const QString& candidate : {name + QStringLiteral(": ") + range, name, shortName})
            if (!candidate.isEmpty() && fm.horizontalAdvance(candidate) <= room) {
                label = candidate;
                break;
            }
        if (label.isEmpty()) continue;
        const double labelLeft = std::max(left, labelRight) + lh * 0.2;
        p.setFont(font);
        p.setPen(windowColor(w.targetIndex, 255).darker(170));
        p.drawText(QPointF(labelLeft, band.top() - fm.descent() - lh * 0.15), label);
        labelRight = labelLeft + fm.horizontalAdvance(label);
    }

    // Axes, tick labels, titles.
    p.setPen(QPen(Qt::black, 0));
    p.drawRect(plot);
    p.setFont(font);
    double lastLabelRight = -1e18;
    for (double t = std::ceil(t0 / tStep) * tStep; t <= t1 + 1e-9; t += tStep) {
        const QString label = number(t, tDecimals);
        const double w = fm.horizontalAdvance(label);
        const double left = std::clamp(x(t) - w / 2, plot.left() - w / 2, area.right() - w);
        if (left < lastLabelRight + lh * 0.5) continue;
        p.drawText(QPointF(left, plot.bottom() + lh * 0.2 + fm.ascent()), label);
        lastLabelRight = left + w;
    }
    for (double f = 0.0; f <= fMax + 1e-9; f += fStep) {
        const QString label = number(f, fDecimals);
        p.drawText(QPointF(plot.left() - fm.horizontalAdvance(label) - lh * 0.3, y(f) + (fm.ascent() - fm.descent()) / 2),
                   label);
    }
    p.drawText(QPointF(plot.center().x() - fm.horizontalAdvance(tTitle) / 2, plot.bottom() + lh * 1.4 + fm.ascent()),
               tTitle);
    p.drawText(QPointF(area.left(), plot.top() - lh * 0.4 - fm.descent()), fTitle);

    QPainterPath curve;
    bool started = false;
    for (const ForceSample& s : series) {
        if (!std::isfinite(s.timeS) || !std::isfinite(s.forceN)) continue;
        const QPointF pt(x(s.timeS), y(s.forceN));
        if (started)
            curve.lineTo(pt);
        else
            curve.moveTo(pt), started = true;
    }
    p.setPen(QPen(QColor(30, 60, 170), layout.mm(0.35)));
    p.setClipRect(plot);
    p.drawPath(curve);
    p.setClipping(false);
}

QString resultText(const ScoreReport& report) {
    const ScoreGuidance& g = report.guidance;
    if (g.completed) return Tr::tr("completed in %1 s").arg(number(g.exerciseTimeS, 1));
    if (g.timeUp) return Tr::tr("time limit reached (%1 s)").arg(number(g.exerciseTimeS, 1));
    return Tr::tr("not finished (%1 s scored)").arg(number(g.exerciseTimeS, 1));
}

void drawReport(ReportLayout& layout, const ScoreReportContent& content) {
    const ScoreReport& report = content.report;
    const double line = layout.metrics(layout.body()).height();

    layout.paragraph(layout.title(), Tr::tr("Palpate score report"));
    layout.skip(line * 0.5);
    const QString device = content.device.isEmpty() ? Tr::tr("not recorded") : content.device;
    layout.fields({
        {Tr::tr("Exercise:"), content.exerciseName.isEmpty() ? Tr::tr("(unnamed)") : shownName(content.exerciseName)},
        {Tr::tr("Trainee:"), content.traineeName.isEmpty() ? Tr::tr("not recorded") : shownName(content.traineeName)},
        {Tr::tr("Date:"), content.sessionStart.isValid()
                              ? QLocale().toString(content.sessionStart.toLocalTime(), QLocale::LongFormat)
                              : Tr::tr("not recorded")},
        {Tr::tr("Device:"), device},
        {Tr::tr("Result:"), resultText(report)},
    });
    layout.skip(line * 0.6);
    layout.paragraph(layout.score(), Tr::tr("Score: %1 / 100").arg(scoreText(report.score)));
    layout.skip(line * 0.8);

    if (!report.targets.empty()) {
        std::vector<std::vector<Cell>> rows;
        for (std::size_t i = 0; i < report.targets.size(); ++i) {
            const TargetResult& t = report.targets[i];
            const PressTarget* def = i < content.targets.size() ? &content.targets[i] : nullptr;
            rows.push_back({{Tr::tr("Target %1").arg(i + 1), {}},
                            {def ? window(def->forceMinN, def->forceMaxN) : QString(), {}},
                            {def ? Tr::tr("%1 s").arg(number(def->holdS, 1)) : QString(), {}},
                            {t.achieved ? Tr::tr("achieved at %1 s").arg(number(t.achievedAtS, 1)) : Tr::tr("not achieved"), {}},
                            {t.errorMeasured ? Tr::tr("%1 mm").arg(number(t.errorMm, 2)) : Tr::tr("n/a"), {}},
                            {Tr::tr("%1 s").arg(number(t.onTargetS, 2)), {}},
                            {Tr::tr("%1 s").arg(number(t.inWindowS, 2)), {}}});
        }
        layout.table(Tr::tr("Targets"),
                     {{Tr::tr("Target"), 0.13, false},
                      {Tr::tr("Force window"), 0.17, false},
                      {Tr::tr("Hold"), 0.09, false},
                      {Tr::tr("Result"), 0.22, false},
                      {Tr::tr("Error"), 0.12, true},
                      {Tr::tr("On target"), 0.13, true},
                      {Tr::tr("In window"), 0.14, true}},
                     rows);
        layout.skip(line * 1.2);
    }

    if (!content.force.empty()) {
        // Below the summary when there is room enough for it, else at the top of the next page.
        const double heading = layout.textHeight(layout.heading(), layout.page().width(), Tr::tr("Force over time")) + line * 0.3;
        const double caption = layout.textHeight(layout.small(), layout.page().width(), QStringLiteral("x")) * 2;
        const double wanted = layout.mm(105), least = layout.mm(75);
        layout.ensure(heading + caption + std::min(wanted, std::max(least, layout.spaceLeft() - heading - caption)));
        layout.paragraph(layout.heading(), Tr::tr("Force over time"));
        layout.skip(line * 0.3);
        const double height = std::min(wanted, layout.spaceLeft() - caption);
        drawForcePlot(layout, QRectF(0, layout.y(), layout.page().width(), height), content);
        layout.skip(height);
        if (!content.windows.empty())
            layout.paragraph(layout.small(),
                             content.windows.front().targetIndex >= 0
                                 ? Tr::tr("Shaded: each target's own force window, over the time it was the target to press.")
                                 : Tr::tr("Shaded: the force band to keep while tracing."),
                             QColor(90, 90, 90));
        layout.skip(line * 1.2);
    }

    if (report.palpation) {
        // Palpation: what was found, how much was examined and how firmly, and what to do better.
        const PalpationSummary& p = *report.palpation;
        layout.ensure(line * 6);
        layout.paragraph(layout.heading(), Tr::tr("Palpation"));
        layout.skip(line * 0.3);
        if (const auto& d = p.detection; d && !d->findingOfLump.empty()) {
            std::vector<std::vector<Cell>> lumpRows;
            for (std::size_t k = 0; k < d->findingOfLump.size(); ++k) {
                const LumpDef* def = k < content.lumps.size() ? &content.lumps[k] : nullptr;
                const bool hit = d->findingOfLump[k] >= 0;
                lumpRows.push_back({{Tr::tr("Lump %1").arg(k + 1), {}},
                                    {def ? Tr::tr("%1 mm").arg(number(def->depthMm, 1)) : QString(), {}},
                                    {def ? Tr::tr("%1 mm").arg(number(def->radiusMm, 1)) : QString(), {}},
                                    {def ? Tr::tr("%1 x").arg(number(def->contrast, 1)) : QString(), {}},
                                    {hit ? Tr::tr("found") : Tr::tr("missed"), {}},
                                    {hit ? Tr::tr("%1 mm").arg(number(d->localisationMm[k], 1)) : Tr::tr("n/a"), {}}});
            }
            layout.table(Tr::tr("Lumps"),
                         {{Tr::tr("Lump"), 0.16, false},
                          {Tr::tr("Depth"), 0.16, true},
                          {Tr::tr("Radius"), 0.16, true},
                          {Tr::tr("Contrast"), 0.16, true},
                          {Tr::tr("Result"), 0.18, false},
                          {Tr::tr("Off by"), 0.18, true}},
                         lumpRows);
            layout.skip(line * 0.6);
        }
        for (const QString& text : palpationSummaryLines(report)) {
            layout.paragraph(layout.body(), text);
            layout.skip(line * 0.2);
        }
        if (!content.surfaceMm.empty() && !p.peakForceN.empty()) {
            const double height = layout.mm(85);
            layout.ensure(height + line * 4.0);
            layout.skip(line * 0.4);
            layout.paragraph(layout.heading(), Tr::tr("Surface examined"));
            layout.skip(line * 0.3);
            drawHeatMap(layout, QRectF(0, layout.y(), layout.page().width(), height), content);
            layout.skip(height + line * 1.5);  // the picture, its captions and the scale under them
        }
        if (p.forceByPhase.search || p.forceByPhase.palpation) {
            std::vector<std::vector<Cell>> phaseRows;
            auto phaseRow = [&](const QString& name, const std::optional<ForcePercentiles>& f) {
                if (!f) return;
                phaseRows.push_back({{name, {}},
                                     {Tr::tr("%1 N").arg(number(f->p10N, 2)), {}},
                                     {Tr::tr("%1 N").arg(number(f->p50N, 2)), {}},
                                     {Tr::tr("%1 N").arg(number(f->p90N, 2)), {}},
                                     {Tr::tr("%1 N").arg(number(f->maxN, 2)), {}},
                                     {QLocale().toString(qulonglong(f->samples)), {}}});
            };
            phaseRow(Tr::tr("Search"), p.forceByPhase.search);
            phaseRow(Tr::tr("Palpation"), p.forceByPhase.palpation);
            layout.skip(line * 0.4);
            layout.table(Tr::tr("Force by phase"),
                         {{Tr::tr("Phase"), 0.2, false},
                          {Tr::tr("10th pct."), 0.16, true},
                          {Tr::tr("Median"), 0.16, true},
                          {Tr::tr("90th pct."), 0.16, true},
                          {Tr::tr("Largest"), 0.16, true},
                          {Tr::tr("Ticks"), 0.16, true}},
                         phaseRows);
        }
        layout.skip(line * 1.2);
    }

    std::vector<std::vector<Cell>> rows;
    for (const MetricResult& m : report.metrics) {
        const QString value = m.measured ? localMetricValueText(m.metric, m.value) : Tr::tr("n/a");
        rows.push_back({{metricNameText(m.metric), metricDescriptionText(m.metric)},
                        {value, {}},
                        {number(m.subScore, 2), {}},
                        {number(m.weight, 1), {}},
                        {number(m.contribution, 1), {}}});
    }
    layout.table(Tr::tr("Breakdown"),
                 {{Tr::tr("Metric"), 0.46, false},
                  {Tr::tr("Value"), 0.16, true},
                  {Tr::tr("Sub-score"), 0.12, true},
                  {Tr::tr("Weight"), 0.11, true},
                  {Tr::tr("Contribution"), 0.15, true}},
                 rows);
    if (const QString work = workDoneText(report.workDone); !work.isEmpty()) {
        layout.skip(line * 0.5);
        layout.paragraph(layout.body(), work, QColor(40, 40, 40));
    }
    if (!report.warnings.empty()) {
        layout.skip(line * 0.8);
        for (const std::string& w : report.warnings) {
            layout.paragraph(layout.body(), Tr::tr("Warning: %1").arg(QString::fromStdString(w)), QColor(150, 60, 0));
            layout.skip(line * 0.3);
        }
    }
}

}  // namespace

bool writeScoreReportPdf(const QString& path, const ScoreReportContent& content, QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = Tr::tr("%1: %2").arg(QDir::toNativeSeparators(path), why);
        return false;
    };
    const QFileInfo info(path);
    const QFileInfo folder(info.absolutePath());
    if (!folder.isDir())
        return fail(Tr::tr("cannot be written: folder %1 does not exist")
                        .arg(QDir::toNativeSeparators(folder.absoluteFilePath())));
    if (info.isDir()) return fail(Tr::tr("cannot be written: it is a folder"));
    const ChartApplication application;
    if (!application.problem().empty()) return fail(QString::fromStdString(application.problem()));

    // Drawn into memory first, then written whole to a temporary file that replaces the target.
    // Twice: the first pass counts the pages for the footers of the second (the footer's text
    // does not move anything).
    QByteArray bytes;
    int pageCount = 0;
    for (int pass = 0; pass < 2; ++pass) {
        bytes.clear();
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QPdfWriter writer(&buffer);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
        writer.setResolution(300);
        writer.setTitle(Tr::tr("Palpate score report"));
        writer.setCreator(QStringLiteral("Palpate"));
        ReportLayout layout(writer, pageCount);
        if (!layout.begin()) return fail(Tr::tr("cannot be drawn (the PDF writer did not start)"));
        drawReport(layout, content);
        if (!layout.end()) return fail(Tr::tr("cannot be drawn"));
        pageCount = layout.pageNumber();
    }
    if (bytes.isEmpty()) return fail(Tr::tr("cannot be drawn (empty document)"));
    // Through the engine's atomic writer (docs/reliability.md): a failed write or fsync is an error
    // naming its reason, and the old file stays as it was.
    if (const std::string problem =
            writeFileAtomically(QDir::toNativeSeparators(path).toStdString(), std::string(bytes.constData(), std::size_t(bytes.size())));
        !problem.empty()) {
        if (error) *error = QString::fromStdString(problem);
        return false;
    }
    return true;
}

}  // namespace palpate
