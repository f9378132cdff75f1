#pragma once
// The limits of every input format, stated once (docs/conventions.md, "File limits"): each
// format's reader refuses a file beyond its limit before reading it, and its writer refuses to
// write what the reader would refuse. A recording embeds a preset and an exercise as JSON, so its
// header is sized from kPresetFile and kExerciseFile.

#include <cstdint>

namespace palpate {

/// What an input file should be: its name with the article, as the messages use it ("a preset
/// file": "is a FIFO, not a preset file"), and the most bytes such a file may hold.
struct InputKind {
    const char* name;
    std::uint64_t maxBytes;
};

inline constexpr std::uint64_t kKiB = 1024;
inline constexpr std::uint64_t kMiB = 1024 * kKiB;

/// Tissue presets: a few kilobytes of parameters and a description.
inline constexpr InputKind kPresetFile{"a preset file", 1 * kMiB};

/// The most press targets and trace path points an exercise may hold (docs/scoring.md).
inline constexpr int kMaxPressTargets = 1000;
inline constexpr int kMaxLumps = 100;
inline constexpr int kMaxTracePathPoints = 10000;
/// Exercises: the largest holds kMaxTracePathPoints points or kMaxPressTargets targets with every
/// number at full precision, indented: about 1.4 MB (tests/io/test_json_safety.cpp checks it fits
/// with room to spare).
inline constexpr InputKind kExerciseFile{"an exercise file", 4 * kMiB};

/// Waypoint files of the simulated device (`sim:path:FILE`): a path is a few thousand lines; the
/// limit leaves room for hours of dense waypoints.
inline constexpr InputKind kWaypointFile{"a waypoint file", 64 * kMiB};

/// Mesh files (.obj, .off, .ply, .stl, .om) and the counts a mesh may have: what the product loads
/// and builds its octree and rings on in seconds. `mesh generate` refuses more vertices.
inline constexpr InputKind kMeshFile{"a mesh file", 256 * kMiB};
/// Exercise bundles: an exercise, its mesh, its preset and its scripted paths, each as base64
/// (4 bytes for 3): room for the largest mesh.
inline constexpr InputKind kExerciseBundleFile{"an exercise bundle", 512 * kMiB};
inline constexpr std::uint64_t kMaxMeshVertices = 2'000'000;
inline constexpr std::uint64_t kMaxMeshFaces = 2 * kMaxMeshVertices;

/// The level-of-detail cache's index (JSON) beside its level meshes (kMeshFile each).
inline constexpr InputKind kLevelCacheIndexFile{"a level cache index", 1 * kMiB};

}  // namespace palpate
