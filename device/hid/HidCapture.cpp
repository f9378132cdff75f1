#include "device/hid/HidCapture.h"

#include <fstream>
#include <sstream>

namespace palpate {

std::string loadHidCapture(const std::string& path, std::vector<FakeHidRead>& reads) {
    std::string error;
    reads.clear();
    std::ifstream in(path);
    if (!in) {
        error = "HID capture '" + path + "': cannot be read";
        return error;
    }
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        std::string word;
        std::vector<std::uint8_t> bytes;
        bool special = false;
        while (words >> word) {
            if (word == "timeout" || word == "error") {
                if (!bytes.empty() || special) {
                    error = "HID capture '" + path + "' line " + std::to_string(number) + ": '" + word + "' must stand alone";
                    return error;
                }
                reads.push_back(word == "timeout" ? FakeHidRead::timeout() : FakeHidRead::error());
                special = true;
                continue;
            }
            std::size_t used = 0;
            unsigned long value = 0;
            try {
                value = std::stoul(word, &used, 16);
            } catch (...) {
                used = 0;
            }
            if (special || used != word.size() || word.size() > 2 || value > 0xff) {
                error = "HID capture '" + path + "' line " + std::to_string(number) + ": '" + word + "' is not a hex byte";
                return error;
            }
            bytes.push_back(std::uint8_t(value));
        }
        if (!bytes.empty()) reads.push_back(FakeHidRead::bytes(std::move(bytes)));
    }
    return {};
}

}  // namespace palpate
