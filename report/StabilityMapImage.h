#pragma once
// A stability map as a PNG, for palpate-cli stability --png (a process with no QApplication): the
// cells coloured bounded/divergent, the derived boundary drawn over them as a line and the measured
// one as markers, the region the device cannot render passively hatched (where the map has
// passivity), log axes where the map's axes are log.

#include "engine/stability/StabilityMap.h"

#include <string>

namespace palpate {

/// Renders `map` into a widthPx x heightPx PNG at `path`. Creates an offscreen QGuiApplication if
/// the process has no Qt application. Returns "" or why it cannot.
std::string renderStabilityMapPng(const StabilityMap& map, const std::string& path, int widthPx = 1000,
                                  int heightPx = 800);

}  // namespace palpate
