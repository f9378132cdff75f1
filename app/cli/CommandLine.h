#pragma once
// palpate-cli's command line: every command, subcommand and option is defined once with CLI11, and
// the parser, the checks of each option's type and range and every --help are made from those
// definitions. Exit codes: 0 success, 1 failure of the task, 2 bad usage.

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace palpate::cli {

/// What one command was given on the command line, read from its definition once CLI11 parsed
/// and checked it. Names are the options' long names without "--".
class Given {
public:
    explicit Given(const CLI::App& command) : mCommand(&command) {}
    bool flag(const std::string& name) const;
    /// The option's value, or nullopt when it was not given (or the command has no such option).
    std::optional<std::string> option(const std::string& name) const;
    /// The values of the command's positional arguments, in the order they are defined.
    std::vector<std::string> positional() const;

private:
    const CLI::App* mCommand;
};

/// What runs a command once its command line parsed: the exit code.
using CommandRun = std::function<int(const Given&)>;

/// The whole command line of palpate-cli.
class CommandLine {
public:
    CommandLine();
    /// Parses `words` (the arguments after the program's name), runs the chosen command and returns
    /// its exit code; a usage error is printed naming the command and the option, exit code 2.
    int run(const std::vector<std::string>& words);

    CLI::App& root() { return mRoot; }
    /// A command that runs: `run` is called with what it was given.
    CLI::App* command(CLI::App& parent, const std::string& name, const std::string& description, CommandRun run);
    /// A command that only holds subcommands (mesh, bench, ...): exactly one of them is needed.
    CLI::App* group(CLI::App& parent, const std::string& name, const std::string& description);

private:
    int runChosen();
    std::string usageError(const CLI::ParseError& e) const;

    CLI::App mRoot;
    std::vector<std::pair<const CLI::App*, CommandRun>> mRuns;
};

/// "--name VALUE": a value given at most once.
CLI::Option* addValue(CLI::App& command, const std::string& name, const std::string& valueName,
                      const std::string& description);
/// "--name": a flag given at most once.
CLI::Option* addFlag(CLI::App& command, const std::string& name, const std::string& description);
/// A positional argument (FILE).
CLI::Option* addPositional(CLI::App& command, const std::string& name, const std::string& description);

/// A finite number in a range; `lowerOpen`/`upperOpen` leave the end out. The help and the
/// message show the range in interval notation: "must be a number in (0, 86400], not '-1'".
CLI::Validator numberIn(double lo, double hi, bool lowerOpen = false, bool upperOpen = false);
/// A finite number (any size).
CLI::Validator anyNumber();
/// A whole number from `lo` to `hi`.
CLI::Validator wholeNumberIn(long long lo, long long hi);
/// One of `names`: "must be one of punch, hertz, not 'flat'".
CLI::Validator oneOf(std::vector<std::string> names);

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
