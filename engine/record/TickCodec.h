#pragma once
// The tick stream's compression: each field is stored as the zigzag varint of its difference from a
// prediction, on the integer bit patterns (lossless: a replay needs the exact floats). Clock and
// force follow a second-order prediction (2 prev - prev-before), the device sequence and time are
// predicted from the tick's own clock, the touched vertex and buttons by the previous value, and a
// one-byte flag set covers the booleans. A recording averages about 20 bytes per tick
// (docs/recording.md). The coder restarts at each chunk, so every chunk decodes on its own.

#include "engine/loop/RecorderSink.h"

#include <cstdint>
#include <vector>

namespace palpate {

/// Predictor state shared by encoder and decoder; reset at each chunk.
struct TickPrediction {
    std::uint64_t now[2] = {0, 0};  ///< bit patterns of the last two clocks
    std::uint64_t time[2] = {0, 0}; ///< of the last two sample times that differed from the clock
    std::uint32_t pos[2][3] = {};
    std::uint32_t force[2][3] = {};
    std::uint64_t sequence = 0;
    std::uint32_t touched = kNoVertex;
    std::uint32_t buttons = 0;
    std::uint8_t state = 0;         ///< DeviceState::Disconnected
    int ticks = 0, times = 0, positions = 0;
};

class TickEncoder {
public:
    /// Starts a chunk.
    void reset() { mP = TickPrediction{}; }
    /// Appends one tick (its index is implicit: chunk first tick + position).
    void encode(const RecordedTick& tick, std::vector<std::uint8_t>& out);

private:
    TickPrediction mP;
};

class TickDecoder {
public:
    void reset() { mP = TickPrediction{}; }
    /// Decodes one tick from [*cursor, end), giving it index `tickIndex`. False on malformed or
    /// truncated input (then `*cursor` is unspecified but within [begin, end]).
    bool decode(const std::uint8_t** cursor, const std::uint8_t* end, std::uint64_t tickIndex, RecordedTick& out);

private:
    TickPrediction mP;
};

/// The loop's determinism hash step (FNV-1a over the force's and the touched vertex's bytes, as
/// HapticLoop does), so that the recorder's session hash equals the loop's for a recording that
/// starts with the loop.
void hashTick(std::uint64_t& hash, const glm::vec3& forceN, VertexId touched);
inline constexpr std::uint64_t kHashSeed = 1469598103934665603ull;  ///< FNV-1a offset basis

}  // namespace palpate
