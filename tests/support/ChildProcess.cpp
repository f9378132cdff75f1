#include "tests/support/ChildProcess.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

extern char** environ;

namespace palpate::test {

double nowS() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

std::string ChildResult::describe() const {
    std::string how;
    if (timedOut) how = "hung: killed at the timeout";
    else if (exited) how = "exit " + std::to_string(exitCode);
    else how = std::string("killed by signal ") + std::to_string(signal) + " (" + strsignal(signal) + ")";
    std::string tail = err.size() > 1500 ? "..." + err.substr(err.size() - 1500) : err;
    return how + " after " + std::to_string(seconds) + " s; stderr: [" + tail + "]";
}

namespace {

void readAvailable(int& fd, std::string& into) {
    if (fd < 0) return;
    char buffer[8192];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            // Keep the first 4 MiB: a runaway writer must not run this process out of memory.
            if (into.size() < (4u << 20)) into.append(buffer, static_cast<std::size_t>(n));
            continue;
        }
        if (n == 0) {
            ::close(fd);
            fd = -1;
        }
        return;  // EAGAIN or an error: try again later
    }
}

}  // namespace

Child::Child(const ChildSpec& spec) : mSpec(spec) {
    // Everything the child needs is built before fork: only async-signal-safe calls after it.
    std::map<std::string, std::string> env;
    for (char** e = environ; *e; ++e) {
        const std::string entry(*e);
        const auto eq = entry.find('=');
        if (eq != std::string::npos) env[entry.substr(0, eq)] = entry.substr(eq + 1);
    }
    for (const auto& [key, value] : spec.env) env[key] = value;
    std::vector<std::string> envStrings;
    for (const auto& [key, value] : env) envStrings.push_back(key + "=" + value);
    std::vector<char*> envp;
    for (auto& s : envStrings) envp.push_back(s.data());
    envp.push_back(nullptr);
    std::vector<std::string> args = spec.argv;
    std::vector<char*> argv;
    for (auto& s : args) argv.push_back(s.data());
    argv.push_back(nullptr);

    int outPipe[2];
    int errPipe[2];
    if (::pipe2(outPipe, O_CLOEXEC) != 0) return;
    if (::pipe2(errPipe, O_CLOEXEC) != 0) {
        ::close(outPipe[0]);
        ::close(outPipe[1]);
        return;
    }
    const int devNull = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    mStartS = nowS();
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::setpgid(0, 0);
        if (devNull >= 0) ::dup2(devNull, STDIN_FILENO);
        ::dup2(outPipe[1], STDOUT_FILENO);
        ::dup2(errPipe[1], STDERR_FILENO);
        if (spec.addressSpaceBytes) {
            const rlimit limit{*spec.addressSpaceBytes, *spec.addressSpaceBytes};
            ::setrlimit(RLIMIT_AS, &limit);
        }
        if (spec.fileSizeBytes) {
            const rlimit limit{*spec.fileSizeBytes, *spec.fileSizeBytes};
            ::setrlimit(RLIMIT_FSIZE, &limit);
        }
        // The default dispositions, whatever the test runner ignores (SIGXFSZ, SIGPIPE).
        ::signal(SIGXFSZ, SIG_DFL);
        ::signal(SIGPIPE, SIG_DFL);
        sigset_t none;
        sigemptyset(&none);
        ::sigprocmask(SIG_SETMASK, &none, nullptr);
        if (!mSpec.workingDir.empty() && ::chdir(mSpec.workingDir.c_str()) != 0) ::_exit(126);
        ::execve(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    ::close(outPipe[1]);
    ::close(errPipe[1]);
    if (devNull >= 0) ::close(devNull);
    if (pid < 0) {
        ::close(outPipe[0]);
        ::close(errPipe[0]);
        return;
    }
    ::setpgid(pid, pid);  // also here, so that a kill right after the fork finds the group
    mPid = pid;
    mOut = outPipe[0];
    mErr = errPipe[0];
    ::fcntl(mOut, F_SETFL, O_NONBLOCK);
    ::fcntl(mErr, F_SETFL, O_NONBLOCK);
}

Child::~Child() {
    if (started() && !mDone) finish(true);
    if (mOut >= 0) ::close(mOut);
    if (mErr >= 0) ::close(mErr);
}

ChildResult Child::wait() { return finish(false); }
ChildResult Child::kill9() { return finish(true); }

ChildResult Child::finish(bool killNow) {
    if (mDone) return mResult;
    mDone = true;
    ChildResult r;
    if (!started()) {
        r.err = "could not start " + (mSpec.argv.empty() ? std::string("?") : mSpec.argv[0]);
        mResult = r;
        return r;
    }
    if (killNow) ::kill(-mPid, SIGKILL);
    int status = 0;
    bool reaped = false;
    while (!reaped) {
        pollfd fds[2] = {{mOut, POLLIN, 0}, {mErr, POLLIN, 0}};
        ::poll(fds, 2, 10);
        readAvailable(mOut, r.out);
        readAvailable(mErr, r.err);
        const pid_t done = ::waitpid(mPid, &status, WNOHANG);
        if (done == mPid) {
            reaped = true;
            break;
        }
        if (!r.timedOut && nowS() - mStartS > mSpec.timeoutS) {
            r.timedOut = true;
            ::kill(-mPid, SIGKILL);
        }
    }
    r.seconds = nowS() - mStartS;
    // Grandchildren may hold the pipes open: the group is killed, then the pipes drained briefly.
    ::kill(-mPid, SIGKILL);
    const double drainUntil = nowS() + 1.0;
    while ((mOut >= 0 || mErr >= 0) && nowS() < drainUntil) {
        pollfd fds[2] = {{mOut, POLLIN, 0}, {mErr, POLLIN, 0}};
        ::poll(fds, 2, 10);
        readAvailable(mOut, r.out);
        readAvailable(mErr, r.err);
    }
    if (WIFEXITED(status) && !r.timedOut) {
        r.exited = true;
        r.exitCode = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        r.signal = WTERMSIG(status);
    }
    mResult = r;
    return r;
}

ChildResult runChild(const ChildSpec& spec) {
    Child child(spec);
    return child.wait();
}

}  // namespace palpate::test
