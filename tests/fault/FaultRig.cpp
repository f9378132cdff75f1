#include "FaultRig.h"

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <random>
#include <regex>
#include <sstream>

namespace palpate::fault {

std::string cliPath() { return PALPATE_CLI_PATH; }
std::string shimPath() { return PALPATE_FAULT_SHIM_PATH; }
std::string sourcePath(const std::string& relative) { return std::string(PALPATE_SOURCE_DIR) + "/" + relative; }

bool haveGui() {
#ifdef PALPATE_GUI_PATH
    return true;
#else
    return false;
#endif
}

std::string guiPath() {
#ifdef PALPATE_GUI_PATH
    return PALPATE_GUI_PATH;
#else
    return {};
#endif
}

bool sanitized() {
#ifdef PALPATE_FAULT_SANITIZED
    return true;
#else
    return false;
#endif
}

bool havePdf() {
#ifdef PALPATE_FAULT_HAVE_PDF
    return true;
#else
    return false;
#endif
}

namespace {

std::string uniqueSuffix() {
    static std::mt19937_64 generator(std::random_device{}() ^ static_cast<unsigned long long>(::getpid()));
    std::ostringstream s;
    s << std::hex << generator();
    return s.str();
}

}  // namespace

Scratch::Scratch() {
    mRoot = fs::temp_directory_path() / ("palpate-fault-" + std::to_string(::getpid()) + "-" + uniqueSuffix());
    fs::create_directories(mRoot / "in");
    fs::create_directories(mRoot / "out");
    fs::create_directories(mRoot / "home");
    fs::create_directories(mRoot / "runtime");
    // Qt insists on a private runtime folder (and warns on stderr otherwise).
    fs::permissions(mRoot / "runtime", fs::perms::owner_all, fs::perm_options::replace);
}

Scratch::~Scratch() {
    std::error_code ec;
    // A FIFO or a 2 GB sparse file is removed like any other entry; nothing under it is followed.
    fs::remove_all(mRoot, ec);
}

ChildSpec cliSpec(const Scratch& scratch, std::vector<std::string> args) {
    ChildSpec spec;
    if (args.empty() || args[0].empty() || args[0][0] != '/') args.insert(args.begin(), cliPath());
    spec.argv = std::move(args);
    const std::string home = (scratch.root() / "home").string();
    spec.env["HOME"] = home;
    spec.env["XDG_CONFIG_HOME"] = home + "/.config";
    spec.env["XDG_DATA_HOME"] = home + "/.local/share";
    spec.env["XDG_CACHE_HOME"] = home + "/.cache";
    spec.env["XDG_RUNTIME_DIR"] = (scratch.root() / "runtime").string();
    spec.env["QT_QPA_PLATFORM"] = "offscreen";
    spec.env["LC_ALL"] = "C";
    spec.env["LANGUAGE"] = "en";
    // A sanitized child otherwise refuses a preloaded library that comes before its runtime.
    const char* asan = std::getenv("ASAN_OPTIONS");
    spec.env["ASAN_OPTIONS"] = std::string(asan ? asan : "") + (asan && *asan ? ":" : "") + "verify_asan_link_order=0";
    spec.workingDir = scratch.root().string();
    return spec;
}

static void addShim(ChildSpec& spec, const Scratch& scratch) {
    spec.env["LD_PRELOAD"] = shimPath();
    spec.env["PALPATE_FAULT_DIR"] = scratch.outDir().string();
    spec.env["PALPATE_FAULT_LOG"] = scratch.faultLog().string();
}

void applyWriteFault(ChildSpec& spec, const Scratch& scratch, const WriteFault& fault) {
    addShim(spec, scratch);
    if (fault.enospcAfterBytes) spec.env["PALPATE_FAULT_ENOSPC_AFTER_BYTES"] = std::to_string(*fault.enospcAfterBytes);
    if (fault.eioAfterBytes) spec.env["PALPATE_FAULT_EIO_AFTER_BYTES"] = std::to_string(*fault.eioAfterBytes);
    if (fault.shortWrites) spec.env["PALPATE_FAULT_SHORT_WRITES"] = "1";
    if (fault.fsyncEio) spec.env["PALPATE_FAULT_FSYNC_EIO"] = "1";
}

void applyThreadFault(ChildSpec& spec, const Scratch& scratch, int k) {
    addShim(spec, scratch);
    spec.env["PALPATE_FAULT_PTHREAD_CREATE_FAIL_AFTER"] = std::to_string(k);
}

std::vector<std::string> injectedFaults(const Scratch& scratch) {
    std::vector<std::string> kinds;
    std::ifstream in(scratch.faultLog());
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) kinds.push_back(line);
    return kinds;
}

fs::path cachedFixture(const std::string& name, const std::function<void(const fs::path&)>& build) {
    struct stat cli {};
    ::stat(cliPath().c_str(), &cli);
    const std::string key = std::to_string(cli.st_size) + "-" + std::to_string(cli.st_mtim.tv_sec) + "-" +
                            std::to_string(cli.st_mtim.tv_nsec);
    const fs::path root = fs::temp_directory_path() / ("palpate-fault-fixtures-" + key);
    const fs::path final = root / name;
    if (fs::exists(final)) return final;
    fs::create_directories(root);
    const fs::path building = root / (name + ".building-" + std::to_string(::getpid()) + "-" + uniqueSuffix());
    fs::create_directories(building);
    build(building);
    std::error_code ec;
    fs::rename(building, final, ec);  // another process may have won the race: its copy is as good
    if (ec) fs::remove_all(building, ec);
    return final;
}

fs::path exercisePath() { return sourcePath("resources/exercises/press_targets.json"); }

fs::path fixtureRecording() {
    const fs::path dir = cachedFixture("recording", [](const fs::path& into) {
        Scratch scratch;
        const fs::path file = into / "session.rec";
        const ChildResult r = runChild(cliSpec(scratch, {"run", "--seconds", "0.3", "--exercise", exercisePath().string(),
                                                         "--record", file.string()}));
        if (!r.succeeded()) throw std::runtime_error("fixture recording failed: " + r.describe());
    });
    return dir / "session.rec";
}

std::string digest(const fs::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return {};
    if (!S_ISREG(st.st_mode) || st.st_size > (64ll << 20)) {
        return "mode " + std::to_string(st.st_mode) + " size " + std::to_string(st.st_size) + " mtime " +
               std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
    }
    std::ifstream in(path, std::ios::binary);
    unsigned long long hash = 1469598103934665603ull;
    char buffer[65536];
    while (in) {
        in.read(buffer, sizeof buffer);
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            hash ^= static_cast<unsigned char>(buffer[i]);
            hash *= 1099511628211ull;
        }
    }
    std::ostringstream s;
    s << "size " << st.st_size << " fnv " << std::hex << hash;
    return s.str();
}

std::map<std::string, std::string> digests(const std::vector<fs::path>& paths) {
    std::map<std::string, std::string> result;
    for (const auto& p : paths) result[p.string()] = digest(p);
    return result;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void copyFile(const fs::path& from, const fs::path& to) {
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

bool namesPath(const std::string& text, const fs::path& path) {
    std::vector<std::string> forms{path.string()};
    std::error_code ec;
    forms.push_back(fs::absolute(path, ec).string());
    const fs::path canonical = fs::weakly_canonical(path, ec);
    if (!ec) forms.push_back(canonical.string());
    for (const auto& form : forms)
        if (!form.empty() && text.find(form) != std::string::npos) return true;
    return false;
}

std::vector<std::string> filesIn(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

RecordingVerdict recordInfo(const Scratch& scratch, const fs::path& path) {
    RecordingVerdict v;
    ChildSpec spec = cliSpec(scratch, {"record", "info", path.string(), "--json"});
    spec.timeoutS = 20.0;
    const ChildResult r = runChild(spec);
    if (!r.succeeded()) {
        v.problem = r.describe();
        return v;
    }
    try {
        const auto json = nlohmann::json::parse(r.out);
        v.ticks = json.value("ticks", -1ll);
        v.intact = json.value("intact", false);
        v.closedCleanly = json.value("closed_cleanly", false);
        v.damagedRegions = json.value("damaged_regions", -1ll);
        v.note = json.value("note", std::string());
        v.accepted = true;
    } catch (const std::exception& e) {
        v.problem = std::string("record info --json printed no JSON: ") + e.what();
    }
    return v;
}

bool meshAccepted(const Scratch& scratch, const fs::path& path, std::string* problem) {
    ChildSpec spec = cliSpec(scratch, {"mesh", "check", path.string()});
    spec.timeoutS = 20.0;
    const ChildResult r = runChild(spec);
    if (problem) *problem = r.describe();
    return r.succeeded();
}

bool presetAccepted(const Scratch& scratch, const fs::path& path, std::string* problem) {
    ChildSpec spec = cliSpec(scratch, {"run", "--preset", path.string(), "--seconds", "0.01"});
    spec.timeoutS = 20.0;
    const ChildResult r = runChild(spec);
    if (problem) *problem = r.describe();
    return r.succeeded();
}

std::optional<long long> printedRecordedTicks(const std::string& output, const fs::path& recording) {
    // The count on a line that names the recording ("recorded 307 ticks (0.307 s) to FILE"), so a
    // reworded summary is still read; the session's own count ("session: N ticks") names no file.
    static const std::regex count(R"((\d+) ticks)");
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);) {
        if (!namesPath(line, recording) && line.find(recording.filename().string()) == std::string::npos) continue;
        std::smatch m;
        if (std::regex_search(line, m, count)) return std::stoll(m[1].str());
    }
    return std::nullopt;
}

}  // namespace palpate::fault
