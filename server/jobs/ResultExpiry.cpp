#include "server/jobs/ResultExpiry.h"

#include <algorithm>
#include <iostream>

namespace tlmhub::server {

ResultExpiry::ResultExpiry(JobStore& store, std::chrono::seconds lifetime)
    : mStore(store), mLifetime(lifetime), mThread([this] { loop(); })
{
}

ResultExpiry::~ResultExpiry()
{
    {
        std::lock_guard lock(mMutex);
        mStopping = true;
    }
    mWake.notify_all();
    mThread.join();
}

int ResultExpiry::sweep()
{
    const auto now = std::chrono::system_clock::now();
    const auto cutoff = std::chrono::duration_cast<std::chrono::seconds>((now - mLifetime).time_since_epoch());
    return mStore.removeFinishedBefore(cutoff.count());
}

void ResultExpiry::loop()
{
    using namespace std::chrono_literals;
    const auto interval = std::clamp<std::chrono::seconds>(mLifetime / 4, 1s, 3600s);
    std::unique_lock lock(mMutex);
    while (!mStopping) {
        lock.unlock();
        try {
            const int removed = sweep();
            if (removed > 0) std::cerr << "tlmhub-server: deleted " << removed << " expired job(s)\n";
        } catch (const std::exception& e) {
            // A busy or failing database must not end the server; the next sweep retries.
            std::cerr << "tlmhub-server: result expiry failed: " << e.what() << "\n";
        }
        lock.lock();
        mWake.wait_for(lock, interval, [this] { return mStopping; });
    }
}

} // namespace tlmhub::server
