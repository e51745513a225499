#include "server/app/ShutdownSignals.h"

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <pthread.h>
#include <thread>

namespace tlmhub::server {

struct ShutdownSignals::State {
    std::mutex mutex;
    std::function<void()> stop;
};

namespace {

sigset_t shutdownSignals()
{
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    return set;
}

} // namespace

ShutdownSignals::ShutdownSignals(std::chrono::milliseconds grace) : mState(std::make_shared<State>())
{
    const sigset_t set = shutdownSignals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    // Detached: the process ends while it waits (no signal) or while the grace runs out.
    std::thread([state = mState, grace, set] {
        int signal = 0;
        while (sigwait(&set, &signal) != 0) {
        }
        std::function<void()> stop;
        {
            std::lock_guard lock(state->mutex);
            stop = state->stop;
        }
        if (!stop) std::_Exit(128 + signal);
        std::thread([grace] {
            std::this_thread::sleep_for(grace);
            // What still runs is a request: jobs are interrupted or back in the queue by now,
            // and every store write is a transaction, so nothing saved is half-written.
            std::cerr << "tlmhub-server: requests still running " << grace.count()
                      << " ms after the signal; exiting without them" << std::endl;
            std::_Exit(1);
        }).detach();
        stop();
    }).detach();
}

void ShutdownSignals::onSignal(std::function<void()> stop)
{
    std::lock_guard lock(mState->mutex);
    mState->stop = std::move(stop);
}

} // namespace tlmhub::server
