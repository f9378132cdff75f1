// libFuzzer target for the waypoint file parser (sim:path:FILE): any bytes, no crash; either
// waypoints or an error naming the source, never both; waypoints have strictly increasing times
// and finite coordinates. Built as `fuzz_waypoint` by the `fuzz` preset; io_tests runs the same
// function over tests/io/corpus/waypoint and deterministic mutations of it.
#include "device/WaypointFile.h"
#include "tests/io/FuzzCheck.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

int palpateFuzzWaypoint(const std::uint8_t* data, std::size_t size) {
    using namespace palpate;
    std::vector<Waypoint> out;
    std::string error;
    const bool ok = (error = parseWaypoints(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz", out))
                        .empty();
    fuzzCheck("fuzz_waypoint", ok == error.empty());
    fuzzCheck("fuzz_waypoint", ok == !out.empty());
    if (!ok) fuzzCheck("fuzz_waypoint", error.rfind("fuzz:", 0) == 0);
    for (std::size_t i = 0; i < out.size(); ++i) {
        fuzzCheck("fuzz_waypoint", std::isfinite(out[i].timeS));
        fuzzCheck("fuzz_waypoint", std::isfinite(out[i].positionMm.x) && std::isfinite(out[i].positionMm.y) &&
                                       std::isfinite(out[i].positionMm.z));
        if (i > 0) fuzzCheck("fuzz_waypoint", out[i].timeS > out[i - 1].timeS);
    }
    // The same bytes as the scripted trainee's button lines.
    WaypointButtons buttons;
    std::string buttonError;
    const bool buttonsOk = (buttonError = parseWaypointButtons(
                                std::string_view(reinterpret_cast<const char*>(data), size), "fuzz", buttons))
                               .empty();
    fuzzCheck("fuzz_waypoint", buttonsOk == buttonError.empty());
    if (!buttonsOk) fuzzCheck("fuzz_waypoint", buttonError.rfind("fuzz:", 0) == 0 && buttons.marksS.empty());
    for (double t : buttons.marksS) fuzzCheck("fuzz_waypoint", std::isfinite(t) && t >= 0.0);
    if (buttons.doneS) fuzzCheck("fuzz_waypoint", std::isfinite(*buttons.doneS) && *buttons.doneS >= 0.0);
    return 0;
}

#ifdef PALPATE_FUZZ_TARGET
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return palpateFuzzWaypoint(data, size);
}
#endif
