#pragma once
// The GUI's copy of the deformed mesh, kept up to date from the haptic loop's snapshots (docs/architecture.md:
// the GUI only observes). A snapshot lists only the displaced vertices; the observer keeps all
// positions and rings, sets the listed ones and puts back at rest those it had set in the previous
// snapshot that are no longer listed, so each update touches only what changed. It also records
// which vertices really changed (view().changed, under a new view().version), so that the viewport
// can upload just those. Qt-free, single thread.

#include "engine/loop/HapticSnapshot.h"
#include "widgets/SceneSnapshot.h"

#include <cstdint>
#include <vector>

namespace palpate {

class SnapshotObserver {
public:
    /// Starts over from this rest shape (a new scene): every vertex at rest and in no ring, no tool.
    /// Starts a new version, so a viewport that saw the old state reads the next one whole.
    void setRestPositions(const std::vector<glm::vec3>& restMm);

    /// Applies a snapshot of the scene whose rest shape was given. Ids outside the mesh are ignored.
    /// Returns how many vertices were written (set or put back at rest). When a position or ring
    /// changed, view().version increases by one and view().changed lists those vertices.
    std::size_t apply(const HapticSnapshot& snapshot);

    /// What the viewport draws: current positions and rings, tool, contact, force.
    const SceneSnapshot& view() const { return mView; }
    /// Vertices currently away from rest, as last applied.
    const std::vector<VertexId>& displacedIds() const { return mSet; }

private:
    std::vector<glm::vec3> mRestMm;
    SceneSnapshot mView;               // mView.positionsMm and .rings are the observer's copy
    std::vector<VertexId> mSet;        // ids set by the last apply
    std::vector<VertexId> mNextSet;    // scratch for the next one (swapped with mSet)
    std::vector<std::uint32_t> mStamp; // per vertex: the apply() that last listed it
    std::uint32_t mGeneration = 0;
    std::uint64_t mVersion = 0;        // never reset: versions stay unique across scenes
};

}  // namespace palpate
