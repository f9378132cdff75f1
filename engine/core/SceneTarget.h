#pragma once
// Where scripted devices and tool paths press by default: the side of the mesh (the vertex with
// the largest x, away from the generators' poles), along its rest normal, stroking towards +y.

#include "device/HapticDevice.h"
#include "engine/core/TissueMesh.h"

namespace palpate {

/// The vertex with the largest x (0 for an empty mesh); on a flat side, the one nearest its centre.
VertexId defaultTargetVertex(const TissueMesh& mesh);

/// Aims a device that scripts its motion (HapticDevice::setScene) at defaultTargetVertex. A tool
/// with a size (radius > 0: the device's position is the sphere's centre) is aimed `toolRadiusMm`
/// above the surface, so that a script pressing d mm below its target presses the sphere d deep.
void aimAtDefaultTarget(HapticDevice& device, const TissueMesh& mesh, float toolRadiusMm = 0.0f);

}  // namespace palpate
