#include "engine/scoring/ExerciseDocument.h"

#include "engine/core/TissueMesh.h"
#include "engine/exercise/ExerciseGeometry.h"
#include "engine/lod/LodNeeds.h"

#include <algorithm>
#include <filesystem>
#include <utility>

namespace palpate {

namespace {

/// The key a problem names: the text before its first colon ("press_targets.targets[0].vertex").
std::string problemKey(const std::string& problem) {
    std::string key = problem.substr(0, problem.find(':'));
    const auto notSpace = [](char c) { return c != ' '; };
    key.erase(key.begin(), std::find_if(key.begin(), key.end(), notSpace));
    key.erase(std::find_if(key.rbegin(), key.rend(), notSpace).base(), key.end());
    return key;
}

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    return !a.empty() && !b.empty() && std::filesystem::equivalent(a, b, ec) && !ec;
}

}  // namespace

ExerciseDocument::ExerciseDocument(ResourceFinder findResource, TouchReach touch)
    : mFindResource(std::move(findResource)), mTouch(touch), mReach(touch) {}

ExerciseDocument::~ExerciseDocument() {
    {
        const std::lock_guard lock(mJobMutex);
        mStop = true;
        mJob.reset();
    }
    mJobReady.notify_all();
    if (mWorker.joinable()) mWorker.join();
}

void ExerciseDocument::setExercise(Exercise exercise) { mExercise = std::move(exercise); }

std::string ExerciseDocument::resolved(const Exercise& exercise, const std::string& path) const {
    return resolveExercisePath(exercise, path, mFindResource);
}

void ExerciseDocument::setDrawnMesh(std::shared_ptr<const TissueMesh> mesh, const std::string& path) {
    mDrawnMesh = std::move(mesh);
    std::error_code ec;
    mDrawnMeshPath = path.empty() ? std::string() : std::filesystem::absolute(path, ec).lexically_normal().string();
}

bool ExerciseDocument::drawnMeshMatches() const {
    if (!mDrawnMesh || mDrawnMeshPath.empty()) return false;
    // The same file read in another unit is another size: its points in mm would not be the exercise's.
    if (!(mDrawnMesh->report().unit == mExercise.meshUnit)) return false;
    return sameFile(meshFile(), mDrawnMeshPath);
}

std::shared_ptr<const TissueMesh> ExerciseDocument::pointsMesh(const std::string& meshFile) {
    if (drawnMeshMatches()) return mDrawnMesh;
    if (meshFile.empty()) return nullptr;
    const std::string key = meshFile + '\n' + mExercise.meshUnit.text();
    if (key != mFileMeshKey) {
        // Loaded once per file and unit: the checks run after every edit.
        mFileMeshKey = key;
        mFileMesh.reset();
        mFileMeshError.clear();
        auto loaded = TissueMesh::load(meshFile, mExercise.meshUnit);
        if (loaded.mesh) mFileMesh = std::make_shared<const TissueMesh>(std::move(*loaded.mesh));
        else mFileMeshError = loaded.error();
    }
    return mFileMesh;
}

ExerciseProblems ExerciseDocument::examine() {
    const Exercise& e = mExercise;
    ExerciseProblems p;
    p.invalid = messagesOf(validateExercise(e));
    if (e.needs)
        for (std::string& text : messagesOf(validateLodNeeds(*e.needs))) p.invalid.push_back(std::move(text));
    const std::string mesh = meshFile();
    p.meshNotFound = !e.meshPath.empty() && mesh.empty();
    p.presetNotFound = !e.tissuePresetPath.empty() && presetFile().empty();

    // Placement: every point must be a vertex of the exercise's mesh (the drawn one, else its file).
    mCheckedOn = pointsMesh(mesh);
    mGeometry.reset();
    if (!mCheckedOn && !mesh.empty()) p.meshError = mFileMeshError;
    if (mCheckedOn) {
        std::string placementError;
        mGeometry = ExerciseGeometry::build(e, *mCheckedOn, placementError);
        // A key a problem names already (a path of fewer than two points) is not named twice.
        const std::string key = problemKey(placementError);
        const bool named = std::any_of(p.invalid.begin(), p.invalid.end(),
                                       [&](const std::string& q) { return problemKey(q) == key; }) ||
                           (key == "tissue_preset" && p.presetNotFound);
        if (!mGeometry && !named) p.placementError = placementError;
    }
    return p;
}

std::uint64_t ExerciseDocument::checkReach(ReachReady ready) {
    if (!mGeometry || !mCheckedOn) return 0;
    ReachJob job;
    job.geometry = mGeometry;
    job.mesh = mCheckedOn;
    job.meshFile = meshFile();
    job.presetFile = presetFile();
    job.ready = std::move(ready);
    std::uint64_t generation = 0;
    {
        const std::lock_guard lock(mJobMutex);
        generation = job.generation = ++mLatest;
        mJob = std::move(job);  // a check asked for earlier and not begun is not needed any more
        if (!mWorker.joinable()) mWorker = std::thread([this] { runWorker(); });
    }
    mJobReady.notify_one();
    return generation;
}

std::uint64_t ExerciseDocument::latestCheck() const {
    const std::lock_guard lock(mJobMutex);
    return mLatest;
}

void ExerciseDocument::runWorker() {
    for (;;) {
        ReachJob job;
        {
            std::unique_lock lock(mJobMutex);
            mJobReady.wait(lock, [this] { return mStop || mJob.has_value(); });
            if (mStop) return;
            job = std::move(*mJob);
            mJob.reset();
        }
        ReachCheckResult result;
        result.generation = job.generation;
        result.geometry = job.geometry;
        {
            const std::lock_guard lock(mReachMutex);
            result.findings = mReach.check(*job.geometry, job.meshFile, job.presetFile, *job.mesh);
        }
        job.ready(std::move(result));
    }
}

std::optional<TouchPresses> ExerciseDocument::pressesOnDrawnMesh(VertexId vertex) {
    if (!mDrawnMesh) return std::nullopt;
    const std::lock_guard lock(mReachMutex);
    const TouchPresses* presses = mReach.presses(meshFile(), presetFile(), *mDrawnMesh, vertex);
    return presses ? std::optional<TouchPresses>(*presses) : std::nullopt;
}

std::optional<ExamineReach> ExerciseDocument::examineReach() {
    const std::shared_ptr<const TissueMesh> mesh = pointsMesh(meshFile());
    if (!mesh) return std::nullopt;
    const std::lock_guard lock(mReachMutex);
    return mReach.examine(meshFile(), presetFile(), *mesh);
}

}  // namespace palpate
