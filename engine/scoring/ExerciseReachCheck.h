#pragma once
// Whether the mouse can do what an exercise asks of it on its tissue (docs/scoring.md, "Reachable
// targets"): each press target's window, the trace's band at every path point, each lump (with
// the mouse and with a device) and the examining force. The force probe is built once per mesh and
// preset file (and their modification times) and its presses kept per vertex, so checking again
// after an edit probes only vertices not probed yet. Findings carry their figures; the editor words
// them in the user's language. Qt-free, not real-time (a probe runs a stepped loop per vertex).

#include "engine/scoring/TargetReachability.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

/// One thing the mouse (or a device) cannot do, or cannot be known to do.
struct ReachFinding {
    enum class Kind {
        Unknown,             ///< the probe could not be built: `subject` and `why`
        TargetBetweenSteps,  ///< target `item`'s window lies between two wheel steps' forces
        TargetTooSoft,       ///< target `item`'s window is above the deepest press's force
        BandTooSoft,         ///< the trace's band is above the deepest press's force at `points`
        BandBetweenSteps,    ///< the band lies between two wheel steps' forces at `points`
        LumpNeverEngaged,    ///< lump `item`'s top is never reached by the sinking surface
        LumpTooDeep,         ///< lump `item` is felt deeper than the mouse presses
        LumpExcessive,       ///< feeling lump `item` takes at least the excessive force
        LumpBeyondDevice,    ///< feeling lump `item` takes more than a desktop device renders
        CoverageTooSoft,     ///< the deepest press gives less than the examining force
    };
    enum class Subject { Targets, Band, Lumps, Coverage };

    Kind kind = Kind::Unknown;
    Subject subject = Subject::Targets;
    std::size_t item = 0;                  ///< the target or lump, from 0
    std::string why;                       ///< Unknown: why the probe could not be built
    TargetReach target;                    ///< the target's or the band's judgement
    std::optional<ForceWindow> suggested;  ///< a window met two wheel steps past the default press
    std::vector<std::size_t> points;       ///< Band*: the path points, from 0
    double leastN = 0.0;                   ///< BandTooSoft: the least deepest force along the path
    LumpReach lump;
    double excessiveN = 0.0;  ///< LumpExcessive
    double deviceMaxN = 0.0;  ///< LumpBeyondDevice
    ExamineReach examine;     ///< CoverageTooSoft
};

class ExerciseReachCheck {
public:
    explicit ExerciseReachCheck(TouchReach touch) : mTouch(std::move(touch)) {}

    const TouchReach& touch() const { return mTouch; }
    /// What pressing at `vertex` of `mesh` (read from meshFile) gives on the preset in presetFile;
    /// null when a file is not given or the probe cannot be built (then error() says why).
    const TouchPresses* presses(const std::string& meshFile, const std::string& presetFile, const TissueMesh& mesh,
                                VertexId vertex);
    /// How firmly the mouse examines the tissue (judgeExamining over examinePoints); nullopt when
    /// not known (error() says why when the probe failed).
    std::optional<ExamineReach> examine(const std::string& meshFile, const std::string& presetFile,
                                        const TissueMesh& mesh);
    /// Why the last probe could not be built ("" when it was, or no files were given).
    const std::string& error() const { return mError; }

    /// The findings of `geometry`, placed on `mesh`: the band first, then the targets, the lumps
    /// and (for a palpation exercise) the examining force.
    std::vector<ReachFinding> check(const ExerciseGeometry& geometry, const std::string& meshFile,
                                    const std::string& presetFile, const TissueMesh& mesh);

private:
    void bandFindings(const ExerciseGeometry& geometry, const std::string& meshFile, const std::string& presetFile,
                      const TissueMesh& mesh, std::vector<ReachFinding>& out);
    void targetFindings(const ExerciseGeometry& geometry, const std::string& meshFile, const std::string& presetFile,
                        const TissueMesh& mesh, std::vector<ReachFinding>& out);
    void lumpFindings(const ExerciseGeometry& geometry, const std::string& meshFile, const std::string& presetFile,
                      const TissueMesh& mesh, std::vector<ReachFinding>& out);
    void coverageFindings(const Exercise& exercise, const std::string& meshFile, const std::string& presetFile,
                          const TissueMesh& mesh, std::vector<ReachFinding>& out);
    /// An Unknown finding of `subject` when the probe failed with a reason.
    void unknown(ReachFinding::Subject subject, std::vector<ReachFinding>& out) const;

    TouchReach mTouch;
    std::string mKey;  ///< the files, the mesh's unit and the files' times the probe was built for
    std::unique_ptr<TouchForceProbe> mProbe;
    std::map<VertexId, TouchPresses> mPresses;
    std::string mError;
};

}  // namespace palpate
