#pragma once
// A stability map: a model's two governing parameters swept over a grid, each cell run long enough
// to tell bounded from divergent, with the derived boundary drawn over the measured one (found by
// bisection along the y axis, one row per x value), and where the map has one, the passivity of
// the rendered stiffness over the same axes (docs/stability.md, "Rendered stiffness and
// passivity"). The models' cell runners are in StabilityModels.h; this file knows none of them.

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace palpate {

struct StabilityAxis {
    std::string name;      ///< e.g. "dt" or "|m1|"
    std::string unit;      ///< e.g. "s" or "mm/N"
    double minValue = 0.0;
    double maxValue = 1.0;
    bool logScale = true;  ///< cells spaced evenly in log (positive ranges spanning decades)
};

/// What one cell's run concluded.
struct CellOutcome {
    bool bounded = true;
    /// The criterion's figure: energy (or oscillation) at the end over the beginning; NaN/inf when
    /// the state went non-finite.
    double growth = 0.0;
};

/// One model's map: its axes, how a cell runs, and the derived boundary (stable for y below it).
struct StabilityMapSpec {
    std::string model;
    std::string description;         ///< what is swept and what is held fixed
    std::string criterion;           ///< how a cell is classified
    std::string derivedFormula;      ///< the boundary as written in docs/stability.md
    StabilityAxis x, y;
    std::function<CellOutcome(double x, double y)> runCell;
    /// y on the boundary for this x; kNoBound (infinity) when every y is stable.
    std::function<double(double x)> derivedBoundaryY;
    /// Passivity over the same axes: K_eq / K_device at (x, y), > 1 where the device cannot render
    /// the set passively (SampledPassivity.h); empty when the map has none.
    std::function<double(double x, double y)> passivityRatio;
    std::string passivityFormula;  ///< what passivityRatio computes, as in docs/stability.md
};

struct StabilityMapDef {
    int columns = 20;    ///< grid cells along x (and boundary rows: one bisection per column)
    int rows = 20;       ///< grid cells along y
    int bisections = 12; ///< halvings of the log-y bracket per column (12: ~0.1 % of a decade span)
};

struct StabilityCell {
    double x = 0.0, y = 0.0;
    bool bounded = true;
    double growth = 0.0;
    double passivityRatio = 0.0;  ///< K_eq / K_device (NaN when the map has no passivity)
};

/// The passivity ratio sampled on a finer grid than the cells, for drawing its boundary.
struct PassivityGrid {
    int columns = 0, rows = 0;
    std::vector<double> ratio;  ///< row-major: y outer, x inner; values at axisValue(i, columns), (j, rows)
};

/// The boundary at one x: derived, measured (infinity when no y in range diverges), and their gap.
struct StabilityBoundaryPoint {
    double x = 0.0;
    double derivedY = 0.0;
    double measuredY = 0.0;
    double relativeGap = 0.0;  ///< |measured - derived| / derived; 0 when both are unbounded
};

struct StabilityMap {
    std::string model, description, criterion, derivedFormula;
    StabilityAxis x, y;
    std::vector<StabilityCell> cells;               ///< row-major: y outer, x inner
    std::vector<StabilityBoundaryPoint> boundary;   ///< one per column
    /// The derived boundary sampled finely along x (x, y), for drawing; y infinite where unbounded.
    std::vector<std::pair<double, double>> derivedCurve;
    bool hasDerivedBoundary = false;                ///< false: unconditionally stable (no line)
    double relativeGap = 0.0;                       ///< largest over the columns
    bool hasPassivity = false;                      ///< the spec gave a passivity ratio
    std::string passivityFormula;
    PassivityGrid passivity;  ///< 120 x 120 when hasPassivity
};

/// The i-th of `count` values spanning the axis (log or linear).
double axisValue(const StabilityAxis& axis, int i, int count);

/// Runs the grid and the bisections. Cells run one after another on the calling thread.
StabilityMap runStabilityMap(const StabilityMapSpec& spec, const StabilityMapDef& def = {});

}  // namespace palpate
