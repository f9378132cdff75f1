#pragma once
// The GUI's side of the haptic loop (docs/architecture.md, docs/haptic-loop.md): builds scenes and devices off
// the haptic thread, hands them to the loop as commands, and observes its snapshots. The loop owns
// the model; this class never steps it while the thread runs. For drawing it keeps its own copy of
// every mesh it handed over, tagged with the scene id, so nothing it draws can be freed under it.
// Qt-free; every member is called from one thread (the GUI's).

#include "app/gui/SnapshotObserver.h"
#include "engine/loop/HapticLoop.h"
#include "engine/scene/TissuePreset.h"
#include "engine/core/TissueMesh.h"
#include "engine/record/RecordingSession.h"
#include "engine/scoring/ExerciseSession.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace palpate {

class MouseDevice;

enum class LoopMode {
    Threaded,  ///< the loop's own real-time thread (the interactive window)
    Stepped,   ///< ticks run on the caller's thread when asked (screenshots, tests): deterministic
};

/// What the GUI last read from a snapshot, without the vertex data.
struct ObservedLoop {
    std::uint64_t publishCount = 0;  ///< 0: nothing observed yet
    /// When the GUI read it. The loop publishes every tick, so the newest snapshot is at most a
    /// tick old when read: ticks over these times give the achieved rate without the GUI's delays.
    std::chrono::steady_clock::time_point readAt{};
    std::uint64_t tick = 0;
    double timeS = 0.0;
    std::uint64_t sceneId = 0;
    bool paused = false;
    DeviceState deviceState = DeviceState::Disconnected;
    SafetyPhase safetyPhase = SafetyPhase::HoldOff;
    std::uint32_t safetyFlags = 0;
    glm::vec3 toolTipMm{0.0f};
    glm::vec3 commandedForceN{0.0f};
    glm::vec3 forceN{0.0f};
    bool contact = false;
    VertexId touched = kNoVertex;
    LoopCounters counters;
    std::uint32_t displacedCount = 0;
    std::uint32_t displacedTotal = 0;
};

class HapticSession {
public:
    /// The device of stepped runs, screenshots and tests (deterministic, scripted).
    static constexpr const char* kDefaultDeviceUri = "sim:stroke";
    /// The interactive window's device when no hardware is present: the viewport steers the tool.
    static constexpr const char* kInteractiveDeviceUri = "mouse:";
    /// Where releaseTouch() and a fresh mouse device put the tool: this far out along the normal.
    static constexpr float kTouchLiftMm = 20.0f;

    explicit HapticSession(LoopMode mode, const HapticLoopDef& def = {});
    /// Stops the thread before anything it uses goes away.
    ~HapticSession();
    HapticSession(const HapticSession&) = delete;
    HapticSession& operator=(const HapticSession&) = delete;

    /// Loads and validates a mesh whose coordinates are in `unit` (scaled to mm; docs/meshes.md,
    /// "Units"). Never throws; on failure `error` names the file and every problem, and `report`
    /// (if given) is what the loader found (its size, to suggest another unit).
    static std::optional<TissueMesh> loadTissueMesh(const std::string& path, std::string& error,
                                                    const MeshUnit& unit = kMillimetres, MeshReport* report = nullptr);

    /// Loads `path` and builds its scene here, then makes it the loop's scene with a fresh device
    /// aimed at it. The first scene creates the loop (and, threaded, starts its thread) and is drawn
    /// at once; later ones are drawn from the first snapshot that shows them. On failure the current
    /// scene stays and the error (naming the file) is returned; "" on success. When the failure
    /// was the device's (not plugged in, a bad recording), `deviceFailed` (if given) is set.
    /// `unit`: the file's (the window remembers it per file).
    std::string loadMesh(const std::string& path, const MeshUnit& unit = kMillimetres, bool* deviceFailed = nullptr);
    /// The same with a mesh already loaded from `path` (the window loaded it to look at its size first).
    std::string loadMesh(const std::string& path, TissueMesh mesh, bool* deviceFailed = nullptr);
    /// Makes an exercise's mesh, tissue preset and physics (find the lump's inclusion) the loop's
    /// scene, with a fresh device aimed at it. The physics stays with every later scene of that
    /// mesh (restart, a new preset) until another mesh is loaded or clearExercisePhysics(). The
    /// preset becomes this session's (a recording's header carries it). "" or why not.
    std::string loadExercise(const ExerciseAssets& assets);
    void clearExercisePhysics();
    /// The exercise whose physics the scenes carry (null: none).
    const std::shared_ptr<const ExerciseGeometry>& exercisePhysics() const { return mExercisePhysics; }
    /// Opens a device for `uri`, aims it at the current mesh and swaps it in. Before the first mesh
    /// the URI is only checked and remembered. "" or an error naming the URI; the old device stays.
    std::string setDevice(const std::string& uri);
    /// Makes `preset` (already validated) the parameters of every scene from now on. The running
    /// scene gets them at a tick boundary when the model can take them as they are; a new model (or
    /// new parameters of a registry model that takes no slope-ring parameters),
    /// ring count of the paper's methods or octree means a new scene of the same mesh; a new
    /// haptic rate means a new loop. "" or why not.
    std::string applyPreset(const TissuePreset& preset);
    const TissuePreset& preset() const { return mPreset; }
    /// Swaps in a device already opened elsewhere (a hardware device opened on a worker thread: a
    /// Falcon's firmware upload takes seconds). It is aimed at the current mesh like setDevice's.
    /// Before the first mesh only the URI is remembered. "" or why not; the old device stays then.
    std::string setOpenedDevice(const std::string& uri, std::unique_ptr<HapticDevice> device);
    /// Whether opening `uri` may block (real hardware), so that the GUI opens it off its thread.
    static bool opensSlowly(const std::string& uri);
    /// Swaps in a device that is not connected (zero force, state Disconnected) until setDevice.
    std::string disconnectDevice();
    /// A fresh device of the same URI and a fresh scene of the same mesh ("" or why not).
    std::string restart();
    /// Pause: the model gets no tool position (the tissue relaxes, zero force); the thread runs on.
    void setPaused(bool paused);
    bool pauseRequested() const { return mPauseRequested; }

    /// Touch mode (the viewport steers a mouse: device). True while the loop's device is one this
    /// session made for "mouse:" (until the next device swap, disconnect or restart).
    bool touchAvailable() const { return mMouse != nullptr; }
    /// The radius of the tool the running preset's model touches with (0: a point; otherwise the
    /// device's position is the sphere's centre).
    double toolRadiusMm() const { return presetToolRadiusMm(mPreset); }
    /// Moves the mouse device's tool tip to `targetMm` (scene frame, mm). Ignored without a mouse
    /// device or for a non-finite target. Wait-free towards the haptic thread.
    void setTouchTarget(const glm::vec3& targetMm);
    /// Lifts the tool off the surface: kTouchLiftMm along the rest normal of the rest vertex nearest
    /// the last target (before any touch: the vertex the scripted devices aim at), so contact ends.
    void releaseTouch();

    /// Stepped mode: runs `ticks` ticks now, on this thread. Ignored while the thread runs.
    void step(int ticks);
    enum class Observation {
        Nothing,     ///< no new snapshot
        Updated,     ///< new snapshot applied to view()
        SceneSwitched,  ///< the loop now runs the newest scene handed over: drawnMesh() changed
    };
    /// Reads the newest snapshot if one was published since the last call and applies it.
    Observation observe();
    /// Deletes the scenes and devices the loop has let go of (call periodically).
    void collectRetired();
    /// Stops the recording (if any) and joins the haptic thread (window close). Idempotent.
    void stop();

    // --- session recording (docs/recording.md): the GUI's Recorder dock ---
    /// Records the loop into `path` (created). The recorder attaches at the next tick, which
    /// restarts the session state (tissue at rest, safety filter re-armed: the force ramps in
    /// again) so that the file replays from its header alone. From here on scene and device swaps
    /// go through the recording so that the file describes them. "" or why not (no mesh, a scene
    /// switch still on its way to the loop, the file cannot be created: the message names it).
    std::string startRecording(const std::string& path, const std::string& note = {});
    /// Detaches, writes the end chunk, syncs and closes. "" or the first write error. Idempotent.
    std::string stopRecording();
    bool recording() const { return mRecording != nullptr; }
    /// The running recording (mark, stats, path); null when none.
    RecordingSession* recordingSession() const { return mRecording.get(); }
    /// Figures of the last recording as it was closed (the dock shows them after Stop).
    const RecordingStats& lastRecordingStats() const { return mLastRecordingStats; }
    /// Why the last recording ended without stopRecording ("" if it did not): a new haptic rate
    /// needs a new loop, which a recording cannot follow. Cleared by the call.
    std::string takeRecordingEndedReason() { return std::exchange(mRecordingEndedReason, {}); }

    LoopMode mode() const { return mMode; }
    bool hasLoop() const { return mLoop != nullptr; }
    bool threadRunning() const { return mLoop && mLoop->running(); }
    const std::string& deviceUri() const { return mDeviceUri; }
    /// The mesh being drawn, its file and its scene id (null before the first load).
    const std::shared_ptr<const TissueMesh>& drawnMesh() const { return mDrawn.mesh; }
    const std::string& drawnPath() const { return mDrawn.path; }
    std::uint64_t drawnSceneId() const { return mDrawn.sceneId; }
    /// A scene was handed over and has not shown up in a snapshot yet.
    bool sceneSwitchPending() const { return mPending.mesh != nullptr; }
    const ObservedLoop& observed() const { return mObserved; }
    /// Positions, tool, contact and force to draw (the drawn mesh's vertex order).
    const SceneSnapshot& view() const { return mObserver.view(); }
    const SnapshotObserver& observer() const { return mObserver; }
    /// Snapshots applied so far (new publishCount seen).
    std::uint64_t snapshotsObserved() const { return mSnapshotsObserved; }
    double periodS() const { return 1.0 / mDef.rateHz; }
    /// The name of the model the loop runs now (DeformationModel::name()); "" before the first mesh
    /// or while the thread runs (the scene is the haptic thread's then). For stepped runs and tests.
    std::string loopModelName() const;

private:
    TissuePreset mPreset;
    /// The exercise physics every scene of mExercisePath's mesh gets (makeScene).
    std::shared_ptr<const ExerciseGeometry> mExercisePhysics;
    std::string mExercisePath;
    /// A scene of `mesh` (file `path`) with the session's preset, and the exercise's physics when
    /// `path` is the exercise's mesh.
    std::unique_ptr<HapticScene> makeScene(const TissueMesh& mesh, const std::string& path, std::string& error) const;
    struct SceneRecord {
        std::shared_ptr<const TissueMesh> mesh;  // our copy: what is drawn for this scene
        std::string path;
        std::uint64_t sceneId = 0;
    };
    /// A fresh scene of `base`'s mesh and a fresh device of the current URI, handed to the loop.
    std::string handOverFresh(const SceneRecord& base);
    /// The newest mesh handed to the loop (pending, else drawn).
    const SceneRecord& latest() const { return mPending.mesh ? mPending : mDrawn; }
    /// Where a fresh or released mouse tool waits: kTouchLiftMm out from the rest vertex nearest
    /// `nearMm` (or from the aim vertex when null).
    glm::vec3 awayPointMm(const TissueMesh& mesh, const glm::vec3* nearMm) const;
    std::unique_ptr<HapticDevice> openDeviceFor(const std::string& uri, const TissueMesh& mesh, std::string& error);
    /// What every fresh device gets before the loop does: a repeat for scripts, an aim, the mouse away.
    void prepareDevice(HapticDevice& device, const TissueMesh& mesh);
    std::string handOver(SceneRecord record, std::unique_ptr<HapticScene> scene, std::unique_ptr<HapticDevice> device);
    /// mLoop->swapScene, through the recording while one runs (the file must describe the scene).
    std::string swapSceneInLoop(std::unique_ptr<HapticScene> scene, const SceneRecord& record);
    /// mLoop->swapDevice, through the recording while one runs; remembers what the loop got.
    std::string swapDeviceInLoop(std::unique_ptr<HapticDevice> device, const std::string& uri);

    LoopMode mMode;
    HapticLoopDef mDef;
    std::string mDeviceUri = kDefaultDeviceUri;
    bool mPauseRequested = false;
    std::unique_ptr<HapticLoop> mLoop;
    /// Non-owning: the MouseDevice the loop got last (the loop owns it; it stays alive until a later
    /// swap retires it, and every swap here resets this first). Null for any other device.
    MouseDevice* mMouse = nullptr;
    bool mHaveTouchTarget = false;
    glm::vec3 mLastTouchMm{0.0f};
    SceneRecord mDrawn;
    SceneRecord mPending;
    SnapshotObserver mObserver;
    ObservedLoop mObserved;
    std::uint64_t mSnapshotsObserved = 0;
    /// The device the loop got last (URI and spec): a recording's header starts with it.
    RecordedDevice mLoopDevice;
    std::unique_ptr<RecordingSession> mRecording;  // stopped before the loop goes (stop(), applyPreset)
    RecordingStats mLastRecordingStats;
    std::string mRecordingEndedReason;
    int mStepsSinceFlush = 0;  // stepped ticks the recorder's writer has not been asked to take yet
};

}  // namespace palpate
