#include "engine/scoring/Staircase.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace palpate {

namespace {

using Json = nlohmann::json;

constexpr const char* kFormat = "palpate-staircase";
constexpr int kVersion = 1;

std::string number(double v) { return Json(v).dump(); }

}  // namespace

std::string staircaseDefProblem(const StaircaseDef& def) {
    auto finite = [](double v) { return std::isfinite(v); };
    if (!finite(def.step) || def.step <= 0.0) return "staircase.step: " + number(def.step) + " must be > 0";
    if (!finite(def.easiest)) return "staircase.easiest: must be a finite number";
    if (!finite(def.hardest)) return "staircase.hardest: must be a finite number";
    if (def.easiest == def.hardest)
        return "staircase.hardest: equals staircase.easiest (" + number(def.easiest) + "): there is no range to move in";
    if (!finite(def.start) || def.start < std::min(def.easiest, def.hardest) ||
        def.start > std::max(def.easiest, def.hardest))
        return "staircase.start: " + number(def.start) + " is outside [" + number(std::min(def.easiest, def.hardest)) +
               ", " + number(std::max(def.easiest, def.hardest)) + "]";
    if (def.down < 1) return "staircase.down: " + std::to_string(def.down) + " must be >= 1";
    if (def.up < 1) return "staircase.up: " + std::to_string(def.up) + " must be >= 1";
    return {};
}

const char* staircaseParameterName(StaircaseDef::Parameter parameter) {
    return parameter == StaircaseDef::Parameter::DepthMm ? "depth_mm" : "contrast";
}

std::optional<StaircaseDef::Parameter> parseStaircaseParameter(const std::string& name) {
    if (name == "contrast") return StaircaseDef::Parameter::Contrast;
    if (name == "depth_mm") return StaircaseDef::Parameter::DepthMm;
    return std::nullopt;
}

Staircase::Staircase(const StaircaseDef& def) : mDef(def) {
    if (const std::string problem = staircaseDefProblem(def); !problem.empty()) throw std::invalid_argument(problem);
    mLevel = clampLevel(def.start);
}

double Staircase::clampLevel(double level) const {
    return std::clamp(level, std::min(mDef.easiest, mDef.hardest), std::max(mDef.easiest, mDef.hardest));
}

void Staircase::record(bool passed) {
    mHistory.push_back({mLevel, passed});
    int move = 0;
    if (passed) {
        mFails = 0;
        if (++mPasses >= mDef.down) move = +1, mPasses = 0;
    } else {
        mPasses = 0;
        if (++mFails >= mDef.up) move = -1, mFails = 0;
    }
    if (move == 0) return;
    // A turn of the track, even one the clamp makes invisible (a fail at the hardest level after
    // moves harder): the level it turned at is what the estimate averages.
    if (mLastMove != 0 && move != mLastMove) mReversals.push_back(mLevel);
    mLastMove = move;
    mLevel = clampLevel(mLevel + move * harderSign() * mDef.step);
}

std::optional<double> Staircase::thresholdEstimate(std::size_t count) const {
    if (mReversals.empty() || count == 0) return std::nullopt;
    const std::size_t n = std::min(count, mReversals.size());
    double sum = 0.0;
    for (std::size_t i = mReversals.size() - n; i < mReversals.size(); ++i) sum += mReversals[i];
    return sum / double(n);
}

void Staircase::redefine(const StaircaseDef& def) {
    if (const std::string problem = staircaseDefProblem(def); !problem.empty()) throw std::invalid_argument(problem);
    // The same definition (every trial's session passes it again) keeps the run of passes or
    // fails: only an edited one restarts it.
    if (def.parameter == mDef.parameter && def.start == mDef.start && def.step == mDef.step &&
        def.easiest == mDef.easiest && def.hardest == mDef.hardest && def.down == mDef.down && def.up == mDef.up)
        return;
    mDef = def;
    mLevel = clampLevel(mLevel);
    mPasses = mFails = 0;
}

std::string Staircase::toJson(int indent) const {
    Json j;
    j["format"] = kFormat;
    j["version"] = kVersion;
    j["parameter"] = staircaseParameterName(mDef.parameter);
    j["start"] = mDef.start;
    j["step"] = mDef.step;
    j["easiest"] = mDef.easiest;
    j["hardest"] = mDef.hardest;
    j["down"] = mDef.down;
    j["up"] = mDef.up;
    j["level"] = mLevel;
    j["consecutive_passes"] = mPasses;
    j["consecutive_fails"] = mFails;
    j["last_move"] = mLastMove;
    Json history = Json::array();
    for (const StaircaseTrial& t : mHistory) history.push_back({{"level", t.level}, {"passed", t.passed}});
    j["history"] = std::move(history);
    j["reversals"] = mReversals;
    return j.dump(indent);
}

std::optional<Staircase> Staircase::fromJson(const std::string& text, std::string& error) {
    const std::string where = "staircase state: ";
    Json j;
    try {
        j = Json::parse(text);
    } catch (const Json::parse_error& e) {
        error = where + "not JSON (" + e.what() + ")";
        return std::nullopt;
    }
    if (!j.is_object()) {
        error = where + "is not a JSON object";
        return std::nullopt;
    }
    static const std::set<std::string> known = {"format", "version", "parameter", "start", "step", "easiest",
                                                "hardest", "down", "up", "level", "consecutive_passes",
                                                "consecutive_fails", "last_move", "history", "reversals"};
    for (const auto& item : j.items())
        if (!known.count(item.key())) {
            error = where + item.key() + ": unknown key";
            return std::nullopt;
        }
    auto fail = [&](const std::string& key, const std::string& problem) {
        error = where + key + ": " + problem;
        return std::nullopt;
    };
    auto need = [&](const std::string& key) -> const Json* {
        if (!j.contains(key)) return nullptr;
        return &j.at(key);
    };
    auto numberAt = [&](const std::string& key, double& out) -> bool {
        const Json* v = need(key);
        if (!v) return error = where + key + ": missing", false;
        if (!v->is_number()) return error = where + key + ": must be a number, is " + v->dump(), false;
        out = v->get<double>();
        if (!std::isfinite(out)) return error = where + key + ": must be finite", false;
        return true;
    };
    auto intAt = [&](const std::string& key, int& out) -> bool {
        const Json* v = need(key);
        if (!v) return error = where + key + ": missing", false;
        if (!v->is_number_integer()) return error = where + key + ": must be a whole number, is " + v->dump(), false;
        out = v->get<int>();
        return true;
    };
    const Json* format = need("format");
    if (!format || !format->is_string() || format->get<std::string>() != kFormat)
        return fail("format", std::string("must be \"") + kFormat + "\"");
    int version = 0;
    if (!intAt("version", version)) return std::nullopt;
    if (version != kVersion)
        return fail("version", std::to_string(version) + " is not supported (this build reads " +
                                   std::to_string(kVersion) + ")");
    const Json* parameter = need("parameter");
    if (!parameter || !parameter->is_string()) return fail("parameter", "missing or not text");
    const auto p = parseStaircaseParameter(parameter->get<std::string>());
    if (!p) return fail("parameter", "'" + parameter->get<std::string>() + "' is neither contrast nor depth_mm");
    StaircaseDef def;
    def.parameter = *p;
    double level = 0.0;
    int passes = 0, fails = 0, lastMove = 0;
    if (!numberAt("start", def.start) || !numberAt("step", def.step) || !numberAt("easiest", def.easiest) ||
        !numberAt("hardest", def.hardest) || !intAt("down", def.down) || !intAt("up", def.up) ||
        !numberAt("level", level) || !intAt("consecutive_passes", passes) || !intAt("consecutive_fails", fails) ||
        !intAt("last_move", lastMove))
        return std::nullopt;
    if (const std::string problem = staircaseDefProblem(def); !problem.empty()) {
        error = where + problem;
        return std::nullopt;
    }
    Staircase s(def);
    if (level < std::min(def.easiest, def.hardest) || level > std::max(def.easiest, def.hardest))
        return fail("level", number(level) + " is outside the range of easiest and hardest");
    if (passes < 0 || passes >= def.down) return fail("consecutive_passes", std::to_string(passes) + " is not in [0, down)");
    if (fails < 0 || fails >= def.up) return fail("consecutive_fails", std::to_string(fails) + " is not in [0, up)");
    if (passes > 0 && fails > 0) return fail("consecutive_fails", "passes and fails in a row cannot both be counting");
    if (lastMove < -1 || lastMove > 1) return fail("last_move", "must be -1, 0 or 1");
    s.mLevel = level;
    s.mPasses = passes;
    s.mFails = fails;
    s.mLastMove = lastMove;
    const Json* history = need("history");
    if (!history || !history->is_array()) return fail("history", "missing or not an array");
    for (std::size_t i = 0; i < history->size(); ++i) {
        const Json& t = history->at(i);
        const std::string key = "history[" + std::to_string(i) + "]";
        if (!t.is_object() || !t.contains("level") || !t.at("level").is_number() || !t.contains("passed") ||
            !t.at("passed").is_boolean() || t.size() != 2)
            return fail(key, "must be {\"level\": number, \"passed\": true|false}");
        s.mHistory.push_back({t.at("level").get<double>(), t.at("passed").get<bool>()});
    }
    const Json* reversals = need("reversals");
    if (!reversals || !reversals->is_array()) return fail("reversals", "missing or not an array");
    for (std::size_t i = 0; i < reversals->size(); ++i) {
        if (!reversals->at(i).is_number()) return fail("reversals[" + std::to_string(i) + "]", "must be a number");
        s.mReversals.push_back(reversals->at(i).get<double>());
    }
    if (s.mReversals.size() > s.mHistory.size())
        return fail("reversals", "more reversals (" + std::to_string(s.mReversals.size()) + ") than trials (" +
                                     std::to_string(s.mHistory.size()) + ")");
    error.clear();
    return s;
}

Exercise exerciseAtLevel(const Exercise& exercise, double level) {
    Exercise out = exercise;
    const StaircaseDef::Parameter parameter = exercise.detectLumps.staircase
                                                  ? exercise.detectLumps.staircase->parameter
                                                  : StaircaseDef::Parameter::Contrast;
    for (LumpDef& lump : out.detectLumps.lumps) {
        if (parameter == StaircaseDef::Parameter::DepthMm) lump.depthMm = level;
        else lump.contrast = level;
    }
    return out;
}

MetricValues metricValues(const ScoreReport& report) {
    MetricValues out;
    for (const MetricResult& m : report.metrics)
        out[std::string(metricName(m.metric))] = m.measured ? std::optional<double>(m.value) : std::nullopt;
    return out;
}

std::optional<bool> staircaseTrialPassed(const MetricValues& metrics) {
    const auto sensitivity = metrics.find("sensitivity");
    const auto falseAlarms = metrics.find("false_alarms");
    if (sensitivity == metrics.end() || falseAlarms == metrics.end() || !sensitivity->second || !falseAlarms->second)
        return std::nullopt;
    return *sensitivity->second >= 1.0 && *falseAlarms->second == 0.0;
}

std::optional<bool> staircaseTrialPassed(const ScoreReport& report) { return staircaseTrialPassed(metricValues(report)); }

std::optional<double> staircaseLevelOf(const Exercise& exercise, const StaircaseDef& def) {
    const auto& lumps = exercise.detectLumps.lumps;
    if (lumps.empty()) return std::nullopt;
    auto levelOf = [&](const LumpDef& l) { return def.parameter == StaircaseDef::Parameter::Contrast ? l.contrast : l.depthMm; };
    const double level = levelOf(lumps.front());
    for (const LumpDef& l : lumps)
        if (levelOf(l) != level) return std::nullopt;
    return level;
}

}  // namespace palpate
