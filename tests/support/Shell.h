#pragma once
// Runs a shell command line in a child process and keeps what it printed: the one runner of the
// tests that start palpate-cli or a tool as a user would (the fault suite's ChildProcess adds
// limits and timeouts).

#include <string>

namespace palpate::test {

struct CommandResult {
    int exitCode = -1;   ///< 128 + the signal when a signal ended it
    std::string output;  ///< stdout and stderr
};

/// Runs `commandLine` with /bin/sh, stderr joined to stdout.
CommandResult runCommand(const std::string& commandLine);
/// Single-quotes a word for /bin/sh.
std::string shellQuote(const std::string& text);

}  // namespace palpate::test
