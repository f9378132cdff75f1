#pragma once
// What the haptic loop publishes to its observer every tick (through a triple buffer): enough to
// draw the tool, the force and the deformed region, and to show the loop's health. Fixed size:
// publishing never allocates.

#include "device/HapticDevice.h"
#include "device/SafetyFilter.h"
#include "engine/core/TissueMesh.h"
#include "engine/stability/DivergenceGuard.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>

namespace palpate {

/// Running figures of the loop, kept by the haptic thread.
struct LoopCounters {
    std::uint64_t ticks = 0;
    std::uint64_t missedDeadlines = 0;  ///< deadlines skipped because a tick started too late
    std::uint64_t overruns = 0;         ///< ticks that finished after the next deadline
    double lastComputeUs = 0.0;
    double maxComputeUs = 0.0;
    double lastJitterUs = 0.0;          ///< lateness of the last wake-up
    double maxJitterUs = 0.0;
    double achievedRateHz = 0.0;
    bool schedFifo = false;             ///< the thread runs SCHED_FIFO (else it fell back quietly)
    /// Divergence guard (docs/stability.md): ticks on which the model left its stable range (force zeroed,
    /// tissue reset), the last one's kind and tick; divergenceAdvice(kind) says what to change.
    std::uint64_t divergences = 0;
    DivergenceKind lastDivergence = DivergenceKind::None;
    std::uint64_t lastDivergenceTick = 0;
};

struct HapticSnapshot {
    static constexpr std::size_t kMaxDisplaced = 4096;

    std::uint64_t publishCount = 0;  ///< increases with every publish
    std::uint64_t tick = 0;
    double timeS = 0.0;              ///< loop clock of this tick (RecordedTick::nowS; skips missed deadlines)
    std::uint64_t sceneId = 0;       ///< vertex ids below refer to this scene's mesh
    bool paused = false;

    DeviceState deviceState = DeviceState::Disconnected;
    SafetyPhase safetyPhase = SafetyPhase::HoldOff;
    std::uint32_t safetyFlags = 0;
    glm::vec3 toolTipMm{0.0f};
    /// The tool's size and where it is held on the tissue (TickResult::proxyMm): a sphere of
    /// this radius centred there while in contact; 0 for a point tool.
    float toolRadiusMm = 0.0f;
    glm::vec3 proxyMm{0.0f};
    double toolSampleTimeS = 0.0;     ///< the device sample's time stamp
    std::uint64_t toolSampleSequence = 0;
    glm::vec3 commandedForceN{0.0f};  ///< what the model asked for
    glm::vec3 forceN{0.0f};           ///< what the device was sent (after the safety filter)
    bool contact = false;
    VertexId touched = kNoVertex;
    float penetrationMm = 0.0f;

    LoopCounters counters;
    std::uint64_t determinismHash = 0;  ///< over every tick's force and touched vertex so far

    /// Vertices away from rest, with their positions. If more than kMaxDisplaced are displaced,
    /// displacedTotal says how many and only the first kMaxDisplaced are here.
    std::uint32_t displacedCount = 0;
    std::uint32_t displacedTotal = 0;
    std::array<VertexId, kMaxDisplaced> displacedIds{};
    std::array<glm::vec3, kMaxDisplaced> displacedPositionsMm{};
    /// Ring of the touched vertex each displaced vertex is in (0 = the touched vertex), or
    /// kRelaxingRing (255) for one returning to rest.
    std::array<std::uint8_t, kMaxDisplaced> displacedRings{};

    std::uint64_t closingTick = 0;  ///< equal to `tick`; written last, to show the copy is whole
};

}  // namespace palpate
