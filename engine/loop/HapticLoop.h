#pragma once
// The haptic loop: one thread that, every period, reads the device, finds the touched vertex,
// deforms, filters and writes the force, and publishes a snapshot. The GUI only observes it
// (snapshots through a triple buffer) and talks to it through a lock-free command queue; the
// tick itself never allocates, locks, logs or does I/O. The same tick runs in a stepped mode on a
// virtual clock, so tests and replays are deterministic.

#include "base/params/Problem.h"

#include "device/HapticDevice.h"
#include "device/SafetyFilter.h"
#include "engine/scene/HapticScene.h"
#include "engine/loop/HapticSnapshot.h"
#include "engine/loop/LatencyHistogram.h"
#include "base/concurrency/SpscQueue.h"
#include "base/concurrency/TripleBuffer.h"
#include "engine/loop/RecorderSink.h"
#include "engine/stability/DivergenceGuard.h"

#include <atomic>
#include <memory>
#include <string>
#include <thread>

namespace palpate {

struct HapticLoopDef {
    double rateHz = 1000.0;    ///< 10 Hz .. 10 kHz
    bool trySchedFifo = true;  ///< ask for SCHED_FIFO; fall back quietly (reported in counters)
    int fifoPriority = 80;
    /// Sleep until this fraction of the period before the deadline, then spin (0: no spin). On
    /// virtual machines a core that went idle comes back slow (cold TLB and caches, measured in
    /// docs/haptic-loop.md); spinning part of the period keeps the tick fast. At most 0.9: a
    /// SCHED_FIFO thread that never sleeps is throttled by the kernel.
    double spinFraction = 0.6;
    SafetyFilterDef safety;
};

/// "" when usable, else a message naming the field.
Problems validateHapticLoopDef(const HapticLoopDef& def);

/// Timing of a run, from the loop's histograms (read after stop(), or in stepped mode).
struct LoopReport {
    LoopCounters counters;
    LatencySummary jitter;   ///< lateness of each wake-up after its deadline, µs
    LatencySummary compute;  ///< time spent in each tick, µs
    double elapsedS = 0.0;
    SafetyStats safety;
    std::uint64_t determinismHash = 0;
};

class HapticLoop {
public:
    /// Takes the scene and the device (already open). Throws std::invalid_argument on a bad def.
    HapticLoop(const HapticLoopDef& def, std::unique_ptr<HapticScene> scene, std::unique_ptr<HapticDevice> device);
    ~HapticLoop();
    HapticLoop(const HapticLoop&) = delete;
    HapticLoop& operator=(const HapticLoop&) = delete;

    // --- the thread (controller thread calls these) ---
    /// Starts the haptic thread: "" when it runs; otherwise why not (already running, or no
    /// thread could be created).
    std::string start();
    /// Stops and joins the thread; the scene and device stay, stepped mode is available again.
    void stop();
    bool running() const { return mRunning.load(std::memory_order_acquire); }

    // --- stepped mode: the same tick on a virtual clock, on the caller's thread ---
    /// One tick at virtual time tickCount * period. Not while the thread runs.
    void stepOnce();
    /// One stepped tick on a given clock with a given overrun flag: a replay of a recorded
    /// threaded run feeds back the clock and flag its ticks saw (engine/record/RecordingPlayer).
    void stepAt(double nowS, bool tickOverran);

    // --- commands: validated here, applied by the haptic thread at a tick boundary ---
    /// New parameters for the scene's model: "" when queued; otherwise why not (invalid parameters
    /// name each problem, or queue full). The model takes them at a tick boundary when it can
    /// (DeformationModel::applyModelParams: same kind and method, no reallocation); otherwise the
    /// command changes nothing and a new scene is needed (swapScene).
    std::string setModelParams(const ModelDef& model);
    std::string swapScene(std::unique_ptr<HapticScene> scene);
    std::string swapDevice(std::unique_ptr<HapticDevice> device);
    void pause();
    void resume();
    /// Deletes scenes and devices the loop has let go of (closing devices). Controller thread.
    void collectRetired();

    // --- session recorder (engine/record): each tick's inputs and outputs, for bit-exact replay ---
    /// Attaches `sink` (replacing any other); the next tick picks it up. That tick restarts the
    /// session state (tissue at rest, safety filter re-armed, last device sample forgotten) so that
    /// the recording replays from its header alone. Controller thread.
    void attachRecorder(RecorderSink* sink);
    /// Detaches the recorder; returns once no tick can call it any more (at once when the thread is
    /// not running, else after at most about one tick). Then the sink may be destroyed.
    void detachRecorder();

    // --- the observer (one thread) ---
    const HapticSnapshot& newestSnapshot() { return mSnapshots.newest(); }

    /// Histogram summaries and counters. Call when the thread is not running.
    LoopReport report() const;
    double periodS() const { return mPeriodS; }

    // For tests: run the tick's device/scene without the thread (not while running).
    HapticScene& scene() { return *mScene; }
    HapticDevice& device() { return *mDevice; }

private:
    struct Command {
        enum class Kind : std::uint8_t { Params, Scene, Device, Pause, Resume } kind;
        ModelDef model;  // trivially copyable, so the queue copies it without allocating
        HapticScene* scene;
        HapticDevice* device;
    };
    struct Retired {
        HapticScene* scene;
        HapticDevice* device;
    };

    void threadMain();
    void tick(double nowS, double lateUs);
    void warmUp();
    void applyCommands();
    void pickUpRecorder();
    void retire(HapticScene* scene, HapticDevice* device);
    /// Controller thread: deletes a retired scene and closes and deletes a retired device.
    static void destroyRetired(const Retired& retired);
    void publish(const TickResult& result, const glm::vec3& forceOutN, double nowS);

    HapticLoopDef mDef;
    double mPeriodS;
    std::unique_ptr<HapticScene> mScene;
    std::unique_ptr<HapticDevice> mDevice;
    SafetyFilter mSafety;
    DivergenceGuard mGuard;  // watches each tick's model output (docs/stability.md)

    // Haptic-thread state.
    DeviceSample mLastSample;
    bool mHaveSample = false;
    bool mPaused = false;
    bool mTickOverran = false;
    std::uint64_t mHash = 1469598103934665603ull;  // FNV-1a offset basis
    LoopCounters mCounters;
    LatencyHistogram mJitterUs{1.0, 2000};
    LatencyHistogram mComputeUs{0.01, 5000};
    std::uint64_t mPublishCount = 0;
    RecorderSink* mRecorder = nullptr;  // haptic thread's copy of the attached recorder
    std::uint64_t mRecorderSeen = 0;    // the last attach/detach request the tick acted on
    Retired mPendingRetire[16] = {};
    int mPendingRetireCount = 0;

    SpscQueue<Command, 64> mCommands;
    SpscQueue<Retired, 64> mRetired;
    TripleBuffer<HapticSnapshot> mSnapshots;

    std::thread mThread;
    std::atomic<bool> mRunning{false};
    std::atomic<bool> mStopRequested{false};
    // Recorder hand-over: the controller sets the wanted sink and bumps the request count; the
    // tick picks it up and acknowledges the request, so detachRecorder knows when it was let go.
    std::atomic<RecorderSink*> mWantedRecorder{nullptr};
    std::atomic<std::uint64_t> mRecorderRequest{0};
    std::atomic<std::uint64_t> mRecorderAck{0};
    double mElapsedS = 0.0;
};

}  // namespace palpate
