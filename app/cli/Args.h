#pragma once
// Minimal command-line options: "--name value" and "--flag", with clear errors.

#include <optional>
#include <utility>
#include <string>
#include <vector>

namespace palpate::cli {

class Args {
public:
    Args(std::vector<std::string> words, std::vector<std::string> flags, std::vector<std::string> options);
    bool ok() const { return mError.empty(); }
    const std::string& error() const { return mError; }
    bool flag(const std::string& name) const;
    std::optional<std::string> option(const std::string& name) const;
    const std::vector<std::string>& positional() const { return mPositional; }

private:
    std::vector<std::string> mFlagsSet;
    std::vector<std::pair<std::string, std::string>> mOptions;
    std::vector<std::string> mPositional;
    std::string mError;
};

/// Whether two paths name the same file (through links or another spelling); false when either is "".
bool sameFile(const std::string& a, const std::string& b);
/// An output is never one of the inputs: "" when `output` is none of `inputs` (pairs of a path and
/// what it is, e.g. {"m.off", "mesh"}), else the message for `option` ("--record r.rec is the
/// mesh file: ...").
std::string outputIsAnInput(const std::string& option, const std::string& output,
                            const std::vector<std::pair<std::string, std::string>>& inputs);

/// Parses a positive integer, or returns nullopt.
std::optional<long long> parsePositiveInt(const std::string& text);
/// "a,b,,c" -> {"a", "b", "c"}: an option's comma-separated list, empty items dropped.
std::vector<std::string> splitList(const std::string& text);
/// Parses a whole finite number ("1.5", "2e3"), or returns nullopt.
std::optional<double> parseNumber(const std::string& text);

}  // namespace palpate::cli
