#include "app/cli/BusyProcesses.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <sys/prctl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace palpate::cli {

BusyProcesses::BusyProcesses(int count) {
    const pid_t parent = getpid();
    count = std::clamp(count, 0, kMax);
    for (int i = 0; i < count; ++i) {
        const pid_t pid = fork();
        if (pid < 0) break;
        if (pid == 0) {
            // The child: dies with the parent, then spins. Nothing else (the parent may have threads).
            prctl(PR_SET_PDEATHSIG, SIGKILL);
            if (getppid() != parent) _exit(0);
            volatile unsigned long spin = 0;
            for (;;) spin = spin + 1;
        }
        mPids[mCount++] = int(pid);
    }
}

BusyProcesses::~BusyProcesses() { stop(); }

void BusyProcesses::stop() {
    for (int i = 0; i < mCount; ++i) kill(pid_t(mPids[i]), SIGKILL);
    for (int i = 0; i < mCount; ++i) {
        int status = 0;
        while (waitpid(pid_t(mPids[i]), &status, 0) < 0 && errno == EINTR) {
        }
    }
    mCount = 0;
}

}  // namespace palpate::cli
