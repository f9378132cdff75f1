#include "engine/exercise/LumpDetection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace palpate {

namespace {

/// Minimum-cost assignment of rows to columns of a square matrix (Kuhn-Munkres with potentials,
/// O(n^3)); returns the column of each row.
std::vector<int> assign(const std::vector<std::vector<double>>& cost) {
    const int n = int(cost.size());
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0);
    std::vector<int> rowOfColumn(n + 1, 0), way(n + 1, 0);
    for (int i = 1; i <= n; ++i) {
        rowOfColumn[0] = i;
        int j0 = 0;
        std::vector<double> minv(n + 1, inf);
        std::vector<bool> used(n + 1, false);
        do {
            used[j0] = true;
            const int i0 = rowOfColumn[j0];
            double delta = inf;
            int j1 = 0;
            for (int j = 1; j <= n; ++j) {
                if (used[j]) continue;
                const double reduced = cost[i0 - 1][j - 1] - u[i0] - v[j];
                if (reduced < minv[j]) {
                    minv[j] = reduced;
                    way[j] = j0;
                }
                if (minv[j] < delta) {
                    delta = minv[j];
                    j1 = j;
                }
            }
            for (int j = 0; j <= n; ++j) {
                if (used[j]) {
                    u[rowOfColumn[j]] += delta;
                    v[j] -= delta;
                } else {
                    minv[j] -= delta;
                }
            }
            j0 = j1;
        } while (rowOfColumn[j0] != 0);
        do {
            const int j1 = way[j0];
            rowOfColumn[j0] = rowOfColumn[j1];
            j0 = j1;
        } while (j0 != 0);
    }
    std::vector<int> columnOfRow(n, -1);
    for (int j = 1; j <= n; ++j)
        if (rowOfColumn[j] > 0) columnOfRow[rowOfColumn[j] - 1] = j - 1;
    return columnOfRow;
}

}  // namespace

DetectionResult scoreDetection(const std::vector<HiddenLump>& lumps, const std::vector<glm::dvec3>& findingsMm,
                               const DetectionDef& def) {
    DetectionResult r;
    const std::size_t nl = lumps.size(), nf = findingsMm.size();
    r.findingOfLump.assign(nl, -1);
    r.localisationMm.assign(nl, -1.0);
    if (nl > 0 && nf > 0) {
        // A pair out of reach costs more than every pair in reach together, so the assignment
        // first makes as many pairs in reach as it can, then the shortest ones.
        double reachSum = 0.0;
        for (const HiddenLump& lump : lumps) reachSum += lump.radiusMm + def.toleranceMm;
        const double outOfReach = 1.0 + 2.0 * reachSum;
        const std::size_t n = std::max(nl, nf);
        std::vector<std::vector<double>> cost(n, std::vector<double>(n, outOfReach));
        for (std::size_t l = 0; l < nl; ++l)
            for (std::size_t f = 0; f < nf; ++f) {
                const double d = glm::length(findingsMm[f] - lumps[l].centreMm);
                if (d <= lumps[l].radiusMm + def.toleranceMm) cost[l][f] = d;
            }
        const std::vector<int> columnOfRow = assign(cost);
        for (std::size_t l = 0; l < nl; ++l) {
            const int f = columnOfRow[l];
            if (f < 0 || std::size_t(f) >= nf || cost[l][std::size_t(f)] >= outOfReach) continue;
            r.findingOfLump[l] = f;
            r.localisationMm[l] = cost[l][std::size_t(f)];
            ++r.hits;
        }
    }
    r.misses = nl - r.hits;
    r.falseAlarms = nf - r.hits;
    if (nl > 0) r.sensitivity = double(r.hits) / double(nl);
    if (nf > 0) r.positivePredictive = double(r.hits) / double(nf);
    return r;
}

}  // namespace palpate
