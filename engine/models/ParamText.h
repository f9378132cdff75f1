#pragma once
// Shared wording for the models' parameter validators: "name = value unit must ...".

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace palpate::paramtext {

inline std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

/// Adds "<name> = <v> <unit> must be a positive finite number" when v is not; returns whether it is.
inline bool requirePositive(std::vector<std::string>& errors, double v, const char* name, const char* unit) {
    if (std::isfinite(v) && v > 0.0) return true;
    errors.push_back(std::string(name) + " = " + number(v) + (*unit ? " " : "") + unit +
                     " must be a positive finite number");
    return false;
}

/// Adds "<name> = <v> must be in lo..hi" when v is outside; returns whether it is inside.
inline bool requireRange(std::vector<std::string>& errors, double v, double lo, double hi, const char* name,
                         const char* unit = "") {
    if (std::isfinite(v) && v >= lo && v <= hi) return true;
    errors.push_back(std::string(name) + " = " + number(v) + (*unit ? " " : "") + unit + " must be in " + number(lo) +
                     ".." + number(hi));
    return false;
}

}  // namespace palpate::paramtext
