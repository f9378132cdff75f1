#pragma once
// The feel chart (docs/bench/README.md, "Feel"): every model's tick cost against the largest force
// step the hand feels while the tool slides at constant depth, one point per model and mesh
// resolution (circles: sphere, squares: stomach; a model's points of one shape joined in order of
// resolution), the goal (step <= 1 % of the mean force) as a dashed line. Both axes are logarithmic:
// the models' costs span five decades and their steps three. The x axis is the tick cost as a
// fraction of the paper's "previous" method's on the same mesh and run (the bench's ratios), or
// in microseconds.

#include "engine/bench/FeelBench.h"

#include <QChartView>
#include <QColor>
#include <QString>
#include <QStringList>

#include <string>
#include <vector>

namespace palpate {

class FeelChart final : public QChartView {
    Q_OBJECT
public:
    enum class XAxis { RatioToPrevious, TickMicroseconds };

    explicit FeelChart(QWidget* parent = nullptr);
    ~FeelChart() override;

    void setRows(std::vector<FeelRow> rows);
    const std::vector<FeelRow>& rows() const { return mRows; }
    void setXAxis(XAxis axis);
    XAxis xAxis() const { return mXAxis; }
    /// Shown as the title while there are no rows.
    void setEmptyHint(const QString& hint);
    void setLegendShown(bool shown);
    /// Scales every text (a 1400 px PNG needs larger text than a dock).
    void setTextScale(double scale);

    /// The legend as one line of rich text that wraps, for a dock (see SpeedAccuracyChart).
    QString legendHtml() const;
    /// The model series drawn, in legend order (tests, the panel).
    QStringList seriesNames() const;
    /// Points drawn, and of them those above the goal line.
    int pointCount() const { return mPointCount; }
    int pointsAboveGoal() const { return mAboveGoal; }

    static QColor modelColor(const std::string& model);

signals:
    void rebuilt();

protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void rebuild();
    void applyFonts();
    /// Narrow (a dock): short title and axis titles, no minor grid lines; wide (a PNG): the full ones.
    void applyWidth();
    bool narrow() const;
    QString titleText() const;
    double xOf(const FeelRow& row) const;

    std::vector<FeelRow> mRows;
    XAxis mXAxis = XAxis::RatioToPrevious;
    QString mEmptyHint;
    bool mLegendShown = true;
    double mTextScale = 1.0;
    int mPointCount = 0;
    int mAboveGoal = 0;
};

}  // namespace palpate
