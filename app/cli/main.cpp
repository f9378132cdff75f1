// palpate-cli: headless Palpate. Exit codes: 0 success, 1 failure of the task, 2 bad usage.
#include "app/cli/Commands.h"
#include "engine/record/RecordedToolDevice.h"

#include <csignal>
#include <iostream>
#include <string>
#include <vector>

namespace {
void usage(std::ostream& out) {
    out << "palpate-cli " PALPATE_VERSION " - headless Palpate\n\n"
           "usage:\n"
           "  palpate-cli mesh generate --shape sphere|stomach --vertices N --out FILE\n"
           "  palpate-cli mesh check FILE [--unit mm|cm|m|in|SCALE] [--json]\n"
           "  palpate-cli mesh import IN --out OUT [--unit mm|cm|m|in|SCALE] [--repair] [--keep-all] [--no-fill-holes]\n"
           "                          [--remesh-edge-mm E] [--remesh-iterations N] [--overwrite] [--json]\n"
           "  palpate-cli bench table1 [--json] [--csv FILE] [--quick] [--repeats N]\n"
           "  palpate-cli bench models [--json] [--csv FILE] [--quick] [--sizes N,..] [--models NAME,..] [--repeats N] [--budget-s S]\n"
           "  palpate-cli bench feel [--json] [--csv FILE] [--png FILE] [--quick] [--models NAME,..] [--load N]\n"
           "                         [--loop-models NAME,..|all|none] [--preset FILE] [--repeats N]\n"
           "  palpate-cli demo [--mesh FILE [--mesh-unit U]] [--method previous|hybrid|proposed|coherent] [--json]\n"
           "  palpate-cli loop [--seconds S] [--rate HZ] [--observer-hz 60] [--device URI] [--mesh FILE]\n"
           "                   [--mesh-unit U] [--spin-fraction F] [--no-fifo] [--json] [--csv FILE]\n"
           "  palpate-cli run [--mesh FILE [--mesh-unit U]] [--device URI] [--seconds S] [--record FILE] [--rate HZ]\n"
           "                  [--method M] [--preset FILE] [--note TEXT] [--no-fifo] [--json]\n"
           "                  [--exercise FILE [--mark-at S,..] [--done-at S] [--level L]] [--overwrite]\n"
           "  palpate-cli record info|verify FILE [--json]\n"
           "  palpate-cli record export-csv FILE [--out CSV]\n"
           "  palpate-cli record replay FILE [--mesh FILE [--mesh-unit U]] [--json]\n"
           "  palpate-cli score --recording FILE [--exercise FILE] [--mesh FILE [--mesh-unit U]] [--json] [--pdf FILE] [--trainee NAME [--db FILE]]\n"
           "  palpate-cli trainee list [--db FILE] [--json]\n"
           "  palpate-cli trainee add-session --trainee NAME --recording FILE [--exercise FILE] [--expert] [--db FILE] [--json]\n"
           "  palpate-cli trainee curve --trainee NAME --exercise FILE [--png FILE] [--metric NAME,..] [--db FILE] [--json]\n"
           "  palpate-cli trainee staircase --trainee NAME --exercise FILE [--db FILE] [--json]\n"
           "      --db: the results database (default: the GUI's, results.sqlite in its data folder)\n"
           "  palpate-cli results list|export|sync [--db LOCATION] [--json] [--csv FILE] [--local FILE]\n"
           "      LOCATION: an SQLite file or postgresql://[user@]host[:port]/database (docs/results-store.md)\n"
           "  palpate-cli sweep [--reference punch|fem] [--json] [--csv FILE] [--png FILE] [--quick] [--shapes sphere,stomach]\n"
           "                    [--sizes N,..] [--max-rings N] [--no-paper] [--no-others] [--repeats N] [TISSUE]\n"
           "      --reference fem: the filled stomach's FEM (linear and hyperelastic) at its thin, thick and curved sites\n"
           "  palpate-cli accuracy --reference punch|hertz [--json] [--quick] [--nu LIST] [--levels LIST]\n"
           "  palpate-cli accuracy --reference uniaxial-neo-hookean|uniaxial-exponential|indentation-neo-hookean\n"
           "                       [--json] [--quick] [--nu LIST] [--levels LIST]\n"
           "  palpate-cli calibrate [--mesh FILE [--mesh-unit U]] [--rings N] [--vertex V] [--fem] [--json] [--out PRESET] [--name NAME]\n"
           "                        [--nonlinear [--nonlinear-depth MM] [--stiffening-source TEXT]] [TISSUE]\n"
           "      TISSUE: [--preset FILE] [--youngs-kpa E] [--poisson NU] [--tool-radius MM] [--stiffening-exponent B]\n"
           "  palpate-cli stability --list | --model NAME [--json] [--csv FILE] [--png FILE] [--quick]\n"
           "  palpate-cli devices [--json]\n"
           "  palpate-cli lod levels --mesh FILE [--mesh-unit U] [--json] [--no-cache] [--min-vertices N] [--max-levels N]\n"
           "  palpate-cli lod plan (--mesh FILE [--mesh-unit U] | --exercise FILE) --error E --budget-us T [--json] [--quick]\n"
           "                       [--rings N,..] [--repeats N] [--no-cache] [TISSUE]\n"
           "      U: a mesh file's unit: mm (default), cm, m, in, or mm per file unit (docs/meshes.md, \"Units\")\n"
           "  palpate-cli --help | --version\n";
}
}  // namespace

int main(int argc, char** argv) {
    // Past a file-size limit (ulimit -f) write(2) then fails with EFBIG, which the writers report
    // with the file's name, instead of the signal killing the process without a word.
    std::signal(SIGXFSZ, SIG_IGN);
    palpate::registerReplayDeviceScheme();  // replay:FILE, like every other device URI
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty()) {
        usage(std::cerr);
        return 2;
    }
    const std::string command = words.front();
    words.erase(words.begin());
    if (command == "--help" || command == "-h" || command == "help") {
        usage(std::cout);
        return 0;
    }
    if (command == "--version") {
        std::cout << "palpate-cli " PALPATE_VERSION "\n";
        return 0;
    }
    try {
        if (command == "mesh") return palpate::cli::meshCommand(words);
        if (command == "bench") return palpate::cli::benchCommand(words);
        if (command == "demo") return palpate::cli::demoCommand(words);
        if (command == "loop") return palpate::cli::loopCommand(words);
        if (command == "run") return palpate::cli::runCommand(words);
        if (command == "record") return palpate::cli::recordCommand(words);
        if (command == "score") return palpate::cli::scoreCommand(words);
        if (command == "trainee") return palpate::cli::traineeCommand(words);
        if (command == "results") return palpate::cli::resultsCommand(words);
        if (command == "sweep") return palpate::cli::sweepCommand(words);
        if (command == "stability") return palpate::cli::stabilityCommand(words);
        if (command == "calibrate") return palpate::cli::calibrateCommand(words);
        if (command == "accuracy") return palpate::cli::accuracyCommand(words);
        if (command == "devices") return palpate::cli::devicesCommand(words);
        if (command == "lod") return palpate::cli::lodCommand(words);
    } catch (const std::exception& e) {
        std::cerr << "palpate-cli " << command << ": " << e.what() << "\n";
        return 1;
    }
    std::cerr << "palpate-cli: unknown command '" << command << "'\n";
    usage(std::cerr);
    return 2;
}
