// palpate-cli devices: which device backends this build has, and which devices are connected now
// (with the URI to pass as --device, and the udev rule to install when a node is not accessible).
#include "app/cli/Commands.h"
#include "device/open/DeviceDiscovery.h"
#include "device/open/DeviceUri.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace palpate::cli {

namespace {

int devicesCommand(const Given& args) {
    const std::vector<BackendInfo> backends = listDeviceBackends();
    const std::vector<ConnectedDevice> devices = discoverDevices();
    const std::vector<DeviceSchemeInfo> schemes = listDeviceSchemes();

    if (args.flag("json")) {
        nlohmann::json j;
        j["backends"] = nlohmann::json::array();
        for (const BackendInfo& b : backends)
            j["backends"].push_back({{"name", b.name}, {"library", b.library}, {"compiled_in", b.compiledIn},
                                     {"experimental", b.experimental}});
        j["devices"] = nlohmann::json::array();
        for (const ConnectedDevice& d : devices) {
            char vidpid[16];
            std::snprintf(vidpid, sizeof vidpid, "%04x:%04x", unsigned(d.vendorId), unsigned(d.productId));
            j["devices"].push_back({{"backend", d.backend}, {"uri", d.uri}, {"description", d.description},
                                    {"node", d.node}, {"vid_pid", vidpid}, {"serial", d.serial},
                                    {"accessible", d.accessible}, {"problem", d.problem}});
        }
        j["schemes"] = nlohmann::json::array();
        for (const DeviceSchemeInfo& s : schemes) j["schemes"].push_back({{"uri", s.uri}, {"description", s.description}});
        std::cout << j.dump(2) << "\n";
        return 0;
    }

    std::cout << "Backends:\n";
    for (const BackendInfo& b : backends)
        std::cout << "  " << b.name << (b.experimental ? " (experimental)" : "") << ": "
                  << (b.compiledIn ? "compiled in" : "NOT compiled in") << " - " << b.library << "\n";
    std::cout << "\nConnected devices:\n";
    if (devices.empty()) std::cout << "  none found (SpaceMouse, HID PID joystick, Novint Falcon)\n";
    for (const ConnectedDevice& d : devices) {
        std::cout << "  " << d.uri << "  " << d.description << "  [" << d.node << "]"
                  << (d.serial.empty() ? "" : "  serial " + d.serial) << "\n";
        if (!d.accessible) std::cout << "      " << d.problem << "\n";
    }
    std::cout << "\nURI forms (also: hid:VID:PID[:SERIAL], replay:FILE):\n";
    for (const DeviceSchemeInfo& s : schemes) std::cout << "  " << s.uri << "  " << s.description << "\n";
    return 0;
}

}  // namespace

void defineDevicesCommand(CommandLine& cli) {
    CLI::App* devices = cli.command(cli.root(), "devices", "the device backends compiled in and the devices connected",
                                    devicesCommand);
    addFlag(*devices, "json", "print JSON");
}

}  // namespace palpate::cli
