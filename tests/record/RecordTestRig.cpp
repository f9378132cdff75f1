#include "tests/record/RecordTestRig.h"

#include "engine/core/MeshGenerator.h"
#include "engine/core/SceneTarget.h"
#include "engine/record/RecordingSession.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <stdexcept>

namespace palpate::test {

TempDir::TempDir() {
    std::random_device rd;
    for (int attempt = 0; attempt < 100; ++attempt) {
        mPath = std::filesystem::temp_directory_path() /
                ("palpate-record-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
        if (std::filesystem::create_directory(mPath)) return;
    }
    throw std::runtime_error("cannot create a temporary directory");
}

TempDir::~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(mPath, ec);
}

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

std::vector<std::uint8_t> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

CommandResult runShell(const std::string& commandLine) {
    CommandResult result;
    FILE* pipe = ::popen((commandLine + " 2>&1").c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
    const int status = ::pclose(pipe);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    else if (WIFSIGNALED(status)) result.exitCode = 128 + WTERMSIG(status);
    return result;
}

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) {
        if (c == '\'') q += "'\\''";
        else q += c;
    }
    return q + "'";
}

CommandResult runCli(const std::string& args) { return runShell(shellQuote(PALPATE_CLI_PATH) + " " + args); }

}  // namespace palpate::test
