#pragma once
// What every fault case shares: the binaries, a scratch folder per case, the child's environment
// (the shim, an isolated HOME), fixtures cached across the suite's processes, digests of inputs,
// and the product's own readers as judges of what a command left behind (docs/reliability.md).

#include "tests/support/ChildProcess.h"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace palpate::fault {

using test::Child;
using test::ChildResult;
using test::ChildSpec;
using test::nowS;
using test::runChild;

namespace fs = std::filesystem;

std::string cliPath();
std::string shimPath();
std::string sourcePath(const std::string& relative);  ///< under the repository root
bool haveGui();
std::string guiPath();
bool sanitized();
bool havePdf();  ///< score --pdf exists (a build with the GUI)

/// A folder per case under the system temp dir, removed at the end. in/ holds inputs, out/ is the
/// folder the shim's faults apply to (PALPATE_FAULT_DIR).
class Scratch {
public:
    Scratch();
    ~Scratch();
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    const fs::path& root() const { return mRoot; }
    fs::path in(const std::string& name) const { return mRoot / "in" / name; }
    fs::path out(const std::string& name) const { return mRoot / "out" / name; }
    fs::path inDir() const { return mRoot / "in"; }
    fs::path outDir() const { return mRoot / "out"; }
    fs::path faultLog() const { return mRoot / "fault.log"; }

private:
    fs::path mRoot;
};

/// The write faults of the shim; empty fields inject nothing.
struct WriteFault {
    std::string name;
    std::optional<long long> enospcAfterBytes;
    std::optional<long long> eioAfterBytes;
    bool shortWrites = false;
    bool fsyncEio = false;
};

/// A spec for palpate-cli (or any binary when argv[0] is absolute) with the isolated environment.
ChildSpec cliSpec(const Scratch& scratch, std::vector<std::string> args);
/// Adds the shim with `fault` applied to scratch.outDir().
void applyWriteFault(ChildSpec& spec, const Scratch& scratch, const WriteFault& fault);
/// Adds the shim failing the (k+1)-th pthread_create.
void applyThreadFault(ChildSpec& spec, const Scratch& scratch, int k);
/// The kinds of fault the shim wrote to its log ("enospc", "eio", "short", "fsync", "pthread").
std::vector<std::string> injectedFaults(const Scratch& scratch);

/// A folder cached across the suite's test processes (ctest runs each case in its own process),
/// built once by `build` into a temporary folder and renamed into place; keyed by the CLI binary,
/// so a rebuilt product rebuilds its fixtures.
fs::path cachedFixture(const std::string& name, const std::function<void(const fs::path&)>& build);

/// A short recording of the press-targets exercise (so that score can read it) and its folder.
fs::path fixtureRecording();
fs::path exercisePath();  ///< resources/exercises/press_targets.json

/// Content digest (FNV-1a 64 over the bytes, with the size); for files above 64 MiB (sparse
/// inputs) the size and modification time. Empty when the path does not exist.
std::string digest(const fs::path& path);
/// Digests of several paths, to compare before and after.
std::map<std::string, std::string> digests(const std::vector<fs::path>& paths);
std::string readText(const fs::path& path);
void copyFile(const fs::path& from, const fs::path& to);

/// True when `text` names `path`: as given, absolute or canonical.
bool namesPath(const std::string& text, const fs::path& path);
/// The regular files in a folder (names), to find leftovers such as a stale temporary.
std::vector<std::string> filesIn(const fs::path& dir);

/// What `palpate-cli record info FILE --json` says of a file.
struct RecordingVerdict {
    bool accepted = false;  ///< exit 0 and a parsable answer
    long long ticks = -1;
    bool intact = false;
    bool closedCleanly = false;
    long long damagedRegions = -1;
    std::string note;
    std::string problem;  ///< the reader's stderr when refused
};
RecordingVerdict recordInfo(const Scratch& scratch, const fs::path& path);
/// `palpate-cli mesh check FILE` exits 0.
bool meshAccepted(const Scratch& scratch, const fs::path& path, std::string* problem = nullptr);
/// `palpate-cli run --preset FILE --seconds 0.01` exits 0.
bool presetAccepted(const Scratch& scratch, const fs::path& path, std::string* problem = nullptr);
/// The tick count a run printed for its recording (on a line naming it: "recorded N ticks ... to FILE").
std::optional<long long> printedRecordedTicks(const std::string& output, const fs::path& recording);

}  // namespace palpate::fault
