// The replay:FILE device: a recorded session's tool motion played as a live device into the scene
// that runs now. Its samples follow the recording's clock (the recorded position at each loop
// time, the last one held), a stepped loop driven by it presses where the recording pressed, and
// a missing or empty file is an error naming the file.
#include "RecordTestRig.h"

#include "device/open/DeviceUri.h"
#include "engine/record/RecordedToolDevice.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"

#include <gtest/gtest.h>

using namespace palpate;
using namespace palpate::test;

namespace {

std::string recordStroke(const TempDir& dir, int ticks) {
    const std::string path = dir.file("stroke.palprec");
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    std::string error;
    auto session = RecordingSession::start(*rig.loop, path, rig.header, error);
    EXPECT_TRUE(session) << error;
    for (int i = 0; i < ticks; ++i) rig.loop->stepOnce();
    EXPECT_EQ(session->stop(), "");
    return path;
}

}  // namespace

TEST(RecordedToolDevice, PlaysTheRecordedPositionsOnTheLoopsClock) {
    TempDir dir;
    const std::string path = recordStroke(dir, 3000);
    const RecordingReader reader = RecordingReader::open(path);
    std::vector<RecordedTick> ticks = reader.ticks();
    ASSERT_GT(ticks.size(), 2000u);

    registerReplayDeviceScheme();
    std::string error;
    auto device = openDeviceUri("replay:" + path, error);
    ASSERT_TRUE(device) << error;
    EXPECT_EQ(device->state(), DeviceState::Ready);
    EXPECT_EQ(device->spec().maxForceN, reader.header().device.spec.maxForceN);

    // Started at loop time 5 s: the recording's first sample at 5 s, its 1500th tick 1.5 s later.
    const double periodS = 1.0 / reader.header().rateHz;
    std::size_t firstRead = 0;
    while (!ticks[firstRead].readOk) ++firstRead;
    DeviceSample sample;
    device->setTimeS(5.0);
    ASSERT_TRUE(device->read(sample));
    EXPECT_EQ(sample.positionMm, ticks[firstRead].sample.positionMm);
    const std::size_t later = firstRead + 1500;
    device->setTimeS(5.0 + (ticks[later].nowS - ticks[firstRead].nowS) + 0.25 * periodS);
    ASSERT_TRUE(device->read(sample));
    EXPECT_EQ(sample.positionMm, ticks[later].sample.positionMm);
    // After the end the last sample is held.
    device->setTimeS(1000.0);
    ASSERT_TRUE(device->read(sample));
    EXPECT_EQ(sample.positionMm, ticks.back().sample.positionMm);
    unregisterDeviceFactory(DeviceKind::Replay);
}

TEST(RecordedToolDevice, DrivesALoopToPressWhereTheRecordingPressed) {
    TempDir dir;
    const std::string path = recordStroke(dir, 2500);
    const RecordingReader reader = RecordingReader::open(path);
    std::uint64_t recordedContacts = 0;
    reader.forEachTick([&](const RecordedTick& t) { return recordedContacts += t.contact, true; });
    ASSERT_GT(recordedContacts, 100u);

    // The same scene, driven by the replayed motion: contact as often (the same physics, same clock).
    RecordRig rig = makeRecordRig(SimTrajectory::Stroke);
    auto device = std::make_unique<RecordedToolDevice>(path);
    ASSERT_TRUE(device->open()) << device->lastError();
    ASSERT_EQ(rig.loop->swapDevice(std::move(device)), "");
    std::uint64_t contacts = 0;
    for (int i = 0; i < 2500; ++i) {
        rig.loop->stepOnce();
        contacts += rig.loop->newestSnapshot().contact;
    }
    EXPECT_GT(contacts, recordedContacts / 2);
}

TEST(RecordedToolDevice, BadFilesAreNamedNotCrashedOn) {
    TempDir dir;
    RecordedToolDevice missing(dir.file("nope.palprec"));
    EXPECT_FALSE(missing.open());
    EXPECT_EQ(missing.state(), DeviceState::Fault);
    EXPECT_NE(missing.lastError().find("nope.palprec"), std::string::npos) << missing.lastError();
    DeviceSample sample;
    EXPECT_FALSE(missing.read(sample));

    const std::string garbage = dir.file("garbage.palprec");
    writeBytes(garbage, {'n', 'o', 't', ' ', 'a', ' ', 'r', 'e', 'c'});
    RecordedToolDevice bad(garbage);
    EXPECT_FALSE(bad.open());
    EXPECT_NE(bad.lastError().find("garbage.palprec"), std::string::npos) << bad.lastError();

    // Without the scheme registered, the URI says what to do instead.
    unregisterDeviceFactory(DeviceKind::Replay);
    std::string error;
    EXPECT_FALSE(createDeviceFromUri("replay:" + garbage, error));
    EXPECT_NE(error.find("replay"), std::string::npos) << error;
}

TEST(RecordedToolDevice, RestartScriptPlaysTheRecordingAgainFromItsStart) {
    TempDir dir;
    const std::string path = recordStroke(dir, 2000);
    const RecordingReader reader = RecordingReader::open(path);
    std::vector<RecordedTick> ticks = reader.ticks();
    std::size_t firstRead = 0;
    while (!ticks[firstRead].readOk) ++firstRead;
    registerReplayDeviceScheme();
    std::string error;
    auto device = openDeviceUri("replay:" + path, error);
    ASSERT_TRUE(device) << error;
    DeviceSample sample;
    device->setTimeS(1.0);
    ASSERT_TRUE(device->read(sample));
    device->setTimeS(2.9);  // near the end
    ASSERT_TRUE(device->read(sample));
    ASSERT_NE(sample.positionMm, ticks[firstRead].sample.positionMm);
    device->restartScript();
    device->setTimeS(7.0);
    ASSERT_TRUE(device->read(sample));
    EXPECT_EQ(sample.positionMm, ticks[firstRead].sample.positionMm);
}
