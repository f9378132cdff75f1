#pragma once
// The GUI's copy of the deformed mesh, kept up to date from the haptic loop's snapshots (DESIGN §2:
// the GUI only observes). A snapshot lists only the displaced vertices; the observer keeps all
// positions, sets the listed ones and puts back at rest those it had set in the previous snapshot
// that are no longer listed, so each update touches only what changed. Qt-free, single thread.

#include "engine/HapticSnapshot.h"
#include "widgets/SceneSnapshot.h"

#include <cstdint>
#include <vector>

namespace palpate {

class SnapshotObserver {
public:
    /// Starts over from this rest shape (a new scene): every vertex at rest, no tool.
    void setRestPositions(const std::vector<glm::vec3>& restMm);

    /// Applies a snapshot of the scene whose rest shape was given. Ids outside the mesh are ignored.
    /// Returns how many vertices were written (set or put back at rest).
    std::size_t apply(const HapticSnapshot& snapshot);

    /// What the viewport draws: current positions, tool, contact, force.
    const SceneSnapshot& view() const { return mView; }
    /// Vertices currently away from rest, as last applied.
    const std::vector<VertexId>& displacedIds() const { return mSet; }

private:
    std::vector<glm::vec3> mRestMm;
    SceneSnapshot mView;               // mView.positionsMm is the observer's copy of the positions
    std::vector<VertexId> mSet;        // ids set by the last apply
    std::vector<VertexId> mNextSet;    // scratch for the next one (swapped with mSet)
    std::vector<std::uint32_t> mStamp; // per vertex: the apply() that last listed it
    std::uint32_t mGeneration = 0;
};

}  // namespace palpate
