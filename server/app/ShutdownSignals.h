#pragma once

#include <chrono>
#include <functional>
#include <memory>

namespace tlmhub::server {

// SIGINT and SIGTERM are taken by a thread of their own (sigwait), not by an I/O thread: a
// signal is seen however busy every I/O thread is. The orderly stop then has a bounded time;
// a request that does not let go within it (a long check run, a large model being parsed)
// does not keep the process alive.
class ShutdownSignals {
public:
    // Blocks both signals in the calling thread, and so in every thread it starts later, and
    // starts the waiting thread: construct before any other thread exists.
    explicit ShutdownSignals(std::chrono::milliseconds grace);
    // What the first signal runs from now on (on the waiting thread). Until it is set, a
    // signal ends the process at once: there is nothing to stop in order yet.
    void onSignal(std::function<void()> stop);

private:
    struct State;
    std::shared_ptr<State> mState;   // shared with the detached waiting thread
};

} // namespace tlmhub::server
