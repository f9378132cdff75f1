#include "app/gui/HapticSession.h"

#include "device/open/DeviceUri.h"
#include "device/MouseDevice.h"
#include "device/SimulatedDevice.h"
#include "engine/scene/HapticScene.h"
#include "engine/core/SceneTarget.h"
#include "engine/record/RecordedToolDevice.h"

#include <exception>
#include <filesystem>
#include <limits>

namespace palpate {

namespace {

/// Stepped runs hand the recorder's ring (8192 ticks) this many ticks at most between flushes.
constexpr int kRecordingFlushTicks = 4096;

/// A recording names its mesh by an absolute path, so that a replay finds it from anywhere.
std::string absolutePath(const std::string& path) {
    std::error_code ec;
    const auto absolute = std::filesystem::absolute(path, ec);
    return ec ? path : absolute.lexically_normal().string();
}

}  // namespace

HapticSession::HapticSession(LoopMode mode, const HapticLoopDef& def) : mMode(mode), mDef(def) {
    registerReplayDeviceScheme();  // replay:FILE in the Device panel and menus, like the CLI
}

HapticSession::~HapticSession() { stop(); }

std::optional<TissueMesh> HapticSession::loadTissueMesh(const std::string& path, std::string& error,
                                                        const MeshUnit& unit, MeshReport* report) {
    error.clear();
    if (report) *report = MeshReport{};
    try {
        auto loaded = TissueMesh::load(path, unit);
        if (report) *report = loaded.report;
        if (loaded.mesh) return std::move(loaded.mesh);
        for (const auto& e : loaded.report.errors) error += (error.empty() ? "" : "\n") + e;
        if (error.empty()) error = "the mesh could not be loaded";
    } catch (const std::exception& e) {
        // Validated meshes should not throw; if the engine does, it is still no reason to crash the GUI.
        error = e.what();
    }
    // The engine's messages name the file; make sure ours always do.
    if (error.find(path) == std::string::npos) error = path + ": " + error;
    return std::nullopt;
}

std::string HapticSession::loadMesh(const std::string& path, const MeshUnit& unit, bool* deviceFailed) {
    if (deviceFailed) *deviceFailed = false;
    std::string error;
    auto loaded = loadTissueMesh(path, error, unit);
    if (!loaded) return error;
    return loadMesh(path, std::move(*loaded), deviceFailed);
}

std::string HapticSession::loadMesh(const std::string& path, TissueMesh loaded, bool* deviceFailed) {
    if (deviceFailed) *deviceFailed = false;
    std::string error;
    auto mesh = std::make_shared<const TissueMesh>(std::move(loaded));
    if (path != mExercisePath) clearExercisePhysics();  // another mesh: the exercise's inclusion is not on it
    // The loop gets its own copy; ours stays for drawing (the loop may free its scene any time after a swap).
    auto scene = makeScene(*mesh, path, error);
    if (!scene) return path + ": " + error;
    auto device = openDeviceFor(mDeviceUri, *mesh, error);
    if (!device) {
        if (deviceFailed) *deviceFailed = true;
        return error;
    }
    SceneRecord record{mesh, path, scene->id()};
    return handOver(std::move(record), std::move(scene), std::move(device));
}

std::unique_ptr<HapticScene> HapticSession::makeScene(const TissueMesh& mesh, const std::string& path,
                                                      std::string& error) const {
    try {
        auto scene = HapticScene::create(TissueMesh(mesh), mPreset);  // any registry model (docs/models.md)
        if (mExercisePhysics && path == mExercisePath) {
            error = applyExercisePhysics(*mExercisePhysics, *scene);
            if (!error.empty()) return nullptr;
        }
        return scene;
    } catch (const std::exception& e) {
        error = e.what();
        return nullptr;
    }
}

std::string HapticSession::loadExercise(const ExerciseAssets& assets) {
    if (!assets.mesh || !assets.geometry) return assets.exercise.sourcePath + ": the exercise's mesh is not loaded";
    // loadExerciseAssets validated the preset (its errors name the file and the key).
    auto mesh = std::make_shared<const TissueMesh>(*assets.mesh);
    const TissuePreset previousPreset = mPreset;
    auto previousPhysics = mExercisePhysics;
    const std::string previousPath = mExercisePath;
    mPreset = assets.preset;
    mExercisePhysics = assets.geometry;
    mExercisePath = assets.meshPath;
    std::string error;
    auto scene = makeScene(*mesh, assets.meshPath, error);
    std::unique_ptr<HapticDevice> device;
    if (scene) device = openDeviceFor(mDeviceUri, *mesh, error);
    if (!scene || !device) {
        // Nothing changed in the loop: keep what ran before.
        mPreset = previousPreset;
        mExercisePhysics = std::move(previousPhysics);
        mExercisePath = previousPath;
        return assets.meshPath + ": " + error;
    }
    if (mLoop && preset().hapticRateHz != mDef.rateHz) {
        // A new rate needs a new loop (as applyPreset does).
        if (mRecording) stopRecording();
        stop();
        mMouse = nullptr;
        mLoop.reset();
        mPending = SceneRecord{};
    }
    mDef.rateHz = mPreset.hapticRateHz;
    SceneRecord record{mesh, assets.meshPath, scene->id()};
    return handOver(std::move(record), std::move(scene), std::move(device));
}

void HapticSession::clearExercisePhysics() {
    mExercisePhysics.reset();
    mExercisePath.clear();
}

std::string HapticSession::applyPreset(const TissuePreset& preset) {
    const TissuePreset before = mPreset;
    mPreset = preset;
    if (!mLoop) {
        mDef.rateHz = preset.hapticRateHz;
        return {};
    }
    if (preset.hapticRateHz != mDef.rateHz) {
        // The period is fixed for a loop's life: stop this one and start a new one on the same mesh.
        const SceneRecord base = latest();
        mDef.rateHz = preset.hapticRateHz;
        if (mRecording) {
            const std::string problem = stopRecording();
            mRecordingEndedReason = "the haptic rate changed, which needs a new loop: the recording was stopped" +
                                    (problem.empty() ? std::string() : " (" + problem + ")");
        }
        stop();
        mMouse = nullptr;  // deleted with the loop
        mLoop.reset();
        mPending = SceneRecord{};
        return handOverFresh(base);
    }
    const bool needsScene = preset.model.slopeRingMethod != before.model.slopeRingMethod || preset.octree.maxDepth != before.octree.maxDepth ||
                            preset.octree.leafCapacity != before.octree.leafCapacity ||
                            (preset.model.slopeRingMethod != SlopeRingMethod::Coherent && preset.model.slopeRing.ringCount != before.model.slopeRing.ringCount) ||
                            preset.model.kind != before.model.kind ||
                            // The registry models other than volumetric-rings take no parameters at a tick boundary.
                            (!presetUsesSlopeRingParams(preset) && tissuePresetToJson(preset) != tissuePresetToJson(before));
    if (!needsScene) return mLoop->setModelParams(presetModelDef(preset));
    const SceneRecord base = latest();
    std::string error;
    auto scene = makeScene(*base.mesh, base.path, error);
    if (!scene) return base.path + ": " + error;
    const std::uint64_t sceneId = scene->id();
    if (std::string problem = swapSceneInLoop(std::move(scene), base); !problem.empty()) return problem;
    mPending = SceneRecord{base.mesh, base.path, sceneId};  // drawn from its first snapshot
    return {};
}

std::string HapticSession::disconnectDevice() {
    if (!mLoop) return {};
    mMouse = nullptr;  // the loop retires it with this swap
    // A simulated device that was never opened: Disconnected, it reads nothing and renders nothing.
    return swapDeviceInLoop(std::make_unique<SimulatedDevice>(SimTrajectory::PressHold), "(disconnected)");
}

std::string HapticSession::setDevice(const std::string& uri) {
    std::string error;
    if (!mLoop) {
        // No scene to aim at yet: check the URI (scheme, waypoint file) now, open it with the first mesh.
        if (!createDeviceFromUri(uri, error)) return error;
        mDeviceUri = uri;
        return {};
    }
    auto device = openDeviceFor(uri, *latest().mesh, error);
    if (!device) return error;
    auto* mouse = dynamic_cast<MouseDevice*>(device.get());
    if (std::string problem = swapDeviceInLoop(std::move(device), uri); !problem.empty()) return problem;
    mMouse = mouse;
    mHaveTouchTarget = false;
    mDeviceUri = uri;
    return {};
}

std::string HapticSession::restart() {
    if (!mLoop) return "no mesh is loaded";
    return handOverFresh(latest());
}

std::string HapticSession::handOverFresh(const SceneRecord& base) {
    std::string error;
    auto scene = makeScene(*base.mesh, base.path, error);
    if (!scene) return base.path + ": " + error;
    auto device = openDeviceFor(mDeviceUri, *base.mesh, error);
    if (!device) return error;
    SceneRecord record{base.mesh, base.path, scene->id()};
    return handOver(std::move(record), std::move(scene), std::move(device));
}

std::unique_ptr<HapticDevice> HapticSession::openDeviceFor(const std::string& uri, const TissueMesh& mesh,
                                                            std::string& error) {
    auto device = openDeviceUri(uri, error);
    if (!device) return nullptr;
    prepareDevice(*device, mesh);
    return device;
}

void HapticSession::prepareDevice(HapticDevice& deviceRef, const TissueMesh& mesh) {
    HapticDevice* device = &deviceRef;
    // Finite scripts (press, stroke, scan) repeat after a short rest so the window keeps
    // showing palpation; a waypoint file plays once.
    if (auto* simulated = dynamic_cast<SimulatedDevice*>(device))
        if (simulated->trajectory() != SimTrajectory::Waypoints) simulated->setRepeat(1.0);
    aimAtDefaultTarget(*device, mesh, float(presetToolRadiusMm(mPreset)));  // scripts press the side of the mesh
    // The mouse tool starts off the surface (its default target, the origin, may lie inside the
    // tissue): no contact and zero force until the first touch, so the safety filter arms at once.
    if (auto* mouse = dynamic_cast<MouseDevice*>(device)) mouse->setTargetMm(awayPointMm(mesh, nullptr));
}

bool HapticSession::opensSlowly(const std::string& uri) {
    DeviceUri parsed;
    std::string ignored;
    if (!(ignored = parseDeviceUri(uri, parsed)).empty()) return false;
    return parsed.kind == DeviceKind::Falcon || parsed.kind == DeviceKind::SpaceMouse || parsed.kind == DeviceKind::Hid ||
           parsed.kind == DeviceKind::HidPid;
}

std::string HapticSession::setOpenedDevice(const std::string& uri, std::unique_ptr<HapticDevice> device) {
    if (!device) return uri + ": no device";
    if (!mLoop) {
        mDeviceUri = uri;  // opened again with the first mesh
        return {};
    }
    prepareDevice(*device, *latest().mesh);
    auto* mouse = dynamic_cast<MouseDevice*>(device.get());
    if (std::string problem = swapDeviceInLoop(std::move(device), uri); !problem.empty()) return problem;
    mMouse = mouse;
    mHaveTouchTarget = false;
    mDeviceUri = uri;
    return {};
}

glm::vec3 HapticSession::awayPointMm(const TissueMesh& mesh, const glm::vec3* nearMm) const {
    const auto& rest = mesh.restPositionsMm();
    if (rest.empty()) return glm::vec3(0.0f, 0.0f, 1000.0f);
    VertexId best = 0;
    if (nearMm) {
        float bestD2 = std::numeric_limits<float>::max();
        for (VertexId v = 0; v < rest.size(); ++v) {
            const glm::vec3 d = rest[v] - *nearMm;
            const float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
            if (d2 < bestD2) bestD2 = d2, best = v;
        }
    } else {
        best = defaultTargetVertex(mesh);
    }
    return rest[best] + kTouchLiftMm * mesh.restNormals()[best];
}

void HapticSession::setTouchTarget(const glm::vec3& targetMm) {
    if (!mMouse || !mMouse->setTargetMm(targetMm)) return;
    mLastTouchMm = targetMm;
    mHaveTouchTarget = true;
}

void HapticSession::releaseTouch() {
    if (!mMouse || !mLoop) return;
    mMouse->setTargetMm(awayPointMm(*latest().mesh, mHaveTouchTarget ? &mLastTouchMm : nullptr));
}

std::string HapticSession::handOver(SceneRecord record, std::unique_ptr<HapticScene> scene,
                                    std::unique_ptr<HapticDevice> device) {
    auto* mouse = dynamic_cast<MouseDevice*>(device.get());
    mHaveTouchTarget = false;
    if (!mLoop) {
        mMouse = nullptr;
        mLoopDevice = RecordedDevice{mDeviceUri, device->spec()};
        try {
            mLoop = std::make_unique<HapticLoop>(mDef, std::move(scene), std::move(device));
        } catch (const std::exception& e) {
            return std::string("the haptic loop cannot start: ") + e.what();
        }
        mMouse = mouse;
        if (mPauseRequested) mLoop->pause();
        // The first scene is the loop's from its first tick: draw it now.
        mDrawn = std::move(record);
        mObserver.setRestPositions(mDrawn.mesh->restPositionsMm());
        std::string error;
        if (mMode == LoopMode::Threaded && !(error = mLoop->start()).empty()) return error;
        return {};
    }
    // The device first: switching it re-arms the safety filter, so whatever the new scene would
    // make of the old device's last position for a tick never reaches a hand.
    if (std::string problem = swapDeviceInLoop(std::move(device), mDeviceUri); !problem.empty()) return problem;
    mMouse = mouse;
    if (std::string problem = swapSceneInLoop(std::move(scene), record); !problem.empty()) return problem;
    // Drawn from the first snapshot that carries this scene's id (observe()).
    mPending = std::move(record);
    return {};
}

void HapticSession::setPaused(bool paused) {
    mPauseRequested = paused;
    if (!mLoop) return;
    if (paused)
        mLoop->pause();
    else
        mLoop->resume();
}

void HapticSession::step(int ticks) {
    if (!mLoop || mLoop->running()) return;
    for (int i = 0; i < ticks; ++i) {
        mLoop->stepOnce();
        // The writer drains the ring only every 25 ms: stepping runs faster, so hand it over now and then.
        if (mRecording && ++mStepsSinceFlush >= kRecordingFlushTicks) {
            mRecording->flush();
            mStepsSinceFlush = 0;
        }
    }
    // Whoever follows the file (the exercise's live score) sees every stepped tick at once, as the
    // writer's 25 ms drain gives it in real time.
    if (mRecording && ticks > 0) {
        mRecording->flush();
        mStepsSinceFlush = 0;
    }
}

HapticSession::Observation HapticSession::observe() {
    if (!mLoop) return Observation::Nothing;
    const HapticSnapshot& s = mLoop->newestSnapshot();
    if (s.publishCount == mObserved.publishCount) return Observation::Nothing;
    ++mSnapshotsObserved;

    mObserved.publishCount = s.publishCount;
    mObserved.readAt = std::chrono::steady_clock::now();
    mObserved.tick = s.tick;
    mObserved.timeS = s.timeS;
    mObserved.sceneId = s.sceneId;
    mObserved.paused = s.paused;
    mObserved.deviceState = s.deviceState;
    mObserved.safetyPhase = s.safetyPhase;
    mObserved.safetyFlags = s.safetyFlags;
    mObserved.toolTipMm = s.toolTipMm;
    mObserved.commandedForceN = s.commandedForceN;
    mObserved.forceN = s.forceN;
    mObserved.contact = s.contact;
    mObserved.touched = s.touched;
    mObserved.counters = s.counters;
    mObserved.displacedCount = s.displacedCount;
    mObserved.displacedTotal = s.displacedTotal;

    Observation result = Observation::Updated;
    if (mPending.mesh && s.sceneId == mPending.sceneId) {
        mDrawn = std::move(mPending);
        mPending = SceneRecord{};
        mObserver.setRestPositions(mDrawn.mesh->restPositionsMm());
        result = Observation::SceneSwitched;
    }
    // A snapshot of another scene (the one before a switch, or one handed over and already replaced)
    // has vertex ids of another mesh: it moves nothing here.
    if (s.sceneId == mDrawn.sceneId) mObserver.apply(s);
    return result;
}

std::string HapticSession::loopModelName() const {
    if (!mLoop || mLoop->running()) return {};
    return mLoop->scene().model().name();
}

void HapticSession::collectRetired() {
    if (mLoop) mLoop->collectRetired();
}

void HapticSession::stop() {
    stopRecording();  // before the loop stops: the file gets its end chunk while the loop still exists
    if (!mLoop) return;
    mLoop->stop();
    mLoop->collectRetired();
}

std::string HapticSession::startRecording(const std::string& path, const std::string& note) {
    if (mRecording) return "already recording to " + mRecording->path();
    if (!mLoop) return "no mesh is loaded: there is no session to record";
    // The header must describe the scene the loop runs when the recorder attaches; a switch still
    // on its way could land on either side of that tick.
    if (mPending.mesh) return "a new scene is still on its way to the haptic loop; try again in a moment";
    RecordingHeader header = makeRecordingHeader(*mDrawn.mesh, absolutePath(mDrawn.path), mPreset, mLoopDevice.uri,
                                                 mLoopDevice.spec, mDef.safety);
    header.note = note;
    std::string error;
    mRecording = RecordingSession::start(*mLoop, path, header, error);
    if (!mRecording) return error.empty() ? path + ": the recording could not be started" : error;
    mRecordingEndedReason.clear();
    mStepsSinceFlush = 0;
    return {};
}

std::string HapticSession::stopRecording() {
    if (!mRecording) return {};
    std::string problem = mRecording->stop();
    mLastRecordingStats = mRecording->stats();
    mRecording.reset();
    return problem;
}

std::string HapticSession::swapSceneInLoop(std::unique_ptr<HapticScene> scene, const SceneRecord& record) {
    if (!mRecording) return mLoop->swapScene(std::move(scene));
    return mRecording->swapScene(std::move(scene), describeScene(*record.mesh, absolutePath(record.path), mPreset));
}

std::string HapticSession::swapDeviceInLoop(std::unique_ptr<HapticDevice> device, const std::string& uri) {
    RecordedDevice description{uri, device->spec()};
    std::string problem = mRecording ? mRecording->swapDevice(std::move(device), description)
                                     : mLoop->swapDevice(std::move(device));
    if (problem.empty()) mLoopDevice = std::move(description);
    return problem;
}

}  // namespace palpate
