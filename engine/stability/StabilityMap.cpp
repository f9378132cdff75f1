#include "engine/stability/StabilityMap.h"

#include "engine/stability/StabilityBounds.h"

#include <algorithm>
#include <cmath>

namespace palpate {

namespace {
double between(const StabilityAxis& axis, double lo, double hi) {
    return axis.logScale ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
}
}  // namespace

double axisValue(const StabilityAxis& axis, int i, int count) {
    const double t = count > 1 ? double(i) / double(count - 1) : 0.5;
    if (axis.logScale) return axis.minValue * std::pow(axis.maxValue / axis.minValue, t);
    return axis.minValue + (axis.maxValue - axis.minValue) * t;
}

StabilityMap runStabilityMap(const StabilityMapSpec& spec, const StabilityMapDef& def) {
    StabilityMap map;
    map.model = spec.model;
    map.description = spec.description;
    map.criterion = spec.criterion;
    map.derivedFormula = spec.derivedFormula;
    map.x = spec.x;
    map.y = spec.y;
    const int columns = std::max(1, def.columns), rows = std::max(1, def.rows);
    map.cells.reserve(std::size_t(columns * rows));
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            StabilityCell cell;
            cell.x = axisValue(spec.x, i, columns);
            cell.y = axisValue(spec.y, j, rows);
            const CellOutcome outcome = spec.runCell(cell.x, cell.y);
            cell.bounded = outcome.bounded;
            cell.growth = outcome.growth;
            cell.passivityRatio = spec.passivityRatio ? spec.passivityRatio(cell.x, cell.y) : std::nan("");
            map.cells.push_back(cell);
        }

    // The measured boundary: per column, the bracket [lowest y, highest y] is narrowed around the
    // change from bounded to divergent (stable below, as every model here is along its y axis).
    for (int i = 0; i < columns; ++i) {
        StabilityBoundaryPoint point;
        point.x = axisValue(spec.x, i, columns);
        point.derivedY = spec.derivedBoundaryY(point.x);
        if (std::isfinite(point.derivedY)) map.hasDerivedBoundary = true;
        double lo = spec.y.minValue, hi = spec.y.maxValue;
        if (spec.runCell(point.x, hi).bounded) {
            point.measuredY = kNoBound;
        } else if (!spec.runCell(point.x, lo).bounded) {
            point.measuredY = lo;
        } else {
            for (int b = 0; b < def.bisections; ++b) {
                const double mid = between(spec.y, lo, hi);
                (spec.runCell(point.x, mid).bounded ? lo : hi) = mid;
            }
            point.measuredY = between(spec.y, lo, hi);
        }
        if (!std::isfinite(point.derivedY) && !std::isfinite(point.measuredY)) point.relativeGap = 0.0;
        else if (!std::isfinite(point.derivedY) || !std::isfinite(point.measuredY)) point.relativeGap = kNoBound;
        else point.relativeGap = std::abs(point.measuredY - point.derivedY) / point.derivedY;
        map.relativeGap = std::max(map.relativeGap, point.relativeGap);
        map.boundary.push_back(point);
    }
    constexpr int kCurveSamples = 200;
    for (int s = 0; s <= kCurveSamples; ++s) {
        const double x = axisValue(spec.x, s, kCurveSamples + 1);
        map.derivedCurve.emplace_back(x, spec.derivedBoundaryY(x));
    }
    if (spec.passivityRatio) {
        constexpr int kGrid = 120;
        map.hasPassivity = true;
        map.passivityFormula = spec.passivityFormula;
        map.passivity.columns = map.passivity.rows = kGrid;
        map.passivity.ratio.reserve(std::size_t(kGrid * kGrid));
        for (int j = 0; j < kGrid; ++j)
            for (int i = 0; i < kGrid; ++i)
                map.passivity.ratio.push_back(spec.passivityRatio(axisValue(spec.x, i, kGrid),
                                                                  axisValue(spec.y, j, kGrid)));
    }
    return map;
}

}  // namespace palpate
