#pragma once
// Runs a function in a forked child under a file-size limit (RLIMIT_FSIZE) with SIGXFSZ ignored,
// so that writes beyond the limit fail with EFBIG like a full disk, and returns what the child
// reported. A program under limits runs through tests/support/ChildProcess.h.
#include <csignal>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace palpate::test {

struct ChildResult {
    int exitCode = -1;   ///< -1 when the child did not exit normally (a signal)
    std::string output;  ///< what the child wrote to the pipe (stdout and stderr for a program)
};

inline void limitFileSize(rlim_t bytes) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{bytes, bytes};
    ::setrlimit(RLIMIT_FSIZE, &limit);
}

inline std::string readAll(int fd) {
    std::string out;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) out.append(buffer, std::size_t(n));
    return out;
}

inline ChildResult finish(pid_t pid, int readEnd) {
    ChildResult r;
    r.output = readAll(readEnd);
    ::close(readEnd);
    int status = 0;
    ::waitpid(pid, &status, 0);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// `body` runs in the child under the limit; what it returns is the child's output.
template <class Body>
ChildResult runWithFileSizeLimit(rlim_t bytes, Body body) {
    int fds[2];
    if (::pipe(fds) != 0) return {};
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        limitFileSize(bytes);
        const std::string text = body();
        (void)!::write(fds[1], text.data(), text.size());
        ::_exit(0);
    }
    ::close(fds[1]);
    return finish(pid, fds[0]);
}

}  // namespace palpate::test
