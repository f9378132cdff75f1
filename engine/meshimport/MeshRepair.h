#pragma once
// Repairing a polygon soup into a closed, consistently oriented, manifold triangle surface with
// CGAL's Polygon Mesh Processing (docs/meshes.md, "Repair"): every step that changes something
// says what it changed.

#include "engine/core/PolygonSoup.h"
#include "engine/meshimport/TriangleSurface.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace palpate {

enum class KeepComponents { Largest, All };

struct MeshRepairDef {
    KeepComponents keep = KeepComponents::Largest;
    bool fillHoles = true;
};

struct MeshRepairOutcome {
    std::optional<TriangleSurface> surface;  ///< absent when repair could not make a mesh
    std::vector<std::string> changes;        ///< one line per change, in the order made
    std::string error;                       ///< why there is no surface
};

/// `soup` in mm. `cancelled` is polled between steps; when it returns true the outcome's error is
/// "cancelled".
MeshRepairOutcome repairPolygonSoup(PolygonSoup soup, const MeshRepairDef& def,
                                    const std::function<bool()>& cancelled = {});

}  // namespace palpate
