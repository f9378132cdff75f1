// palpate-cli: headless Palpate. Exit codes: 0 success, 1 failure of the task, 2 bad usage.
#include "app/cli/CommandLine.h"
#include "engine/record/RecordedToolDevice.h"

#include <csignal>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    // Past a file-size limit (ulimit -f) write(2) then fails with EFBIG, which the writers report
    // with the file's name, instead of the signal killing the process without a word.
    std::signal(SIGXFSZ, SIG_IGN);
    palpate::registerReplayDeviceScheme();  // replay:FILE, like every other device URI
    const std::vector<std::string> words(argv + 1, argv + argc);
    try {
        palpate::cli::CommandLine cli;
        return cli.run(words);
    } catch (const std::exception& e) {
        std::cerr << "palpate-cli " << (words.empty() ? std::string() : words.front()) << ": " << e.what() << "\n";
        return 1;
    }
}
