#pragma once
// The trainee's force gauge: |F| now against the exercise's window (press targets) or band (trace),
// with the excessive-force level and (palpation) the force that counts as examined marked. Horizontal, so that it reads at a glance beside the
// viewport: grey scale, the window shaded green, the excessive zone red, the bar coloured by where
// the force is (below: amber, inside: green, excessive: red).

#include <QColor>
#include <QWidget>

namespace palpate {

class ForceGauge final : public QWidget {
    Q_OBJECT
public:
    explicit ForceGauge(QWidget* parent = nullptr);

    /// The window [minN, maxN]; minN >= maxN hides it (no window to aim for).
    void setWindow(double minN, double maxN);
    /// Forces at or above this are excessive (drawn red); <= 0 hides the mark.
    void setExcessiveN(double excessiveN);
    /// The scale's full range (at least the excessive force, so that it always shows).
    void setFullScaleN(double fullScaleN);
    void setForceN(double forceN);
    /// The force a press must reach to count as examined, marked with a blue line; <= 0 hides it.
    void setExamineAtN(double examineAtN);
    double examineAtN() const { return mExamineAtN; }
    /// Fading guidance (docs/scoring.md): 1 fully shown .. 0 hidden (then a note says so).
    void setLevel(double level);
    double level() const { return mLevel; }

    double forceN() const { return mForceN; }
    /// The reading under the track ("0.50 N", "0,50 N" in German).
    QString readingText() const;
    double windowMinN() const { return mWindowMinN; }
    double windowMaxN() const { return mWindowMaxN; }
    double fullScaleN() const { return mFullScaleN; }
    /// The force at the gauge's right end. With a window it is fitted to the window (twice its
    /// upper end), so that a small window is not a sliver; the excessive zone is drawn when it falls
    /// on that scale, else the right end names it. Without a window: the full scale.
    double shownScaleN() const;
    /// Where the force is: -1 below the window (without one: below the force that examines), 0
    /// inside, +1 above it (2 excessive).
    int zone() const;
    /// The bar's colour for the current zone (tests look for it in the picture).
    QColor barColour() const;

    QSize sizeHint() const override { return {260, 44}; }
    QSize minimumSizeHint() const override { return {120, 36}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    double mWindowMinN = 0.0, mWindowMaxN = 0.0;
    double mExcessiveN = 0.0;
    double mExamineAtN = 0.0;
    double mFullScaleN = 4.0;
    double mForceN = 0.0;
    double mLevel = 1.0;
};

}  // namespace palpate
