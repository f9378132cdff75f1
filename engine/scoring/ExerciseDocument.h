#pragma once
// The exercise the editor edits, apart from the editor's widgets (docs/scoring.md, "The exercise
// editor"): the exercise, where its files are, the mesh its points are checked on (the drawn one
// when it is the exercise's, else its file), the problems a session would fail on, and whether the
// mouse can do what it asks (ExerciseReachCheck). The reach check runs on a worker thread of its
// own, so the editor stays responsive while a vertex is probed for the first time; only the
// latest check asked for runs, and its findings say which check they answer. Qt-free.

#include "engine/exercise/Exercise.h"
#include "engine/exercise/ExerciseFile.h"
#include "engine/scoring/ExerciseReachCheck.h"

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace palpate {

class ExerciseGeometry;
class TissueMesh;

/// What a trainee session would fail on, as found by ExerciseDocument::examine(). The messages of
/// the exercise's own values come from the engine's validators; the rest carry what the editor
/// needs to word them.
struct ExerciseProblems {
    std::vector<std::string> invalid;  ///< validateExercise's and the level-of-detail needs' messages
    bool meshNotFound = false;         ///< a mesh is named but not found
    bool presetNotFound = false;       ///< a tissue preset is named but not found
    std::string meshError;             ///< the mesh was found but could not be read
    /// A point not on the mesh, "" when every point is placed (or a problem above names its key).
    std::string placementError;

    bool any() const {
        return !invalid.empty() || meshNotFound || presetNotFound || !meshError.empty() || !placementError.empty();
    }
};

/// The findings of one reach check, and which check they answer.
struct ReachCheckResult {
    std::uint64_t generation = 0;                      ///< checkReach()'s return value
    std::shared_ptr<const ExerciseGeometry> geometry;  ///< what was checked (the findings' items)
    std::vector<ReachFinding> findings;
};

class ExerciseDocument {
public:
    /// Called on the worker thread when a check is done; a later check may have been asked for.
    using ReachReady = std::function<void(ReachCheckResult result)>;

    /// `findResource` finds files under resources/; `touch` is how deep the mouse presses.
    ExerciseDocument(ResourceFinder findResource, TouchReach touch);
    /// Waits for a running check to end (a probe is not interrupted) and stops the worker.
    ~ExerciseDocument();
    ExerciseDocument(const ExerciseDocument&) = delete;
    ExerciseDocument& operator=(const ExerciseDocument&) = delete;

    const Exercise& exercise() const { return mExercise; }
    void setExercise(Exercise exercise);
    /// The absolute path of a file `exercise` names (beside its file, under resources/, or
    /// absolute); "" when it cannot be found.
    std::string resolved(const Exercise& exercise, const std::string& path) const;
    std::string meshFile() const { return resolved(mExercise, mExercise.meshPath); }
    std::string presetFile() const { return resolved(mExercise, mExercise.tissuePresetPath); }

    /// The mesh the viewport draws and its file: picks refer to it.
    void setDrawnMesh(std::shared_ptr<const TissueMesh> mesh, const std::string& path);
    const std::shared_ptr<const TissueMesh>& drawnMesh() const { return mDrawnMesh; }
    /// Its absolute path ("" for none).
    const std::string& drawnMeshPath() const { return mDrawnMeshPath; }
    /// True when the drawn mesh is the exercise's mesh, read in the exercise's unit.
    bool drawnMeshMatches() const;

    /// Checks the exercise: its values, its files and where its points are on its mesh (loaded
    /// once per file and unit when the drawn mesh is not it). After it, geometry() is the
    /// exercise placed on checkMesh() (null when it cannot be placed).
    ExerciseProblems examine();
    const std::shared_ptr<const ExerciseGeometry>& geometry() const { return mGeometry; }
    /// The mesh the points were checked on by the last examine(); null when there is none.
    const std::shared_ptr<const TissueMesh>& checkMesh() const { return mCheckedOn; }

    /// Starts checking the reach of examine()'s geometry on the worker thread; `ready` gets the
    /// findings unless a later check was asked for before this one began. Returns the check's
    /// generation. Nothing is started (and 0 returned) when there is no geometry.
    std::uint64_t checkReach(ReachReady ready);
    /// The generation of the latest check asked for (0 before the first).
    std::uint64_t latestCheck() const;

    /// What pressing at `vertex` of the drawn mesh gives on the exercise's tissue (waits for a
    /// running check: the probe is shared); null when it cannot be had.
    std::optional<TouchPresses> pressesOnDrawnMesh(VertexId vertex);
    /// How firmly the mouse examines the exercise's tissue on its mesh (waits as above).
    std::optional<ExamineReach> examineReach();
    const TouchReach& touch() const { return mTouch; }

private:
    struct ReachJob {
        std::uint64_t generation = 0;
        std::shared_ptr<const ExerciseGeometry> geometry;
        std::shared_ptr<const TissueMesh> mesh;
        std::string meshFile, presetFile;
        ReachReady ready;
    };
    /// The mesh the points are checked on (loading the exercise's file when the drawn mesh is not it).
    std::shared_ptr<const TissueMesh> pointsMesh(const std::string& meshFile);
    void runWorker();

    ResourceFinder mFindResource;
    TouchReach mTouch;
    Exercise mExercise;
    std::shared_ptr<const TissueMesh> mDrawnMesh;
    std::string mDrawnMeshPath;
    std::shared_ptr<const TissueMesh> mFileMesh;  ///< the exercise's mesh file when it is not drawn
    std::string mFileMeshKey;                     ///< its file and unit: either changed reloads it
    std::string mFileMeshError;
    std::shared_ptr<const TissueMesh> mCheckedOn;
    std::shared_ptr<const ExerciseGeometry> mGeometry;

    std::mutex mReachMutex;  ///< guards mReach: the worker's checks and the synchronous probes
    ExerciseReachCheck mReach;

    mutable std::mutex mJobMutex;  ///< guards the fields below
    std::condition_variable mJobReady;
    std::optional<ReachJob> mJob;
    std::uint64_t mLatest = 0;
    bool mStop = false;
    std::thread mWorker;  ///< started by the first check
};

}  // namespace palpate
