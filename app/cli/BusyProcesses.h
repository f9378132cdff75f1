#pragma once
// Busy processes beside the haptic loop, for palpate-cli bench feel --load N: each a forked child
// that spins on a core until it is killed, as a compiler or a browser tab takes a trainee's CPU.
// Killed and reaped when the object goes (and by the kernel when this process dies first).

namespace palpate::cli {

class BusyProcesses {
public:
    /// Forks `count` spinning children (fewer when fork fails: started() says how many).
    explicit BusyProcesses(int count);
    ~BusyProcesses();
    BusyProcesses(const BusyProcesses&) = delete;
    BusyProcesses& operator=(const BusyProcesses&) = delete;

    int started() const { return mCount; }
    /// Kills every child (SIGKILL) and waits for each.
    void stop();

private:
    static constexpr int kMax = 64;
    int mPids[kMax] = {};
    int mCount = 0;
};

}  // namespace palpate::cli
