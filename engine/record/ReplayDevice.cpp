#include "engine/record/ReplayDevice.h"

namespace palpate {

bool ReplayDevice::read(DeviceSample& sample) {
    if (!mFeed.tick || !mFeed.tick->readOk) return false;
    sample = mFeed.tick->sample;
    return true;
}

}  // namespace palpate
