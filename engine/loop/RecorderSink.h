#pragma once
// What the haptic loop hands a session recorder: every input a tick depends on and what it
// produced, so that a stepped replay of the recording gives the same forces bit for bit. The loop
// calls the sink on the haptic thread; implementations must be wait-free: no allocation, lock, I/O,
// logging or exception.

#include "device/HapticDevice.h"
#include "engine/models/ContactDef.h"
#include "engine/models/slopering/SlopeRingParams.h"
#include "engine/core/TissueMesh.h"

#include <glm/vec3.hpp>

#include <cstdint>

namespace palpate {

/// One haptic tick: its inputs (clock, device read, device state, overrun flag, pause) and outputs
/// (force sent, touched vertex, contact).
struct RecordedTick {
    std::uint64_t tick = 0;      ///< the loop's tick count (1 = the loop's first tick)
    double nowS = 0.0;           ///< loop clock given to the device and the safety filter
    DeviceSample sample;         ///< what read() returned (meaningful when readOk)
    glm::vec3 forceN{0.0f};      ///< force written to the device, after the safety filter
    VertexId touched = kNoVertex;
    DeviceState deviceState = DeviceState::Disconnected;  ///< state() as the tick saw it
    bool readOk = false;         ///< read() returned a sample
    bool tickOverran = false;    ///< the previous tick overran (the safety filter zeroes this one)
    bool paused = false;
    bool contact = false;
    /// The divergence guard fired in this tick (docs/stability.md): the DivergenceKind as a number,
    /// 0 when it did not. The force above is then zero and the model was reset to rest. Not in the
    /// tick codec: the writer turns it into a Divergence event.
    std::uint8_t divergence = 0;
};

/// A command the loop applied at the boundary of tick `tick` (before that tick's device read).
struct RecordedCommand {
    enum class Kind : std::uint8_t { Params, Scene, Device };
    std::uint64_t tick = 0;
    Kind kind = Kind::Params;
    SlopeRingParams params;         ///< Params: the whole set applied
    std::uint64_t sceneId = 0;      ///< Scene: HapticScene::id() of the scene switched in
    const void* device = nullptr;   ///< Device: identity of the device switched in (not dereferenced)
    ContactDef contact;             ///< Params: the tool and friction applied with them
};

/// Receives ticks and applied commands from HapticLoop (see HapticLoop::setRecorder).
class RecorderSink {
public:
    virtual ~RecorderSink() = default;
    /// Haptic thread, once per tick after the force was written. Wait-free.
    virtual void onTick(const RecordedTick& tick) noexcept = 0;
    /// Haptic thread, for each command applied at a tick boundary, before that tick's onTick.
    virtual void onCommand(const RecordedCommand& command) noexcept = 0;
};

}  // namespace palpate
