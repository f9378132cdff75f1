#include "app/cli/Args.h"

#include <sstream>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>

namespace palpate::cli {

Args::Args(std::vector<std::string> words, std::vector<std::string> flags, std::vector<std::string> options) {
    auto known = [](const std::vector<std::string>& list, const std::string& w) {
        return std::find(list.begin(), list.end(), w) != list.end();
    };
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        if (w.rfind("--", 0) != 0) {
            mPositional.push_back(w);
            continue;
        }
        const std::string name = w.substr(2);
        if (known(flags, name)) {
            mFlagsSet.push_back(name);
        } else if (known(options, name)) {
            if (i + 1 >= words.size()) {
                mError = "option --" + name + " needs a value";
                return;
            }
            mOptions.emplace_back(name, words[++i]);
        } else {
            mError = "unknown option " + w;
            return;
        }
    }
}

bool Args::flag(const std::string& name) const {
    return std::find(mFlagsSet.begin(), mFlagsSet.end(), name) != mFlagsSet.end();
}

std::optional<std::string> Args::option(const std::string& name) const {
    for (const auto& [k, v] : mOptions)
        if (k == name) return v;
    return std::nullopt;
}

bool sameFile(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty()) return false;
    std::error_code ec;
    if (std::filesystem::exists(a, ec) && std::filesystem::exists(b, ec)) {
        const bool same = std::filesystem::equivalent(a, b, ec);
        return !ec && same;
    }
    // One of them does not exist yet: compare what they would be.
    const auto ca = std::filesystem::weakly_canonical(a, ec);
    if (ec) return false;
    const auto cb = std::filesystem::weakly_canonical(b, ec);
    return !ec && ca == cb;
}

std::string outputIsAnInput(const std::string& option, const std::string& output,
                            const std::vector<std::pair<std::string, std::string>>& inputs) {
    for (const auto& [input, what] : inputs)
        if (sameFile(output, input))
            return "--" + option + " " + output + " is the " + what + " file " + input +
                   ": an output is never written over an input; choose another file";
    return "";
}

std::optional<long long> parsePositiveInt(const std::string& text) {
    long long value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value <= 0) return std::nullopt;
    return value;
}

std::optional<double> parseNumber(const std::string& text) {
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used != text.size() || !std::isfinite(v)) return std::nullopt;
        return v;
    } catch (...) {
        return std::nullopt;
    }
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream s(text);
    for (std::string item; std::getline(s, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

}  // namespace palpate::cli
