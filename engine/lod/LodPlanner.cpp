#include "engine/lod/LodPlanner.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

namespace palpate {

bool meetsError(const LodCandidate& c, const LodNeeds& needs) {
    return std::isfinite(c.errorFraction) && c.errorFraction <= needs.maxErrorFraction;
}

bool meetsBudget(const LodCandidate& c, const LodNeeds& needs) {
    return std::isfinite(c.tickUs) && c.tickUs <= needs.budgetUs;
}

bool cheaperThan(const LodCandidate& a, const LodCandidate& b) {
    return std::tie(a.vertices, a.rings, a.tickUs, a.errorFraction) < std::tie(b.vertices, b.rings, b.tickUs, b.errorFraction);
}

double shortfall(const LodCandidate& c, const LodNeeds& needs) {
    if (!std::isfinite(c.errorFraction) || !std::isfinite(c.tickUs)) return std::numeric_limits<double>::infinity();
    return std::max(0.0, c.errorFraction / needs.maxErrorFraction - 1.0) + std::max(0.0, c.tickUs / needs.budgetUs - 1.0);
}

std::string describeCandidate(const LodCandidate& c) {
    std::ostringstream s;
    s << "level " << c.level << " (" << c.vertices << " vertices), " << c.rings << (c.rings == 1 ? " ring" : " rings")
      << ": error " << c.errorFraction << ", tick " << c.tickUs << " us";
    return s.str();
}

LodPlan planLod(const std::vector<LodCandidate>& candidates, const LodNeeds& needs) {
    LodPlan plan;
    if (const auto problems = validateLodNeeds(needs); !problems.empty()) {
        plan.error = problems.front().message;
        return plan;
    }
    if (candidates.empty()) {
        plan.error = "no candidates were measured";
        return plan;
    }
    std::ostringstream targets;
    targets << "error <= " << needs.maxErrorFraction << " and tick <= " << needs.budgetUs << " us";
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const LodCandidate& c = candidates[i];
        if (meetsError(c, needs) && meetsBudget(c, needs)) {
            ++plan.feasibleCount;
            if (!plan.chosen || cheaperThan(c, candidates[*plan.chosen])) plan.chosen = i;
        }
    }
    std::ostringstream why;
    if (plan.chosen) {
        plan.feasible = true;
        const LodCandidate& c = candidates[*plan.chosen];
        why << "chose " << describeCandidate(c) << ": the coarsest level with the fewest rings of the "
            << plan.feasibleCount << " of " << candidates.size() << " candidates that meet " << targets.str() << ".";
        // Say what the next cheaper configurations lack, so that the choice can be checked: the
        // most rings below the chosen count on this level, and the best of the next coarser level.
        const LodCandidate* fewerRings = nullptr;
        const LodCandidate* coarser = nullptr;
        for (const LodCandidate& o : candidates) {
            if (o.vertices == c.vertices && o.rings < c.rings && (!fewerRings || o.rings > fewerRings->rings)) fewerRings = &o;
            if (o.vertices < c.vertices && (!coarser || o.vertices > coarser->vertices ||
                                            (o.vertices == coarser->vertices && shortfall(o, needs) < shortfall(*coarser, needs))))
                coarser = &o;
        }
        auto lacks = [&](const LodCandidate& o) {
            std::ostringstream s;
            if (!o.note.empty()) return "not measured (" + o.note + ")";
            if (!meetsError(o, needs)) s << "error " << o.errorFraction << " > " << needs.maxErrorFraction;
            if (!meetsError(o, needs) && !meetsBudget(o, needs)) s << ", ";
            if (!meetsBudget(o, needs)) s << "tick " << o.tickUs << " us > " << needs.budgetUs << " us";
            return s.str();
        };
        if (fewerRings)
            why << " With " << fewerRings->rings << (fewerRings->rings == 1 ? " ring" : " rings") << ": " << lacks(*fewerRings) << ".";
        if (coarser)
            why << " The coarser level " << coarser->level << " (" << coarser->vertices << " vertices) at best, with "
                << coarser->rings << (coarser->rings == 1 ? " ring" : " rings") << ": " << lacks(*coarser) << ".";
        plan.reason = why.str();
        return plan;
    }
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const double s = shortfall(candidates[i], needs);
        if (s < best || (s == best && plan.closest && cheaperThan(candidates[i], candidates[*plan.closest]))) {
            best = s;
            plan.closest = i;
        }
    }
    why << "nothing meets " << targets.str() << " (" << candidates.size() << " candidates).";
    if (plan.closest) {
        const LodCandidate& c = candidates[*plan.closest];
        why << " Closest: " << describeCandidate(c) << " (";
        const bool errorOk = meetsError(c, needs), tickOk = meetsBudget(c, needs);
        if (!errorOk) why << "error " << c.errorFraction / needs.maxErrorFraction << "x the target";
        if (!errorOk && !tickOk) why << ", ";
        if (!tickOk) why << "tick " << c.tickUs / needs.budgetUs << "x the budget";
        why << ").";
    } else {
        why << " No candidate was measured successfully.";
    }
    plan.reason = why.str();
    return plan;
}

}  // namespace palpate
