#pragma once
// The haptic loop's rate range, said once: the loop, recordings, the benches and presets refuse a
// rate outside it, and the Parameters panel offers only rates inside it (docs/haptic-loop.md).

namespace palpate {

inline constexpr double kMinHapticRateHz = 10.0;
inline constexpr double kMaxHapticRateHz = 10000.0;

/// Whether a rate lies in the range (a NaN does not).
inline bool hapticRateInRange(double rateHz) { return rateHz >= kMinHapticRateHz && rateHz <= kMaxHapticRateHz; }

}  // namespace palpate
