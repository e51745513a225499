#pragma once
// At most a few of one user's requests of a kind at once (large replies: a model's JSON, a
// run's results, an FMU): a slot is taken before the work is queued and given back when the
// reply is built, so one user cannot fill the pool that builds them for everyone.
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>

namespace tlmhub::server {

class PerUserSlots {
public:
    explicit PerUserSlots(std::size_t perUser) : mPerUser(perUser) {}
    PerUserSlots(const PerUserSlots&) = delete;
    PerUserSlots& operator=(const PerUserSlots&) = delete;

    // Held while the work runs; the slot is free again when the last copy goes.
    using Slot = std::shared_ptr<void>;
    // A slot, or null when `userId` holds `perUser` already.
    Slot tryTake(std::int64_t userId);
    std::size_t perUser() const { return mPerUser; }

private:
    void give(std::int64_t userId);

    const std::size_t mPerUser;
    std::mutex mMutex;
    std::map<std::int64_t, std::size_t> mTaken;
};

} // namespace tlmhub::server
