#pragma once
// The one runner of programs with limits (the fault suite's, the hostile inputs'): a child process
// with a hard timeout: fork/exec, stdout and stderr through pipes (so a file-size
// limit on the child does not touch them), resource limits set in the child before exec, and the
// whole process group killed with SIGKILL when the timeout passes (a hang is a failure, never a
// stuck suite).

#include <sys/types.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace palpate::test {

struct ChildSpec {
    std::vector<std::string> argv;
    std::map<std::string, std::string> env;  ///< set on top of this process's environment
    std::optional<unsigned long long> addressSpaceBytes;  ///< RLIMIT_AS
    std::optional<unsigned long long> fileSizeBytes;      ///< RLIMIT_FSIZE
    double timeoutS = 10.0;
    std::string workingDir;  ///< empty: this process's
};

struct ChildResult {
    bool exited = false;  ///< WIFEXITED
    int exitCode = -1;
    int signal = 0;  ///< the signal that ended it, when it did not exit
    bool timedOut = false;  ///< killed by the runner at the timeout
    double seconds = 0.0;
    std::string out;
    std::string err;

    bool succeeded() const { return exited && exitCode == 0; }
    /// One line for assertion messages: how it ended, and its stderr.
    std::string describe() const;
};

/// A started child; wait() or kill9() it. The destructor kills and reaps a child still running.
class Child {
public:
    explicit Child(const ChildSpec& spec);
    ~Child();
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;

    pid_t pid() const { return mPid; }
    bool started() const { return mPid > 0; }
    /// Waits up to the spec's timeout (from the start), then kills the group.
    ChildResult wait();
    /// SIGKILL now (the process group), then reap.
    ChildResult kill9();

private:
    ChildResult finish(bool killNow);

    ChildSpec mSpec;
    pid_t mPid = -1;
    int mOut = -1;
    int mErr = -1;
    double mStartS = 0.0;
    bool mDone = false;
    ChildResult mResult;
};

/// Starts and waits.
ChildResult runChild(const ChildSpec& spec);

/// Monotonic seconds.
double nowS();

}  // namespace palpate::test
