#include "engine/loop/HapticLoop.h"

#include "engine/core/HapticRate.h"
#include "base/params/FieldTable.h"

#include <glm/geometric.hpp>

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <chrono>
#include <system_error>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace palpate {

namespace {

double monotonicS() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

timespec toTimespec(double s) {
    timespec ts{};
    ts.tv_sec = time_t(s);
    ts.tv_nsec = long((s - double(ts.tv_sec)) * 1e9);
    if (ts.tv_nsec >= 1000000000L) {
        ts.tv_sec += 1;
        ts.tv_nsec -= 1000000000L;
    }
    return ts;
}

void hashBytes(std::uint64_t& hash, const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= bytes[i];
        hash *= 1099511628211ull;
    }
}

}  // namespace

Problems validateHapticLoopDef(const HapticLoopDef& def) {
    if (!hapticRateInRange(def.rateHz))
        return oneProblem("rateHz", "haptic rate " + std::to_string(def.rateHz) + " Hz is out of range " +
                                        formatNumber(kMinHapticRateHz) + ".." + formatNumber(kMaxHapticRateHz) + " Hz");
    if (!std::isfinite(def.spinFraction) || def.spinFraction < 0.0 || def.spinFraction > 0.9)
        return oneProblem("spinFraction",
                          "spinFraction " + std::to_string(def.spinFraction) + " must be in 0..0.9 of the period");
    if (def.fifoPriority < 1 || def.fifoPriority > 99)
        return oneProblem("fifoPriority", "fifoPriority " + std::to_string(def.fifoPriority) + " must be in 1..99");
    return validateSafetyFilterDef(def.safety);
}

HapticLoop::HapticLoop(const HapticLoopDef& def, std::unique_ptr<HapticScene> scene,
                       std::unique_ptr<HapticDevice> device)
    : mDef(def),
      mPeriodS(1.0 / def.rateHz),
      mScene(std::move(scene)),
      mDevice(std::move(device)),
      mSafety(mDevice ? mDevice->spec() : DeviceSpec{}, def.safety) {
    const std::string problem = joinedMessages(validateHapticLoopDef(def));
    if (!problem.empty()) throw std::invalid_argument(problem);
    if (!mScene) throw std::invalid_argument("HapticLoop needs a scene");
    if (!mDevice) throw std::invalid_argument("HapticLoop needs a device");
}

HapticLoop::~HapticLoop() {
    stop();
    // Scenes and devices still queued (sent after the last tick) are ours to free.
    Command c;
    while (mCommands.pop(c)) destroyRetired({c.scene, c.device});
    collectRetired();
}

std::string HapticLoop::start() {
    if (running()) return "the haptic loop is already running";
    if (mThread.joinable()) mThread.join();
    mStopRequested.store(false, std::memory_order_release);
    mRunning.store(true, std::memory_order_release);
    try {
        mThread = std::thread([this] { threadMain(); });
    } catch (const std::system_error& e) {
        // No thread (a process limit, no memory for its stack): the loop stays usable in stepped mode.
        mRunning.store(false, std::memory_order_release);
        return std::string("could not start the haptic thread: ") + e.what();
    }
    return {};
}

void HapticLoop::stop() {
    mStopRequested.store(true, std::memory_order_release);
    if (mThread.joinable()) mThread.join();
    mRunning.store(false, std::memory_order_release);
}

void HapticLoop::threadMain() {
    mCounters.schedFifo = false;
    if (mDef.trySchedFifo) {
        sched_param param{};
        param.sched_priority = mDef.fifoPriority;
        mCounters.schedFifo = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
    }
    const double startS = monotonicS();
    const double clockOffsetS = double(mCounters.ticks) * mPeriodS;  // continue the loop clock after a restart
    double deadlineS = startS + mPeriodS;
    const double spinS = mDef.spinFraction * mPeriodS;
    std::uint64_t ticksThisRun = 0;
    while (!mStopRequested.load(std::memory_order_acquire)) {
        const double sleepUntil = deadlineS - spinS;
        const timespec ts = toTimespec(sleepUntil);
        while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
        }
        // An idle core comes back with cold caches and TLB (on virtual machines a first touch of a
        // page can cost tens of µs): pay for it now, before the deadline, not inside the tick.
        warmUp();
        double nowS = monotonicS();
        while (nowS < deadlineS) nowS = monotonicS();  // the short spin to the deadline
        const double lateUs = (nowS - deadlineS) * 1e6;

        tick(clockOffsetS + (deadlineS - startS), lateUs);
        ++ticksThisRun;

        const double doneS = monotonicS();
        const double computeUs = (doneS - nowS) * 1e6;
        mComputeUs.record(computeUs);
        mCounters.lastComputeUs = computeUs;
        mCounters.maxComputeUs = std::max(mCounters.maxComputeUs, computeUs);
        deadlineS += mPeriodS;
        mTickOverran = doneS > deadlineS;
        if (mTickOverran) {
            ++mCounters.overruns;
            // Skip the deadlines that have already passed rather than bursting to catch up.
            while (deadlineS < doneS) {
                deadlineS += mPeriodS;
                ++mCounters.missedDeadlines;
            }
        }
        mElapsedS = doneS - startS;
        mCounters.achievedRateHz = mElapsedS > 0.0 ? double(ticksThisRun) / mElapsedS : 0.0;
    }
    mRunning.store(false, std::memory_order_release);
}

void HapticLoop::warmUp() {
    mScene->model().warm(mLastSample.positionMm);
    const HapticSnapshot& s = mSnapshots.back();
    volatile std::uint64_t sink = s.publishCount + s.displacedIds[0] + s.displacedRings[0] +
                                  std::uint64_t(s.displacedPositionsMm[0].x != 0.0f) + std::uint64_t(mDevice->state()) +
                                  mJitterUs.peek(mCounters.lastJitterUs) + mComputeUs.peek(mCounters.lastComputeUs) +
                                  std::uint64_t(mSafety.phase());
    (void)sink;
}

void HapticLoop::stepOnce() {
    if (running()) return;
    tick(double(mCounters.ticks + 1) * mPeriodS, 0.0);
    mComputeUs.record(0.0);
    mElapsedS = double(mCounters.ticks) * mPeriodS;
    mCounters.achievedRateHz = 1.0 / mPeriodS;
}

void HapticLoop::stepAt(double nowS, bool tickOverran) {
    if (running()) return;
    const bool threadFlag = mTickOverran;
    mTickOverran = tickOverran;
    tick(nowS, 0.0);
    mTickOverran = threadFlag;
    mComputeUs.record(0.0);
    mElapsedS = double(mCounters.ticks) * mPeriodS;
    mCounters.achievedRateHz = 1.0 / mPeriodS;
}

void HapticLoop::tick(double nowS, double lateUs) {
    pickUpRecorder();  // before the commands, so that those applied at its first tick are recorded
    applyCommands();
    mJitterUs.record(lateUs);
    mCounters.lastJitterUs = lateUs;
    mCounters.maxJitterUs = std::max(mCounters.maxJitterUs, lateUs);
    ++mCounters.ticks;

    mDevice->setTimeS(nowS);
    DeviceSample sample;
    const bool readOk = mDevice->read(sample);
    if (readOk) {
        mLastSample = sample;
        mHaveSample = true;
    }
    const DeviceState deviceState = mDevice->state();  // read once: the recorder stores what was used
    const bool ready = deviceState == DeviceState::Ready && mHaveSample;

    // Without a usable tool position the model gets a non-finite one: no contact, the tissue
    // relaxes, and the force is zero.
    const glm::vec3 tool = ready && !mPaused ? mLastSample.positionMm : glm::vec3(NAN);
    TickResult result = mScene->model().step(tool, mPeriodS);
    // Divergence guard (docs/stability.md): a model that left its stable range (NaN,
    // energy growth, force flipping every tick, an inverted triangle at the tool) renders no force
    // this tick and goes back to rest; counted and published so the GUI can say what to change.
    // Allocation-free; it reads only the touched fan and a few sampled vertices (copyPositionsMm),
    // so a model that writes its positions when read (the coherent method) is not made to write them.
    const DivergenceVerdict verdict = mGuard.check(mScene->mesh(), mScene->model(), result);
    if (verdict) {
        result.forceN = glm::vec3(0.0f);
        result.contact = false;
        mScene->model().reset();
        mGuard.reset();
        ++mCounters.divergences;
        mCounters.lastDivergence = verdict.kind;
        mCounters.lastDivergenceTick = mCounters.ticks;
    }

    SafetyInput in;
    in.nowS = nowS;
    in.sampleSequence = mLastSample.sequence;
    in.sampleTimeS = mLastSample.timeS;
    in.tickOverran = mTickOverran;
    in.deviceReady = ready;
    const glm::vec3 forceOut = mSafety.filter(result.forceN, in);
    mDevice->writeForce(forceOut);

    hashBytes(mHash, &forceOut, sizeof(forceOut));
    hashBytes(mHash, &result.touched, sizeof(result.touched));
    if (mRecorder) {  // everything this tick depended on, so that a replay gives the same force
        RecordedTick r;
        r.tick = mCounters.ticks;
        r.nowS = nowS;
        r.sample = sample;
        r.forceN = forceOut;
        r.touched = result.touched;
        r.deviceState = deviceState;
        r.readOk = readOk;
        r.tickOverran = mTickOverran;
        r.paused = mPaused;
        r.contact = result.contact;
        r.divergence = std::uint8_t(verdict.kind);  // the writer makes it a Divergence event
        mRecorder->onTick(r);
    }
    publish(result, forceOut, nowS);

    // Retry handing back anything the retire queue had no room for.
    while (mPendingRetireCount > 0 && mRetired.push(mPendingRetire[mPendingRetireCount - 1])) --mPendingRetireCount;
}

void HapticLoop::publish(const TickResult& result, const glm::vec3& forceOutN, double nowS) {
    HapticSnapshot& s = mSnapshots.back();
    s.publishCount = ++mPublishCount;
    s.tick = mCounters.ticks;
    // The clock the device and the recording saw, which skips the deadlines a late tick missed:
    // not ticks x period, which falls behind it on a loaded machine (a scripted mark at a loop
    // time must land where the device's path is at that time).
    s.timeS = nowS;
    s.sceneId = mScene->id();
    s.paused = mPaused;
    s.deviceState = mDevice->state();
    s.safetyPhase = mSafety.phase();
    s.safetyFlags = mSafety.lastFlags();
    s.toolTipMm = mLastSample.positionMm;
    s.toolRadiusMm = mScene->model().toolRadiusMm();
    s.proxyMm = result.contact && s.toolRadiusMm > 0.0f ? result.proxyMm : mLastSample.positionMm;
    s.toolSampleTimeS = mLastSample.timeS;
    s.toolSampleSequence = mLastSample.sequence;
    s.commandedForceN = result.forceN;
    s.forceN = forceOutN;
    s.contact = result.contact;
    s.touched = result.touched;
    s.penetrationMm = result.penetrationMm;
    s.counters = mCounters;
    s.determinismHash = mHash;
    const std::size_t total = mScene->model().copyDisplaced(s.displacedIds.data(), s.displacedPositionsMm.data(),
                                                            s.displacedRings.data(), HapticSnapshot::kMaxDisplaced);
    s.displacedTotal = std::uint32_t(total);
    s.displacedCount = std::uint32_t(std::min(total, HapticSnapshot::kMaxDisplaced));
    s.closingTick = s.tick;
    mSnapshots.publish();
}

void HapticLoop::applyCommands() {
    Command c;
    while (mCommands.pop(c)) {
        switch (c.kind) {
            case Command::Kind::Params:
                // Only parameters the model took are recorded (a rejected set changes nothing).
                // A recording stores the slope-ring parameters (the models that take parameters in
                // real time are the slope-ring methods and volumetric rings, both made of them).
                if (mScene->model().applyModelParams(c.model) && mRecorder)
                    if (const SlopeRingParams* params = slopeRingParamsOf(c.model))
                        mRecorder->onCommand(
                            {mCounters.ticks + 1, RecordedCommand::Kind::Params, *params, 0, nullptr, c.model.contact});
                break;
            case Command::Kind::Scene:
                retire(mScene.release(), nullptr);
                mScene.reset(c.scene);
                mGuard.reset();  // its history was the old scene's
                if (mRecorder)
                    mRecorder->onCommand(
                        {mCounters.ticks + 1, RecordedCommand::Kind::Scene, {}, mScene->id(), nullptr});
                break;
            case Command::Kind::Device:
                mDevice->writeForce(glm::vec3(0.0f));
                retire(nullptr, mDevice.release());
                mDevice.reset(c.device);
                mHaveSample = false;
                mSafety.rearm();
                if (mRecorder)
                    mRecorder->onCommand({mCounters.ticks + 1, RecordedCommand::Kind::Device, {}, 0, c.device});
                break;
            case Command::Kind::Pause: mPaused = true; break;
            case Command::Kind::Resume: mPaused = false; break;
        }
    }
}

void HapticLoop::pickUpRecorder() {
    const std::uint64_t request = mRecorderRequest.load(std::memory_order_acquire);
    if (request == mRecorderSeen) return;
    mRecorderSeen = request;
    RecorderSink* const wanted = mWantedRecorder.load(std::memory_order_relaxed);
    if (wanted && wanted != mRecorder) {
        // A recording replays from its header alone, so it starts from the state a fresh loop has:
        // tissue at rest, safety filter re-armed (force held off, then ramped in), no sample yet.
        // Once per recording; the reset is O(vertices) but allocates nothing.
        mScene->model().reset();
        mGuard.reset();  // a replay starts with a fresh guard too
        mSafety.rearm();
        mHaveSample = false;
        mLastSample = DeviceSample{};
        // A scripted device starts its script with the recording, so a scripted trainee's run
        // is scored from its first move however late the recording attached.
        mDevice->restartScript();
    }
    mRecorder = wanted;
    mRecorderAck.store(request, std::memory_order_release);
}

void HapticLoop::attachRecorder(RecorderSink* sink) {
    mWantedRecorder.store(sink, std::memory_order_relaxed);
    mRecorderRequest.fetch_add(1, std::memory_order_release);
}

void HapticLoop::detachRecorder() {
    mWantedRecorder.store(nullptr, std::memory_order_relaxed);
    const std::uint64_t request = mRecorderRequest.fetch_add(1, std::memory_order_release) + 1;
    while (running() && mRecorderAck.load(std::memory_order_acquire) < request)
        std::this_thread::sleep_for(std::chrono::microseconds(100));
    if (!running()) {  // no thread: nothing can call the sink; let go of it here
        mRecorder = nullptr;
        mRecorderSeen = request;
    }
}

void HapticLoop::retire(HapticScene* scene, HapticDevice* device) {
    const Retired r{scene, device};
    if (mRetired.push(r)) return;
    if (mPendingRetireCount < int(std::size(mPendingRetire))) mPendingRetire[mPendingRetireCount++] = r;
    // else: the controller has not collected 80 retired objects; keeping the pointer would need
    // memory we must not allocate here, so it is leaked rather than freed on the haptic thread.
}

std::string HapticLoop::setModelParams(const ModelDef& model) {
    const auto errors = validateModelDef(model);
    if (!errors.empty()) {
        std::string text = "parameters not applied:";
        for (const auto& e : errors) text += "\n  " + e.message;
        return text;
    }
    Command c{Command::Kind::Params, model, nullptr, nullptr};
    return mCommands.push(c) ? std::string() : std::string("parameters not applied: the command queue is full");
}

std::string HapticLoop::swapScene(std::unique_ptr<HapticScene> scene) {
    if (!scene) return "no scene given";
    Command c{Command::Kind::Scene, {}, scene.get(), nullptr};
    if (!mCommands.push(c)) return "scene not switched: the command queue is full";
    scene.release();  // owned by the loop from now on
    return {};
}

std::string HapticLoop::swapDevice(std::unique_ptr<HapticDevice> device) {
    if (!device) return "no device given";
    Command c{Command::Kind::Device, {}, nullptr, device.get()};
    if (!mCommands.push(c)) return "device not switched: the command queue is full";
    device.release();
    return {};
}

void HapticLoop::pause() { mCommands.push(Command{Command::Kind::Pause, {}, nullptr, nullptr}); }
void HapticLoop::resume() { mCommands.push(Command{Command::Kind::Resume, {}, nullptr, nullptr}); }

void HapticLoop::destroyRetired(const Retired& r) {
    delete r.scene;
    if (r.device) {
        r.device->close();
        delete r.device;
    }
}

void HapticLoop::collectRetired() {
    Retired r;
    while (mRetired.pop(r)) destroyRetired(r);
    if (!running()) {  // the thread is gone: its pending list is ours now
        for (int i = 0; i < mPendingRetireCount; ++i) destroyRetired(mPendingRetire[i]);
        mPendingRetireCount = 0;
    }
}

LoopReport HapticLoop::report() const {
    LoopReport r;
    r.counters = mCounters;
    r.jitter = mJitterUs.summary();
    r.compute = mComputeUs.summary();
    r.elapsedS = mElapsedS;
    r.safety = mSafety.stats();
    r.determinismHash = mHash;
    return r;
}

}  // namespace palpate
