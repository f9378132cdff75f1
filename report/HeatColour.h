#pragma once
// The coverage heat map's colour scale (docs/scoring.md, "Palpation views"), shared by the
// viewport and the PDF report so that both read the same: amber for the lightest examining force
// to deep red for the firmest, none of the tissue's, the rings' or the markers' colours.

#include <QColor>

#include <algorithm>
#include <cmath>

namespace palpate {

inline QColor coverageHeatColour(double forceN, double minN, double maxN) {
    const double t = maxN > minN ? std::clamp((forceN - minN) / (maxN - minN), 0.0, 1.0) : 1.0;
    const auto mix = [t](int a, int b) { return int(std::lround(a + t * (b - a))); };
    return QColor(mix(255, 190), mix(214, 20), mix(70, 40));
}

}  // namespace palpate
