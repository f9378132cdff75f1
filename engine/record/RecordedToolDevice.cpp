#include "engine/record/RecordedToolDevice.h"

#include "engine/record/RecordingReader.h"

#include <algorithm>
#include <cmath>

namespace palpate {

bool RecordedToolDevice::open() {
    mSamples.clear();
    mCursor = 0;
    mStartS = -1.0;
    mState = DeviceState::Opening;
    const RecordingReader reader = RecordingReader::open(mPath);
    if (!reader.headerOk()) {
        mError = mPath + ": " + (reader.fileError().empty() ? reader.headerError() : reader.fileError());
        mState = DeviceState::Fault;
        return false;
    }
    mSpec = reader.header().device.spec;
    mSpec.name = "replay of " + mPath;
    double firstS = std::nan("");
    reader.forEachTick([&](const RecordedTick& t) {
        if (!t.readOk || t.paused) return true;
        if (std::isnan(firstS)) firstS = t.nowS;
        mSamples.push_back(Sample{t.nowS - firstS, t.sample.positionMm, t.sample.buttons});
        return true;
    });
    if (mSamples.empty()) {
        mError = mPath + ": the recording holds no device sample to play";
        mState = DeviceState::Fault;
        return false;
    }
    mError.clear();
    mState = DeviceState::Ready;
    return true;
}

bool RecordedToolDevice::read(DeviceSample& sample) {
    if (mState != DeviceState::Ready || mSamples.empty()) return false;
    if (mStartS < 0.0) mStartS = mNowS;
    const double t = mNowS - mStartS;
    // Forward only, and usually by one sample a tick: a scan from the last position is O(1).
    while (mCursor + 1 < mSamples.size() && mSamples[mCursor + 1].timeS <= t) ++mCursor;
    const Sample& s = mSamples[mCursor];
    sample.sequence = ++mSequence;
    sample.timeS = mNowS;
    sample.positionMm = s.positionMm;
    sample.buttons = s.buttons;
    return true;
}

void registerReplayDeviceScheme() {
    registerDeviceFactory(DeviceKind::Replay, [](const DeviceUri& uri, std::string& error) -> std::unique_ptr<HapticDevice> {
        if (uri.path.empty()) {
            error = "replay: needs a recording file (replay:FILE)";
            return nullptr;
        }
        return std::make_unique<RecordedToolDevice>(uri.path);
    });
}

}  // namespace palpate
