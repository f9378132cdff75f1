#include "engine/lod/LodNeeds.h"

#include <cmath>
#include <sstream>

namespace palpate {

namespace {

std::string text(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

/// One value in (0, hi]: zero is as absurd as negative (no model has zero error or zero cost).
void positiveUpTo(Problems& errors, const std::string& key, double value, double hi, const char* unit) {
    if (!std::isfinite(value)) errors.push_back({key, -1, -1, key + ": must be a finite number, got " + text(value)});
    else if (value <= 0.0) errors.push_back({key, -1, -1, key + ": must be above 0, got " + text(value) + unit});
    else if (value > hi)
        errors.push_back({key, -1, -1,
                          key + ": " + text(value) + unit + " is absurd (at most " + text(hi) + unit + ")"});
}

}  // namespace

Problems validateLodNeeds(const LodNeeds& needs, const std::string& keyPrefix) {
    Problems errors;
    positiveUpTo(errors, keyPrefix + "max_error", needs.maxErrorFraction, kMaxLodErrorFraction, "");
    positiveUpTo(errors, keyPrefix + "budget_us", needs.budgetUs, kMaxLodBudgetUs, " us");
    return errors;
}

}  // namespace palpate
