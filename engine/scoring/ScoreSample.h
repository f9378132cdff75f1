#pragma once
// What the scorer consumes per haptic tick: the recorded tick (clock, device sample with position
// and buttons, force rendered, touched vertex, contact) and a summary of the tissue's damage after
// that tick, which needs the model (DamageProbe on a replay). Live and replayed sessions give the
// scorer the same samples, so the same score.

#include "engine/loop/RecorderSink.h"

namespace palpate {

/// The tissue after one tick, against the exercise's displacement limit.
struct DamageSummary {
    float maxDisplacementMm = 0.0f;  ///< largest |position - rest| of any displaced vertex
    float areaAboveLimitMm2 = 0.0f;  ///< sum of the vertex areas of vertices displaced beyond the limit
};

struct ScoreSample {
    RecordedTick tick;
    DamageSummary damage;
};

}  // namespace palpate
