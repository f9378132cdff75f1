#include "engine/scoring/ExerciseReachCheck.h"

#include "device/HapticDevice.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/exercise/ExerciseKind.h"
#include "engine/scene/TissuePreset.h"

#include <cmath>
#include <exception>
#include <system_error>

namespace palpate {

namespace {

/// A file's modification time as text ("" when it cannot be read): a changed file rebuilds the probe.
std::string stamp(const std::string& path) {
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(path, ec);
    return ec ? std::string() : std::to_string(time.time_since_epoch().count());
}

}  // namespace

const TouchPresses* ExerciseReachCheck::presses(const std::string& meshFile, const std::string& presetFile,
                                                const TissueMesh& mesh, VertexId vertex) {
    if (meshFile.empty() || presetFile.empty()) return nullptr;  // a problem says so already
    const std::string key = meshFile + '\n' + stamp(meshFile) + '\n' + mesh.report().unit.text() + '\n' + presetFile +
                            '\n' + stamp(presetFile);
    if (key != mKey) {
        mKey = key;
        mProbe.reset();
        mPresses.clear();
        mError.clear();
        PresetLoadResult loaded;
        try {
            loaded = loadTissuePreset(presetFile);
        } catch (const std::exception& e) {
            loaded.errors.push_back(presetFile + ": " + e.what());
        }
        std::string error = loaded.errors.empty() ? std::string("not a tissue preset") : loaded.errors.front();
        // Press targets have no physics of their own: the scene is the tissue's as it is.
        if (loaded.preset) mProbe = TouchForceProbe::create(mesh, *loaded.preset, nullptr, mTouch, error);
        if (!mProbe) mError = error;
    }
    if (!mProbe) return nullptr;
    auto it = mPresses.find(vertex);
    if (it == mPresses.end()) it = mPresses.emplace(vertex, mProbe->presses(vertex)).first;
    return it->second.forcesN.empty() ? nullptr : &it->second;
}

void ExerciseReachCheck::unknown(ReachFinding::Subject subject, std::vector<ReachFinding>& out) const {
    if (mError.empty()) return;
    ReachFinding f;
    f.kind = ReachFinding::Kind::Unknown;
    f.subject = subject;
    f.why = mError;
    out.push_back(f);
}

std::vector<ReachFinding> ExerciseReachCheck::check(const ExerciseGeometry& geometry, const std::string& meshFile,
                                                    const std::string& presetFile, const TissueMesh& mesh) {
    std::vector<ReachFinding> out;
    bandFindings(geometry, meshFile, presetFile, mesh, out);
    targetFindings(geometry, meshFile, presetFile, mesh, out);
    lumpFindings(geometry, meshFile, presetFile, mesh, out);
    if (exerciseKind(geometry.exercise().type).palpation())
        coverageFindings(geometry.exercise(), meshFile, presetFile, mesh, out);
    return out;
}

void ExerciseReachCheck::bandFindings(const ExerciseGeometry& geometry, const std::string& meshFile,
                                      const std::string& presetFile, const TissueMesh& mesh,
                                      std::vector<ReachFinding>& out) {
    const auto& vertices = geometry.pathVertices();
    if (vertices.empty()) return;
    // The band at every path point, as a target's window (pressed, not slid: a slide at the same
    // depth renders about the same force, plus friction).
    PressTarget band;
    band.forceMinN = geometry.exercise().trace.forceMinN;
    band.forceMaxN = geometry.exercise().trace.forceMaxN;
    ReachFinding tooSoft, between;
    tooSoft.kind = ReachFinding::Kind::BandTooSoft;
    between.kind = ReachFinding::Kind::BandBetweenSteps;
    tooSoft.subject = between.subject = ReachFinding::Subject::Band;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const TouchPresses* p = presses(meshFile, presetFile, mesh, vertices[i]);
        if (!p) return unknown(ReachFinding::Subject::Band, out);
        const TargetReach reach = judgeTarget(band, p->forcesN, mTouch);
        if (reach.reachable) continue;
        if (reach.belowForceN) {
            between.points.push_back(i);
            continue;
        }
        if (tooSoft.points.empty() || reach.maxForceN < tooSoft.leastN) {
            tooSoft.leastN = reach.maxForceN;
            tooSoft.suggested = comfortableWindow(p->forcesN, mTouch);
        }
        tooSoft.target = reach;
        tooSoft.points.push_back(i);
    }
    if (!tooSoft.points.empty()) out.push_back(tooSoft);
    else if (!between.points.empty()) out.push_back(between);
}

void ExerciseReachCheck::targetFindings(const ExerciseGeometry& geometry, const std::string& meshFile,
                                        const std::string& presetFile, const TissueMesh& mesh,
                                        std::vector<ReachFinding>& out) {
    for (std::size_t i = 0; i < geometry.targets().size(); ++i) {
        const ResolvedTarget& target = geometry.targets()[i];
        const TouchPresses* p = presses(meshFile, presetFile, mesh, target.vertex);
        if (!p) return unknown(ReachFinding::Subject::Targets, out);
        ReachFinding f;
        f.subject = ReachFinding::Subject::Targets;
        f.item = i;
        f.target = judgeTarget(target.def, p->forcesN, mTouch);
        if (f.target.reachable) continue;
        f.kind = f.target.belowForceN ? ReachFinding::Kind::TargetBetweenSteps : ReachFinding::Kind::TargetTooSoft;
        if (!f.target.belowForceN) f.suggested = comfortableWindow(p->forcesN, mTouch);
        out.push_back(f);
    }
}

void ExerciseReachCheck::lumpFindings(const ExerciseGeometry& geometry, const std::string& meshFile,
                                      const std::string& presetFile, const TissueMesh& mesh,
                                      std::vector<ReachFinding>& out) {
    // A device renders up to its maximum force; the nominal one of a desktop device (DeviceSpec).
    const double deviceMaxN = DeviceSpec{}.maxForceN;
    const double excessiveN = geometry.exercise().excessiveForceN;
    for (std::size_t i = 0; i < geometry.lumps().size(); ++i) {
        const ResolvedLump& lump = geometry.lumps()[i];
        const TouchPresses* p = presses(meshFile, presetFile, mesh, lump.vertex);
        if (!p) return unknown(ReachFinding::Subject::Lumps, out);
        ReachFinding f;
        f.subject = ReachFinding::Subject::Lumps;
        f.item = i;
        f.lump = judgeLump(lump.def, *p, mTouch);
        f.excessiveN = excessiveN;
        f.deviceMaxN = deviceMaxN;
        if (!f.lump.mouseFeels) {
            f.kind = std::isfinite(f.lump.engageDepthMm) ? ReachFinding::Kind::LumpTooDeep
                                                         : ReachFinding::Kind::LumpNeverEngaged;
            out.push_back(f);
        }
        if (f.lump.forceN && *f.lump.forceN >= excessiveN) {
            f.kind = ReachFinding::Kind::LumpExcessive;
            out.push_back(f);
        } else if (f.lump.forceN && *f.lump.forceN > deviceMaxN) {
            f.kind = ReachFinding::Kind::LumpBeyondDevice;
            out.push_back(f);
        }
    }
}

std::optional<ExamineReach> ExerciseReachCheck::examine(const std::string& meshFile, const std::string& presetFile,
                                                        const TissueMesh& mesh) {
    std::vector<std::vector<double>> forces;
    for (const VertexId v : examinePoints(mesh.restPositionsMm())) {
        const TouchPresses* p = presses(meshFile, presetFile, mesh, v);
        if (!p) return std::nullopt;
        forces.push_back(p->forcesN);
    }
    return judgeExamining(forces, mTouch, mTouch.defaultDepthMm);
}

void ExerciseReachCheck::coverageFindings(const Exercise& exercise, const std::string& meshFile,
                                          const std::string& presetFile, const TissueMesh& mesh,
                                          std::vector<ReachFinding>& out) {
    const std::optional<ExamineReach> reach = examine(meshFile, presetFile, mesh);
    if (!reach) return unknown(ReachFinding::Subject::Coverage, out);
    if (exercise.coverage.minForceN <= reach->deepestN) return;
    ReachFinding f;
    f.kind = ReachFinding::Kind::CoverageTooSoft;
    f.subject = ReachFinding::Subject::Coverage;
    f.examine = *reach;
    out.push_back(f);
}

}  // namespace palpate
