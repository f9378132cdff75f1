#include "engine/record/RecordingSession.h"

#include "engine/core/MeshHash.h"

#include <chrono>
#include <cmath>

namespace palpate {

RecordedScene describeScene(const TissueMesh& mesh, const std::string& meshPath, const TissuePreset& preset) {
    RecordedScene s;
    s.meshPath = meshPath;
    s.meshUnit = mesh.report().unit;
    s.meshHash = meshHash(mesh);
    s.vertexCount = std::uint32_t(mesh.vertexCount());
    s.triangleCount = std::uint32_t(mesh.triangleCount());
    s.method = preset.model.slopeRingMethod;
    s.params = preset.model.slopeRing;
    s.contact = presetModelDef(preset).contact;
    s.octree = preset.octree;
    s.presetJson = tissuePresetToJson(preset);
    return s;
}

RecordingHeader makeRecordingHeader(const TissueMesh& mesh, const std::string& meshPath, const TissuePreset& preset,
                                    const std::string& deviceUri, const DeviceSpec& deviceSpec,
                                    const SafetyFilterDef& safety) {
    RecordingHeader h;
    h.startUnixUs = std::chrono::duration_cast<std::chrono::microseconds>(
                        std::chrono::system_clock::now().time_since_epoch())
                        .count();
    h.rateHz = preset.hapticRateHz;
    h.scene = describeScene(mesh, meshPath, preset);
    h.device.uri = deviceUri;
    h.device.spec = deviceSpec;
    h.safety = safety;
    return h;
}

std::unique_ptr<RecordingSession> RecordingSession::start(HapticLoop& loop, const std::string& path,
                                                          const RecordingHeader& header, std::string& error,
                                                          const RecordingWriterDef& def) {
    if (std::abs(header.rateHz - 1.0 / loop.periodS()) > 1e-9 * header.rateHz) {
        error = "recording header: rateHz " + std::to_string(header.rateHz) + " differs from the loop's " +
                std::to_string(1.0 / loop.periodS()) + " Hz";
        return nullptr;
    }
    auto writer = RecordingWriter::create(path, header, error, def);
    if (!writer) return nullptr;
    std::unique_ptr<RecordingSession> session(new RecordingSession(loop, std::move(writer)));
    loop.attachRecorder(session->mWriter.get());
    return session;
}

RecordingSession::RecordingSession(HapticLoop& loop, std::unique_ptr<RecordingWriter> writer)
    : mLoop(loop), mWriter(std::move(writer)) {}

RecordingSession::~RecordingSession() { stop(); }

std::string RecordingSession::stop() {
    if (mStopped) return mStopResult;
    mStopped = true;
    mLoop.detachRecorder();
    mStopResult = mWriter->close();
    return mStopResult;
}

std::string RecordingSession::swapScene(std::unique_ptr<HapticScene> scene, const RecordedScene& description) {
    if (!scene) return "no scene given";
    mWriter->describeScene(scene->id(), description);
    return mLoop.swapScene(std::move(scene));
}

std::string RecordingSession::swapDevice(std::unique_ptr<HapticDevice> device, const RecordedDevice& description) {
    if (!device) return "no device given";
    mWriter->describeDevice(device.get(), description);
    return mLoop.swapDevice(std::move(device));
}

}  // namespace palpate
