#pragma once
// Recording a HapticLoop: what a front end (the GUI's recorder dock, palpate-cli run) uses. Start
// creates the file and attaches the writer to the loop, whose next tick begins the recording (and
// restarts the session state, see HapticLoop::attachRecorder); stop detaches, drains and closes.
//
//   std::string error;
//   auto session = RecordingSession::start(loop, "run.palprec", makeRecordingHeader(...), error);
//   session->mark("first palpation");           // any controller thread, any time
//   RecordingStats s = session->stats();        // ticks, bytes, drops, elapsed: for a status line
//   session->stop();                            // controller thread; "" or the write error
//
// Parameter sets go through loop.setModelParams as usual: the loop reports each one it applied. Scenes
// and devices switched while recording go through swapScene/swapDevice here, so that the file
// describes them (a replay rebuilds the scene from that description).

#include "engine/loop/HapticLoop.h"
#include "engine/scene/TissuePreset.h"
#include "engine/record/RecordingWriter.h"

#include <memory>
#include <string>

namespace palpate {

/// A header for a session on `mesh` (as loaded, for its hash) with `preset` (model, parameters,
/// octree, rate) and a device; start time is now. `meshPath` and `deviceUri` are stored as given.
RecordingHeader makeRecordingHeader(const TissueMesh& mesh, const std::string& meshPath, const TissuePreset& preset,
                                    const std::string& deviceUri, const DeviceSpec& deviceSpec,
                                    const SafetyFilterDef& safety = {});
/// The scene part of a header, for makeRecordingHeader and for RecordingSession::swapScene.
RecordedScene describeScene(const TissueMesh& mesh, const std::string& meshPath, const TissuePreset& preset);

class RecordingSession {
public:
    /// Creates the file, writes the header and attaches to `loop` (running or stopped). Null with
    /// `error` on failure (the loop is left untouched). Controller thread.
    static std::unique_ptr<RecordingSession> start(HapticLoop& loop, const std::string& path,
                                                   const RecordingHeader& header, std::string& error,
                                                   const RecordingWriterDef& def = {});
    /// Stops (see stop()). The loop must outlive the session or the session must be stopped first.
    ~RecordingSession();
    RecordingSession(const RecordingSession&) = delete;
    RecordingSession& operator=(const RecordingSession&) = delete;

    /// Detaches from the loop (at most about one tick's wait), writes what is left and the end
    /// chunk, syncs and closes. Idempotent. Returns "" or the first write error. Controller thread.
    std::string stop();
    bool recording() const { return !mStopped; }

    /// A user's mark at the current tick (any thread).
    void mark(const std::string& text) { mWriter->mark(text); }
    /// An exercise event (free text, e.g. JSON) at the current tick (any thread).
    void exerciseEvent(const std::string& text) { mWriter->exerciseEvent(text); }
    /// HapticLoop::swapScene, with the description a replay needs to rebuild the scene.
    std::string swapScene(std::unique_ptr<HapticScene> scene, const RecordedScene& description);
    /// HapticLoop::swapDevice, with its URI and spec for the file.
    std::string swapDevice(std::unique_ptr<HapticDevice> device, const RecordedDevice& description);

    /// Ticks, bytes, drops, elapsed loop time (any thread; updated at each drain).
    RecordingStats stats() const { return mWriter->stats(); }
    /// Blocks until every tick so far is in the file. Stepped runs call it every few thousand
    /// ticks so the ring never overflows; the real-time loop never needs it.
    std::string flush() { return mWriter->flush(); }
    const std::string& path() const { return mWriter->path(); }
    RecordingWriter& writer() { return *mWriter; }

private:
    RecordingSession(HapticLoop& loop, std::unique_ptr<RecordingWriter> writer);

    HapticLoop& mLoop;
    std::unique_ptr<RecordingWriter> mWriter;
    bool mStopped = false;
    std::string mStopResult;
};

}  // namespace palpate
