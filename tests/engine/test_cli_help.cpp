// palpate-cli's command line as a user meets it: every command and subcommand answers --help
// (exit 0) listing each option it takes, the top-level --help lists exactly the commands there
// are, and the parser's rules: --x=value, a repeated option refused, ranges named, options only
// where they apply. The commands are enumerated from the CLI's own definition (the hidden
// `palpate-cli help-tree`), so a new command or option is walked without changing this test.

#include "tests/engine/TestMeshes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace palpate {
namespace {

using test::runCommand;
using test::shellQuote;

class CliHelp : public ::testing::Test {
protected:
    void SetUp() override {
        cli = test::cliPath();
        if (cli.empty()) GTEST_SKIP() << "built without PALPATE_CLI_PATH";
        ASSERT_TRUE(std::filesystem::exists(cli)) << cli;
    }
    test::CommandResult run(const std::string& args) const { return runCommand(shellQuote(cli) + " " + args); }

    /// help-tree: "mesh generate" -> {"--shape", "--vertices", "--out", "--help"}, every command.
    std::map<std::string, std::vector<std::string>> tree() const {
        const auto r = run("help-tree");
        EXPECT_EQ(r.exitCode, 0) << r.output;
        std::map<std::string, std::vector<std::string>> commands;
        std::istringstream lines(r.output);
        for (std::string line; std::getline(lines, line);) {
            const auto tab = line.find('\t');
            if (tab == std::string::npos) continue;
            std::vector<std::string>& options = commands[line.substr(0, tab)];
            std::istringstream words(line.substr(tab + 1));
            for (std::string word; words >> word;) options.push_back(word);
        }
        return commands;
    }

    std::string cli;
};

/// The names a --help lists under "Subcommands:".
std::set<std::string> listedSubcommands(const std::string& help) {
    std::set<std::string> names;
    std::istringstream lines(help);
    bool inSection = false;
    for (std::string line; std::getline(lines, line);) {
        if (line.starts_with("Subcommands:")) {
            inSection = true;
            continue;
        }
        if (!inSection) continue;
        if (line.empty() || !line.starts_with("  ")) break;
        std::istringstream words(line);
        std::string name;
        words >> name;
        names.insert(name);
    }
    return names;
}

/// Whether `help` names `option` as a whole word ("--mesh" is not found in "--mesh-unit").
bool namesOption(const std::string& help, const std::string& option) {
    for (auto at = help.find(option); at != std::string::npos; at = help.find(option, at + 1)) {
        const std::size_t end = at + option.size();
        const bool startOk = at == 0 || help[at - 1] == ' ' || help[at - 1] == ',';
        const bool endOk = end == help.size() ||
                           !(std::isalnum(static_cast<unsigned char>(help[end])) || help[end] == '-');
        if (startOk && endOk) return true;
    }
    return false;
}

TEST_F(CliHelp, EveryCommandAndSubcommandListsItsOptions) {
    const auto commands = tree();
    ASSERT_GE(commands.size(), 20u);
    // Among them those that once answered "unknown option --help".
    for (const char* known :
         {"accuracy", "trainee curve", "results class", "results grant", "results revoke", "lod plan"})
        EXPECT_TRUE(commands.contains(known)) << known;
    for (const auto& [path, options] : commands) {
        const auto r = run(path + " --help");
        EXPECT_EQ(r.exitCode, 0) << path << " --help\n" << r.output;
        EXPECT_NE(r.output.find("palpate-cli " + path), std::string::npos) << path << " --help\n" << r.output;
        for (const std::string& option : options)
            EXPECT_TRUE(namesOption(r.output, option)) << path << " --help does not list " << option << "\n"
                                                       << r.output;
    }
}

TEST_F(CliHelp, EachHelpListsExactlyItsSubcommands) {
    const auto commands = tree();
    std::map<std::string, std::set<std::string>> children;  // "" is the top level
    for (const auto& [path, options] : commands) {
        const auto space = path.rfind(' ');
        children[space == std::string::npos ? "" : path.substr(0, space)].insert(space == std::string::npos
                                                                                     ? path
                                                                                     : path.substr(space + 1));
    }
    for (const auto& [parent, names] : children) {
        const auto r = run(parent.empty() ? "--help" : parent + " --help");
        EXPECT_EQ(r.exitCode, 0) << parent << " --help\n" << r.output;
        EXPECT_EQ(listedSubcommands(r.output), names) << parent << " --help\n" << r.output;
    }
    EXPECT_FALSE(listedSubcommands(run("--help").output).contains("help-tree"));
    EXPECT_EQ(run("help").exitCode, 0);
}

TEST_F(CliHelp, ValuesMayFollowAnEqualsSign) {
    test::TempDir dir;
    const std::string path = dir.file("m.off");
    const auto r = run("mesh generate --shape=sphere --vertices=200 --out=" + shellQuote(path));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(path));
    EXPECT_EQ(run("mesh check --json " + shellQuote(path) + " --unit=mm").exitCode, 0);
}

TEST_F(CliHelp, ARepeatedOptionIsRefusedNamingIt) {
    for (const char* args : {"loop --seconds 1 --seconds 2", "devices --json --json", "loop --seconds=1 --seconds=2"}) {
        const auto r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        const std::string option = std::string(args).find("--json") != std::string::npos ? "--json" : "--seconds";
        EXPECT_NE(r.output.find(option + " is given 2 times"), std::string::npos) << args << "\n" << r.output;
    }
}

TEST_F(CliHelp, AValueOutOfRangeNamesTheOptionAndTheRange) {
    auto r = run("loop --seconds 0");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--seconds"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(0, 86400]"), std::string::npos) << r.output;
    r = run("bench table1 --repeats=101");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--repeats"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("from 1 to 100"), std::string::npos) << r.output;
    r = run("sweep --reference flat");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("punch, fem"), std::string::npos) << r.output;
}

TEST_F(CliHelp, OptionsAreTakenOnlyWhereTheyApply) {
    // The options of one results subcommand are not another's (results and trainee need a build
    // with the GUI).
    const bool withResults = tree().contains("results list");
    for (const std::string args :
         {"results list --csv x.csv", "results export --role r", "results revoke --local f", "record info --out x.csv",
          "record verify --mesh m.off", "trainee list --png p.png"}) {
        if (!withResults && (args.starts_with("results") || args.starts_with("trainee"))) continue;
        const auto r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("unknown option"), std::string::npos) << args << "\n" << r.output;
    }
    const auto r = run("record frobnicate x");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("unknown subcommand 'frobnicate'"), std::string::npos) << r.output;
    const auto none = run("frobnicate");
    EXPECT_EQ(none.exitCode, 2) << none.output;
    EXPECT_NE(none.output.find("unknown command 'frobnicate'"), std::string::npos) << none.output;
    EXPECT_EQ(run("").exitCode, 2);
}

}  // namespace
}  // namespace palpate
