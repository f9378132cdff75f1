#include "app/cli/CommandLine.h"

#include "app/cli/Commands.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace palpate::cli {

namespace {

/// The numbers of a range as people write them: 86400, 0.5, 1e+06.
std::string numberText(double value) {
    std::ostringstream s;
    s << value;
    return s.str();
}

/// The command that was chosen: the deepest parsed subcommand (the root when none).
const CLI::App* chosenCommand(const CLI::App& root) {
    const CLI::App* at = &root;
    while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
    return at;
}

/// "mesh generate" for that command; "palpate-cli" for the root.
std::string commandPath(const CLI::App& command) {
    std::string path;
    for (const CLI::App* at = &command; at->get_parent() != nullptr; at = at->get_parent())
        path = at->get_name() + (path.empty() ? "" : " " + path);
    return path.empty() ? command.get_name() : path;
}

std::vector<const CLI::App*> subcommandsOf(const CLI::App& command) {
    std::vector<const CLI::App*> shown;
    for (const CLI::App* sub : command.get_subcommands([](const CLI::App*) { return true; }))
        if (!sub->get_group().empty()) shown.push_back(sub);
    return shown;
}

std::string namesText(const std::vector<const CLI::App*>& commands) {
    std::string text;
    for (std::size_t i = 0; i < commands.size(); ++i)
        text += (i == 0 ? "" : i + 1 == commands.size() ? " or " : ", ") + commands[i]->get_name();
    return text;
}

/// The long names of a command's options ("--mesh"), then its positionals ("FILE"), in order.
std::vector<std::string> optionNames(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* o : command.get_options()) {
        if (o->get_positional()) names.push_back(o->get_name(true));
        for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    }
    return names;
}

/// "run: --seconds is given 2 times; give it once" when an option of the command (or of a command
/// above it) was given more than once, else "".
std::string repeatedOption(const CLI::App& chosen) {
    for (const CLI::App* at = &chosen; at != nullptr; at = at->get_parent())
        for (const CLI::Option* o : at->get_options())
            if (o->count() > 1 && !o->get_positional())
                return commandPath(chosen) + ": " + o->get_name() + " is given " + std::to_string(o->count()) +
                       " times; give it once";
    return "";
}

/// help-tree: every command and subcommand, one a line: its path, a tab, its options separated by
/// spaces. The test that walks every --help reads it.
void printHelpTree(const CLI::App& command, std::ostream& out) {
    for (const CLI::App* sub : subcommandsOf(command)) {
        out << commandPath(*sub) << "\t";
        const std::vector<std::string> names = optionNames(*sub);
        for (std::size_t i = 0; i < names.size(); ++i) out << (i == 0 ? "" : " ") << names[i];
        out << "\n";
        printHelpTree(*sub, out);
    }
}

}  // namespace

bool Given::flag(const std::string& name) const {
    const CLI::Option* o = mCommand->get_option_no_throw("--" + name);
    return o != nullptr && o->count() > 0;
}

std::optional<std::string> Given::option(const std::string& name) const {
    const CLI::Option* o = mCommand->get_option_no_throw("--" + name);
    if (o == nullptr || o->count() == 0) return std::nullopt;
    return o->results().back();
}

std::vector<std::string> Given::positional() const {
    std::vector<std::string> values;
    for (const CLI::Option* o : mCommand->get_options())
        if (o->get_positional())
            for (const std::string& v : o->results()) values.push_back(v);
    return values;
}

CommandLine::CommandLine() : mRoot("palpate-cli " PALPATE_VERSION " - headless Palpate", "palpate-cli") {
    mRoot.set_version_flag("--version", "palpate-cli " PALPATE_VERSION);
    mRoot.require_subcommand(1);
    mRoot.footer(
        "Exit codes: 0 success, 1 failure of the task, 2 bad usage.\n"
        "Every command and subcommand takes --help.");
    defineMeshCommands(*this);
    defineBenchCommands(*this);
    defineDemoCommand(*this);
    defineLoopCommand(*this);
    defineRunCommand(*this);
    defineRecordCommands(*this);
    defineScoreCommand(*this);
    defineTraineeCommands(*this);
    defineExerciseCommands(*this);
    defineResultsCommands(*this);
    defineSweepCommand(*this);
    defineAccuracyCommand(*this);
    defineCalibrateCommand(*this);
    defineStabilityCommand(*this);
    defineDevicesCommand(*this);
    defineLodCommands(*this);
    // Hidden (no group): lists every command with its options for the test that walks --help.
    command(mRoot, "help-tree", "every command and its options, one a line", [this](const Given&) {
        printHelpTree(mRoot, std::cout);
        return 0;
    })->group("");
}

CLI::App* CommandLine::command(CLI::App& parent, const std::string& name, const std::string& description,
                               CommandRun run) {
    CLI::App* sub = parent.add_subcommand(name, description);
    mRuns.emplace_back(sub, std::move(run));
    return sub;
}

CLI::App* CommandLine::group(CLI::App& parent, const std::string& name, const std::string& description) {
    CLI::App* sub = parent.add_subcommand(name, description);
    sub->require_subcommand(1);
    return sub;
}

int CommandLine::run(const std::vector<std::string>& words) {
    if (words.empty()) {
        std::cerr << mRoot.help();
        return 2;
    }
    if (words.front() == "help") {  // "palpate-cli help", as "palpate-cli --help"
        std::cout << mRoot.help();
        return 0;
    }
    std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 takes them last first
    try {
        mRoot.parse(reversed);
    } catch (const CLI::Success& e) {  // --help, --version
        return mRoot.exit(e, std::cout, std::cerr);
    } catch (const CLI::ParseError& e) {
        std::cerr << usageError(e) << "\n";
        std::cerr << "(palpate-cli " << (chosenCommand(mRoot) == &mRoot ? "" : commandPath(*chosenCommand(mRoot)) + " ")
                  << "--help lists what it takes)\n";
        return 2;
    }
    return runChosen();
}

int CommandLine::runChosen() {
    const CLI::App* chosen = chosenCommand(mRoot);
    // CLI11 lets a flag be repeated; it is refused like a repeated option.
    if (const std::string repeated = repeatedOption(*chosen); !repeated.empty()) {
        std::cerr << repeated << "\n";
        return 2;
    }
    for (const auto& [command, run] : mRuns)
        if (command == chosen) return run(Given(*chosen));
    std::cerr << commandPath(*chosen) << ": needs a subcommand\n";
    return 2;
}

std::string CommandLine::usageError(const CLI::ParseError& e) const {
    const CLI::App* chosen = chosenCommand(mRoot);
    const std::string path = commandPath(*chosen);
    if (const std::string repeated = repeatedOption(*chosen); !repeated.empty()) return repeated;
    const std::vector<const CLI::App*> subs = subcommandsOf(*chosen);
    const std::vector<std::string> extra = chosen->remaining(false);
    const bool isRoot = chosen == &mRoot;
    if (!subs.empty()) {  // a group, none of whose subcommands was given
        if (!extra.empty() && !extra.front().starts_with("-"))
            return path + ": unknown " + (isRoot ? "command" : "subcommand") + " '" + extra.front() + "' (use " +
                   namesText(subs) + ")";
        if (extra.empty() && dynamic_cast<const CLI::RequiredError*>(&e) != nullptr)
            return path + ": needs a " + (isRoot ? "command" : "subcommand") + ": " + namesText(subs);
    }
    if (!extra.empty())
        return path + ": " + (extra.front().starts_with("-") ? "unknown option " : "unexpected argument ") + "'" +
               extra.front() + "'";
    // CLI11 says "--mesh: 1 required FILE missing" of an option given last without its value.
    const std::string what = e.what();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr && what.ends_with(" missing") &&
        what.find(": ") != std::string::npos)
        return path + ": " + what.substr(0, what.find(": ")) + " needs a value";
    return path + ": " + what;
}

CLI::Option* addValue(CLI::App& command, const std::string& name, const std::string& valueName,
                      const std::string& description) {
    return command.add_option("--" + name, description)
        ->type_name(valueName)
        ->multi_option_policy(CLI::MultiOptionPolicy::Throw);
}

CLI::Option* addFlag(CLI::App& command, const std::string& name, const std::string& description) {
    return command.add_flag("--" + name, description);
}

CLI::Option* addPositional(CLI::App& command, const std::string& name, const std::string& description) {
    return command.add_option(name, description)->type_name("");
}

CLI::Validator numberIn(double lo, double hi, bool lowerOpen, bool upperOpen) {
    const std::string range = std::string(lowerOpen ? "(" : "[") + numberText(lo) + ", " + numberText(hi) +
                              (upperOpen ? ")" : "]");
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            const auto value = parseNumber(text);
            const bool inside = value && (lowerOpen ? *value > lo : *value >= lo) &&
                                (upperOpen ? *value < hi : *value <= hi);
            return inside ? std::string() : "must be a number in " + range + ", not '" + text + "'";
        },
        "in " + range);
}

CLI::Validator anyNumber() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            return parseNumber(text) ? std::string() : "'" + text + "' is not a number";
        },
        "");
}

CLI::Validator wholeNumberIn(long long lo, long long hi) {
    const std::string range = "from " + std::to_string(lo) + " to " + std::to_string(hi);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            long long value = 0;
            const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
            const bool whole = ec == std::errc() && end == text.data() + text.size();
            return whole && value >= lo && value <= hi ? std::string()
                                                       : "must be a whole number " + range + ", not '" + text + "'";
        },
        range);
}

CLI::Validator oneOf(std::vector<std::string> names) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : "|") + n;
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            if (std::find(names.begin(), names.end(), text) != names.end()) return "";
            std::string choices;
            for (const std::string& n : names) choices += (choices.empty() ? "" : ", ") + n;
            return "must be one of " + choices + ", not '" + text + "'";
        },
        list);
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
