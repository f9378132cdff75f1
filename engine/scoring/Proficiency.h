#pragma once
// Proficiency-based progression (docs/scoring.md, "Proficiency"): a standard set from experts'
// sessions of an exercise, per metric the expert mean and SD and a pass mark two SD to the worse
// side of the mean; a trainee's session passes when every deciding metric reaches its mark, and
// the trainee is proficient after two passing sessions in a row. Works from metric names and
// values, so it holds for every exercise type and every metric the rubric knows.

#include "engine/exercise/Exercise.h"
#include "engine/scoring/Staircase.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct ProficiencyParams {
    std::size_t minExpertSessions = 2;  ///< fewer: no standard (an SD needs two)
    double markSd = 2.0;                ///< the mark is this many SD from the expert mean
    int passesInARow = 2;               ///< passing sessions in a row that make a trainee proficient
};

struct MetricStandard {
    std::string metric;           ///< the metric's name
    double mean = 0.0;            ///< over the expert sessions that measured it
    double sd = 0.0;              ///< sample SD (n - 1)
    double passMark = 0.0;        ///< mean - k SD (higher is better) or mean + k SD (lower is better)
    bool higherIsBetter = true;   ///< from the rubric line: full marks above zero marks
    bool deciding = false;        ///< rubric weight > 0 and measured by enough experts
    std::size_t expertSessions = 0;  ///< how many expert sessions measured it
    /// Whether `value` reaches the mark (at the mark passes).
    bool passes(double value) const { return higherIsBetter ? value >= passMark : value <= passMark; }
};

struct ProficiencyStandard {
    std::vector<MetricStandard> metrics;  ///< in the rubric's metric order
    std::size_t expertSessions = 0;
    std::string problem;                  ///< why there is no standard; "" when there is one
    bool valid() const { return problem.empty(); }
    const MetricStandard* find(const std::string& metric) const;
};

/// The standard from the experts' metric values of one exercise. Direction and deciding from
/// effectiveRubric(exercise); metrics the exercise's type does not measure, or that have no name
/// the rubric knows, are left out.
ProficiencyStandard buildProficiencyStandard(const Exercise& exercise, const std::vector<MetricValues>& experts,
                                             const ProficiencyParams& params = {});

struct SessionVerdict {
    bool passed = false;  ///< every deciding metric passed
    /// Per metric of the standard: passed, or nullopt when the session did not measure it (a
    /// deciding metric not measured fails the session).
    std::vector<std::pair<std::string, std::optional<bool>>> metrics;
    int consecutivePasses = 0;  ///< passing sessions in a row ending with this one
};

SessionVerdict judgeSession(const ProficiencyStandard& standard, const MetricValues& session);

struct ProficiencyProgress {
    std::vector<SessionVerdict> sessions;  ///< in the order given (oldest first)
    /// The index of the session that made the trainee proficient (the last of the first run of
    /// passesInARow passing sessions); nullopt: not (yet) proficient.
    std::optional<std::size_t> proficientAt;
    bool proficient() const { return proficientAt.has_value(); }
    int consecutivePasses() const { return sessions.empty() ? 0 : sessions.back().consecutivePasses; }
};

/// The verdict on each session in order and when the trainee became proficient. Empty with an
/// invalid standard.
ProficiencyProgress judgeSessions(const ProficiencyStandard& standard, const std::vector<MetricValues>& sessions,
                                  const ProficiencyParams& params = {});

}  // namespace palpate
