#pragma once
// The haptic loop's rate range, said once: the loop refuses a rate outside it, presets and the
// Parameters panel offer only rates inside it (docs/haptic-loop.md).

namespace palpate {

inline constexpr double kMinHapticRateHz = 10.0;
inline constexpr double kMaxHapticRateHz = 10000.0;

}  // namespace palpate
