#pragma once
// Adaptive difficulty for detect-lumps trials (docs/scoring.md, "Staircase"): a transformed up-down
// staircase over one lump property (contrast or depth). After `down` passed trials in a row the
// level moves one step harder, after `up` failed ones one step easier, always between the easiest
// and the hardest level; the levels where the track turns (reversals) estimate the trainee's
// threshold. A 2-down-1-up staircase settles where a trial passes with probability 0.707.

#include "engine/exercise/Exercise.h"
#include "engine/exercise/ScoreReport.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

struct StaircaseTrial {
    double level = 0.0;  ///< the level the trial was run at
    bool passed = false;
};

/// "" when the definition can drive a staircase, else what is wrong with it (naming the key:
/// "staircase.step: ...").
std::string staircaseDefProblem(const StaircaseDef& def);
/// "contrast", "depth_mm".
const char* staircaseParameterName(StaircaseDef::Parameter parameter);
std::optional<StaircaseDef::Parameter> parseStaircaseParameter(const std::string& name);

class Staircase {
public:
    /// Reversals the threshold estimate averages by default.
    static constexpr std::size_t kEstimateReversals = 6;

    /// Starts at def.start, clamped into [hardest, easiest]. The definition must be valid
    /// (staircaseDefProblem); an invalid one throws std::invalid_argument with the problem.
    explicit Staircase(const StaircaseDef& def);

    const StaircaseDef& def() const { return mDef; }
    /// The level the next trial is run at.
    double level() const { return mLevel; }
    int consecutivePasses() const { return mPasses; }
    int consecutiveFails() const { return mFails; }
    const std::vector<StaircaseTrial>& history() const { return mHistory; }
    /// The level at each reversal: the level of the trial after which the track turned.
    const std::vector<double>& reversals() const { return mReversals; }

    /// Records a trial run at level() and moves the level when the rule says so.
    void record(bool passed);
    /// Mean of the levels at the last `count` reversals (fewer when there are fewer); nullopt
    /// before the first reversal.
    std::optional<double> thresholdEstimate(std::size_t count = kEstimateReversals) const;

    /// Takes a changed definition (the exercise was edited): the level is clamped into its range,
    /// the counts of passes and fails in a row restart, the history and reversals are kept. The
    /// same definition changes nothing.
    void redefine(const StaircaseDef& def);

    /// The state as small JSON text: the definition, the level, the counts, history and reversals.
    std::string toJson(int indent = -1) const;
    /// The state back from toJson's text; nullopt with `error` naming the key and the problem.
    static std::optional<Staircase> fromJson(const std::string& text, std::string& error);

private:
    /// +1 when a harder level is a higher number (depth), -1 when lower (contrast).
    double harderSign() const { return mDef.hardest > mDef.easiest ? 1.0 : -1.0; }
    double clampLevel(double level) const;

    StaircaseDef mDef;
    double mLevel = 0.0;
    int mPasses = 0, mFails = 0;
    int mLastMove = 0;  ///< +1 the last move went harder, -1 easier, 0 none yet
    std::vector<StaircaseTrial> mHistory;
    std::vector<double> mReversals;
};

/// The exercise with every lump's staircase property (contrast or depth_mm) set to `level`.
Exercise exerciseAtLevel(const Exercise& exercise, double level);
/// The level an exercise's lumps are at for this staircase's property: nullopt when it has no
/// lumps or they differ (then it is not at one level).
std::optional<double> staircaseLevelOf(const Exercise& exercise, const StaircaseDef& def);

/// Metric values by name (`palpate-cli score --json`'s "metrics"); nullopt: not measured.
using MetricValues = std::map<std::string, std::optional<double>>;
/// The measured metrics of a report, by name.
MetricValues metricValues(const ScoreReport& report);

/// Whether a session is a passed staircase trial: every lump found ("sensitivity" 1) and no false
/// alarm ("false_alarms" 0). nullopt when the values lack either: then it is not a trial.
std::optional<bool> staircaseTrialPassed(const MetricValues& metrics);
std::optional<bool> staircaseTrialPassed(const ScoreReport& report);

}  // namespace palpate
