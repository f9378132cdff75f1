#pragma once
// Shared pieces of the recorder tests: a temporary directory, a mesh file the replay can load, a
// stepped or threaded loop on it with a simulated device, and running palpate-cli.

#include "device/SimulatedDevice.h"
#include "engine/loop/HapticLoop.h"
#include "engine/scene/TissuePreset.h"
#include "engine/record/RecordingFormat.h"
#include "tests/support/Shell.h"
#include "tests/support/TempDir.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace palpate::test {

/// A 1442-vertex sphere written once per process to an OFF file (the replay loads meshes by path).
const std::string& sphereMeshPath();
/// Another mesh (642 vertices), for scene switches and hash mismatches.
const std::string& smallSphereMeshPath();

struct RecordRig {
    std::unique_ptr<HapticLoop> loop;
    SimulatedDevice* device = nullptr;
    RecordingHeader header;
    TissuePreset preset;
    std::string meshPath;
};

/// A loop on the sphere (loaded from sphereMeshPath) with a simulated device aimed at its side
/// vertex, and the recording header describing it. No SCHED_FIFO (tests share the machine).
RecordRig makeRecordRig(SimTrajectory trajectory, TissuePreset preset = {}, const std::string& meshPath = {});
/// A simulated device aimed like the rig's (for device switches).
/// A simulated device aimed at the mesh's default target for a tool of this radius (the default
/// preset's: ours touches with a sphere).
std::unique_ptr<SimulatedDevice> aimedDevice(const TissueMesh& mesh, SimTrajectory trajectory,
                                             float toolRadiusMm = float(presetToolRadiusMm(TissuePreset{})));

std::vector<std::uint8_t> readBytes(const std::string& path);
/// A forger who knows the format: the chunks from `from` on get the tag of the header whose body
/// CRC is `headerCrc`, their header CRCs recomputed, so that they pass as that header's.
void retagChunks(std::vector<std::uint8_t>& bytes, std::size_t from, std::uint32_t headerCrc);
void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes);

/// Runs palpate-cli with these arguments (already quoted where needed).
CommandResult runCli(const std::string& args);

}  // namespace palpate::test
