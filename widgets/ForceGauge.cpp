#include "widgets/ForceGauge.h"

#include <QLocale>
#include <QPainter>
#include <QPen>

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {
const QColor kExamineColour(30, 100, 210);
}  // namespace

ForceGauge::ForceGauge(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setAccessibleName(tr("Force gauge"));
}

void ForceGauge::setWindow(double minN, double maxN) {
    mWindowMinN = std::isfinite(minN) ? minN : 0.0;
    mWindowMaxN = std::isfinite(maxN) ? maxN : 0.0;
    update();
}

void ForceGauge::setExcessiveN(double excessiveN) {
    mExcessiveN = std::isfinite(excessiveN) ? excessiveN : 0.0;
    update();
}

void ForceGauge::setFullScaleN(double fullScaleN) {
    if (std::isfinite(fullScaleN) && fullScaleN > 0.0) mFullScaleN = fullScaleN;
    update();
}

void ForceGauge::setForceN(double forceN) {
    mForceN = std::isfinite(forceN) ? std::max(0.0, forceN) : 0.0;
    update();
}

int ForceGauge::zone() const {
    if (mExcessiveN > 0.0 && mForceN >= mExcessiveN) return 2;
    // Without a window, a press below the force that examines is below what is asked.
    if (mWindowMaxN <= mWindowMinN) return mExamineAtN > 0.0 && mForceN < mExamineAtN ? -1 : 0;
    if (mForceN < mWindowMinN) return -1;
    if (mForceN > mWindowMaxN) return 1;
    return 0;
}

QColor ForceGauge::barColour() const {
    switch (zone()) {
        case -1: return QColor(240, 170, 40);
        case 0: return QColor(60, 190, 80);
        case 1: return QColor(240, 120, 40);
        default: return QColor(220, 40, 40);
    }
}

double ForceGauge::shownScaleN() const {
    if (mWindowMaxN <= mWindowMinN) return std::max({mFullScaleN, mExcessiveN * 1.15, 0.1});
    double scaleN = 2.0 * mWindowMaxN;
    // An excessive level not far beyond the window shares the scale (1-2 N and 3 N: 0-4 N).
    if (mExcessiveN > 0.0 && mExcessiveN * 1.15 <= 3.0 * mWindowMaxN) scaleN = std::max(scaleN, mExcessiveN * 1.15);
    return std::max(scaleN, 0.1);
}

void ForceGauge::setExamineAtN(double examineAtN) {
    if (examineAtN == mExamineAtN) return;
    mExamineAtN = examineAtN;
    setToolTip(examineAtN > 0.0 ? tr("The blue line: a press at or above %1 N counts as examined.")
                                      .arg(QLocale().toString(examineAtN, 'g', 3))
                                : QString());
    update();
}

void ForceGauge::setLevel(double level) {
    const double clamped = std::clamp(level, 0.0, 1.0);
    if (clamped == mLevel) return;
    mLevel = clamped;
    update();
}

QString ForceGauge::readingText() const { return tr("%1 N").arg(locale().toString(mForceN, 'f', 2)); }

void ForceGauge::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, true);
    if (mLevel <= 0.0) {
        // Faded out: the trainee knows it is gone on purpose, not broken.
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(rect(), Qt::AlignCenter, tr("Force gauge faded out: feel the force"));
        return;
    }
    p.setOpacity(mLevel);
    const double scaleN = shownScaleN();
    const bool excessiveShown = mExcessiveN > 0.0 && mExcessiveN < scaleN;
    const QRectF track(4.0, 4.0, width() - 8.0, height() - 22.0);
    const auto xOf = [&](double forceN) { return track.left() + track.width() * std::clamp(forceN / scaleN, 0.0, 1.0); };

    p.setPen(Qt::NoPen);
    p.setBrush(palette().color(QPalette::Base).darker(115));
    p.drawRoundedRect(track, 3, 3);
    if (mWindowMaxN > mWindowMinN) {
        p.setBrush(QColor(60, 190, 80, 90));
        p.drawRect(QRectF(QPointF(xOf(mWindowMinN), track.top()), QPointF(xOf(mWindowMaxN), track.bottom())));
    }
    if (excessiveShown) {
        p.setBrush(QColor(220, 40, 40, 70));
        p.drawRect(QRectF(QPointF(xOf(mExcessiveN), track.top()), QPointF(track.right(), track.bottom())));
    }
    const bool examineShown = mExamineAtN > 0.0 && mExamineAtN < scaleN;
    // The bar: inset, so that the window's shading stays visible around it.
    const QRectF bar(QPointF(track.left(), track.top() + track.height() * 0.25),
                     QPointF(xOf(mForceN), track.bottom() - track.height() * 0.25));
    p.setBrush(barColour());
    p.drawRect(bar);
    if (examineShown) {
        // Over the bar: the line the press must pass to examine the tissue under it.
        p.setPen(QPen(kExamineColour, 2.0, Qt::DashLine));
        p.drawLine(QPointF(xOf(mExamineAtN), track.top()), QPointF(xOf(mExamineAtN), track.bottom()));
    }

    p.setPen(palette().color(QPalette::WindowText));
    QFont font = p.font();
    font.setPixelSize(10);
    p.setFont(font);
    const double labelY = track.bottom() + 14.0;
    // Labels that would run into the one before (or into the reading at the right) are left out.
    const double readingLeft = track.right() - 60.0;
    double lastRight = -1e9;
    const auto label = [&](double forceN, const QString& text) {
        const double x = xOf(forceN);
        const double halfWidth = p.fontMetrics().horizontalAdvance(text) / 2.0 + 2.0;
        if (x - halfWidth < lastRight || x + halfWidth > readingLeft) return;
        lastRight = x + halfWidth;
        p.drawLine(QPointF(x, track.bottom()), QPointF(x, track.bottom() + 3.0));
        p.drawText(QRectF(x - 30.0, track.bottom() + 3.0, 60.0, 14.0), Qt::AlignHCenter | Qt::AlignTop, text);
    };
    if (mWindowMaxN > mWindowMinN) {
        label(mWindowMinN, locale().toString(mWindowMinN, 'g', 3));
        label(mWindowMaxN, locale().toString(mWindowMaxN, 'g', 3));
    }
    if (examineShown) {
        p.setPen(kExamineColour);
        label(mExamineAtN, locale().toString(mExamineAtN, 'g', 3));
        p.setPen(palette().color(QPalette::WindowText));
    }
    if (excessiveShown) label(mExcessiveN, locale().toString(mExcessiveN, 'g', 3));
    // The reading, right-aligned under the track's end, clear of the window's labels.
    font.setBold(true);
    p.setFont(font);
    p.drawText(QRectF(readingLeft, labelY - 11.0, 60.0, 14.0), Qt::AlignRight | Qt::AlignTop, readingText());
    if (mExcessiveN > 0.0 && !excessiveShown) {
        // Off this scale: the track's right end says where excessive begins.
        font.setBold(false);
        p.setFont(font);
        p.setPen(QColor(200, 30, 30));
        p.drawText(track.adjusted(0.0, 0.0, -4.0, 0.0), Qt::AlignRight | Qt::AlignVCenter,
                   tr("excessive ≥ %1 N ▸").arg(locale().toString(mExcessiveN, 'g', 3)));
    }
}

}  // namespace palpate
