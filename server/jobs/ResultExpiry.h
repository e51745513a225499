#pragma once
// Deletes finished jobs and their results once they are older than the server's
// --result-ttl, so a lab server's disk does not fill with last term's runs. Sweeps at
// start and then every quarter of the lifetime (at least every second, at most hourly) on a
// thread of its own; the per-user storage quota still applies in between.
#include "server/store/JobStore.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace tlmhub::server {

class ResultExpiry {
public:
    ResultExpiry(JobStore& store, std::chrono::seconds lifetime);
    ~ResultExpiry();
    ResultExpiry(const ResultExpiry&) = delete;
    ResultExpiry& operator=(const ResultExpiry&) = delete;

    // One sweep now; returns how many jobs were deleted.
    int sweep();

private:
    void loop();

    JobStore& mStore;
    const std::chrono::seconds mLifetime;
    std::mutex mMutex;
    std::condition_variable mWake;
    bool mStopping = false;
    std::thread mThread;
};

} // namespace tlmhub::server
