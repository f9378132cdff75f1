#include "tests/record/RecordTestRig.h"

#include "engine/core/MeshGenerator.h"
#include "engine/core/SceneTarget.h"
#include "engine/record/Crc32.h"
#include "engine/record/RecordingFormat.h"
#include "engine/record/RecordingSession.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <stdexcept>

namespace palpate::test {

namespace {

std::string writeSphere(std::size_t vertices, const std::string& name) {
    static TempDir dir;  // lives until the process ends
    auto generated = generateMesh(GeneratedShape::Sphere, vertices);
    if (!generated.mesh) throw std::runtime_error("sphere generation failed");
    const std::string path = dir.file(name);
    const std::string error = generated.mesh->save(path);
    if (!error.empty()) throw std::runtime_error(error);
    return path;
}

}  // namespace

const std::string& sphereMeshPath() {
    static const std::string path = writeSphere(1442, "sphere1442.off");
    return path;
}

const std::string& smallSphereMeshPath() {
    static const std::string path = writeSphere(642, "sphere642.off");
    return path;
}

std::unique_ptr<SimulatedDevice> aimedDevice(const TissueMesh& mesh, SimTrajectory trajectory, float toolRadiusMm) {
    auto device = std::make_unique<SimulatedDevice>(trajectory);
    aimAtDefaultTarget(*device, mesh, toolRadiusMm);
    if (!device->open()) throw std::runtime_error("simulated device does not open");
    return device;
}

RecordRig makeRecordRig(SimTrajectory trajectory, TissuePreset preset, const std::string& meshPath) {
    RecordRig rig;
    rig.meshPath = meshPath.empty() ? sphereMeshPath() : meshPath;
    rig.preset = preset;
    auto loaded = TissueMesh::load(rig.meshPath);
    if (!loaded.mesh) throw std::runtime_error(loaded.error());
    auto device = aimedDevice(*loaded.mesh, trajectory, float(presetToolRadiusMm(preset)));
    rig.device = device.get();
    const std::string uri = std::string("sim:") + simTrajectoryName(trajectory);
    HapticLoopDef def;
    def.rateHz = preset.hapticRateHz;
    def.trySchedFifo = false;
    rig.header = makeRecordingHeader(*loaded.mesh, rig.meshPath, preset, uri, device->spec(), def.safety);
    rig.loop = std::make_unique<HapticLoop>(
        def, HapticScene::create(std::move(*loaded.mesh), preset),
        std::move(device));
    return rig;
}

void retagChunks(std::vector<std::uint8_t>& bytes, std::size_t from, std::uint32_t headerCrc) {
    const std::uint32_t tag = chunkHeaderTag(headerCrc);
    for (std::size_t offset = findChunkMagic(bytes.data(), bytes.size(), from); offset < bytes.size();
         offset = findChunkMagic(bytes.data(), bytes.size(), offset + 1)) {
        if (bytes.size() - offset < kChunkHeaderBytes) break;
        std::uint8_t* p = bytes.data() + offset;
        p[5] = std::uint8_t(tag);
        p[6] = std::uint8_t(tag >> 8);
        p[7] = std::uint8_t(tag >> 16);
        const std::uint32_t crc = crc32(p + 4, kChunkHeaderBytes - 8);
        for (int i = 0; i < 4; ++i) p[kChunkHeaderBytes - 4 + std::size_t(i)] = std::uint8_t(crc >> (8 * i));
    }
}

std::vector<std::uint8_t> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

CommandResult runCli(const std::string& args) { return runCommand(shellQuote(PALPATE_CLI_PATH) + " " + args); }

}  // namespace palpate::test
