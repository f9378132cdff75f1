#pragma once
// The speed-vs-accuracy chart (docs/calibration.md): every model's tick cost against its
// displacement error, one series per model joined in order of resolution, the Pareto front marked,
// and the configuration in use highlighted, so that a choice of rings and model can be read off as
// "how much error for how many microseconds". One shape (sphere or stomach) per chart: the two
// shapes' fronts differ and mixed on one plot they hide each other.

#include "engine/core/MeshGenerator.h"
#include "engine/accuracy/AccuracySweep.h"

#include <QChartView>
#include <QColor>
#include <QString>
#include <QStringList>

#include <optional>
#include <string>
#include <vector>

class QLogValueAxis;
class QValueAxis;

namespace palpate {

class SpeedAccuracyChart final : public QChartView {
    Q_OBJECT
public:
    explicit SpeedAccuracyChart(QWidget* parent = nullptr);
    ~SpeedAccuracyChart() override;

    /// Replaces the points (each keeps its own `pareto` flag: markParetoFront decides, not the chart).
    void setPoints(std::vector<SweepPoint> points);
    const std::vector<SweepPoint>& points() const { return mPoints; }
    /// The tissue and tool the slopes were calibrated for, named in the title; nullopt when unknown
    /// (e.g. a CSV without its JSON), and the title says so.
    void setToolContact(const std::optional<ToolContact>& contact);
    /// Which shape's points to draw; nullopt: the first shape the points have.
    void setShape(std::optional<GeneratedShape> shape);
    /// The shape drawn now (the first present when none was chosen; Sphere without points).
    GeneratedShape shownShape() const;
    /// The shapes the points have, in order of first appearance.
    std::vector<GeneratedShape> shapesPresent() const;
    /// The organ sweep's sites (docs/accuracy.md, "The organ's own shape") of `shape`, in order of
    /// first appearance; a punch sweep has one, "".
    std::vector<std::string> sitesPresent(GeneratedShape shape) const;
    /// Which site's points to draw (each site has its own front); one not present: the first.
    void setSite(const std::string& site);
    std::string shownSite() const;
    /// Marks the points of `series` measured on `vertices` vertices (the configuration in use) with
    /// a larger outlined marker. An empty series clears the mark.
    void setHighlight(const std::string& series, std::size_t vertices);
    void clearHighlight() { setHighlight({}, 0); }
    /// Shown as the title while there are no points (e.g. "Run a sweep…").
    void setEmptyHint(const QString& hint);
    /// Draws the legend.
    void setLegendShown(bool shown);
    /// Scales every text of the chart (titles, labels, legend): a 1400 px PNG needs larger text
    /// than a dock.
    void setTextScale(double scale);

    /// The legend as one line of rich text that wraps (coloured markers and names): a dock shows it
    /// under the chart instead of the chart's own legend, which would take the plot's width.
    QString legendHtml() const;

    /// The model series drawn now, by name, in legend order (for tests and the panel).
    QStringList seriesNames() const;
    /// Points drawn with the Pareto mark, and with the highlight, in the shown shape.
    int paretoMarkCount() const;
    int highlightMarkCount() const;

    /// The colour of a series: slope-ring 1..8 rings on one sequential scale (more rings, darker),
    /// the paper's methods in colours of their own.
    static QColor seriesColor(const std::string& series);
    /// "Sphere", "Stomach" (translated).
    static QString shapeTitle(GeneratedShape shape);

signals:
    /// The series were drawn anew (points, shape or highlight changed).
    void rebuilt();

protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void rebuild();
    void applyFonts();
    void applyLegendLabels();
    QString titleText() const;

    std::vector<SweepPoint> mPoints;
    std::optional<ToolContact> mContact;
    std::optional<GeneratedShape> mShape;
    std::string mSite;
    std::string mHighlightSeries;
    std::size_t mHighlightVertices = 0;
    QString mEmptyHint;
    bool mLegendShown = true;
    double mTextScale = 1.0;
    int mParetoMarks = 0;
    int mHighlightMarks = 0;
};

}  // namespace palpate
