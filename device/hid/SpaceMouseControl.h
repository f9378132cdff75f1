#pragma once
// How SpaceMouse deflection steers the tool tip: as a rate controller (deflection = velocity, the
// tool stays where it was let go) or a position controller (deflection = offset from home, the
// tool springs back with the cap). Pure and allocation-free: it runs in the haptic tick.

#include "base/params/Problem.h"

#include "device/hid/SpaceMouseCodec.h"

#include <glm/vec3.hpp>

#include <string>

namespace palpate {

enum class SpaceMouseMode { Rate, Position };

const char* spaceMouseModeName(SpaceMouseMode mode);

struct SpaceMouseControlDef {
    SpaceMouseMode mode = SpaceMouseMode::Rate;
    double fullScaleCounts = 350.0;  ///< deflection that counts as 1 (reports run to about +-350)
    double deadbandCounts = 12.0;    ///< smaller deflections are zero: the cap never rests at exactly 0
    double rateMmPerS = 30.0;        ///< rate mode: speed at full deflection
    double positionRangeMm = 15.0;   ///< position mode: offset at full deflection
    glm::vec3 homeMm{0.0f, 0.0f, 5.0f};  ///< start (and position-mode centre), scene frame: above the target
    double workspaceRadiusMm = 80.0;     ///< rate mode keeps the tool within this of home
};

/// "" when usable, else a message naming the field.
Problems validateSpaceMouseControlDef(const SpaceMouseControlDef& def);

/// Deflection in [-1, 1] per axis, scene frame: x = HID Tx (right), y = -HID Ty (pushing the cap
/// away from the user moves the tool away... up the screen), z = -HID Tz (pressing the cap down
/// moves the tool into the tissue, whose outward normal is +z).
glm::vec3 spaceMouseDeflection(const SpaceMouseRaw& raw, const SpaceMouseControlDef& def);

/// Integrates (rate) or maps (position) the tool position.
class SpaceMouseControl {
public:
    explicit SpaceMouseControl(SpaceMouseControlDef def = {});
    /// The tool position after `dtS` seconds at this deflection. dtS < 0 or non-finite counts as 0.
    glm::vec3 update(const SpaceMouseRaw& raw, double dtS);
    void reset() { mPositionMm = mDef.homeMm; }
    glm::vec3 positionMm() const { return mPositionMm; }
    const SpaceMouseControlDef& def() const { return mDef; }

private:
    SpaceMouseControlDef mDef;
    glm::vec3 mPositionMm;
};

}  // namespace palpate
