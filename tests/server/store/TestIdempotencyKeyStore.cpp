// IdempotencyKeyStore's contract (server/store/IdempotencyKeyStore.h) on both back ends. Times
// are given by the caller, so the tests choose them.
#include "StoreBackends.h"

#include <atomic>
#include <thread>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class IdempotencyKeyStoreConformance : public StoreTest {
protected:
    const IdempotencyKey jobPost{"POST /jobs", "hash-1", 0};
};
TLMHUB_STORE_CONFORMANCE(IdempotencyKeyStoreConformance);

TEST_P(IdempotencyKeyStoreConformance, AKeyIsReservedOnceThenGivesWhatItMade)
{
    const User alice = addUser("alice");
    auto& keys = store().idempotencyKeys();
    EXPECT_EQ(keys.reserve(alice.id, "k1", jobPost, 1000, 0), std::nullopt) << "the first use reserves it";
    const auto pending = keys.reserve(alice.id, "k1", jobPost, 1001, 0);
    ASSERT_TRUE(pending);
    EXPECT_EQ(pending->objectId, 0) << "pending while the first request runs";
    keys.complete(alice.id, "k1", 42);
    const auto made = keys.reserve(alice.id, "k1", {"POST /studies", "hash-2", 0}, 1002, 0);
    ASSERT_TRUE(made);
    EXPECT_EQ(made->objectId, 42);
    EXPECT_EQ(made->route, "POST /jobs") << "what the first use was, not this one";
    EXPECT_EQ(made->requestHash, "hash-1");
}

TEST_P(IdempotencyKeyStoreConformance, KeysAreTheirOwnersAndAReleasedOneIsFreeAgain)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    auto& keys = store().idempotencyKeys();
    EXPECT_EQ(keys.reserve(alice.id, "k", jobPost, 1000, 0), std::nullopt);
    EXPECT_EQ(keys.reserve(bob.id, "k", jobPost, 1000, 0), std::nullopt) << "bob's own key";
    keys.release(alice.id, "k");
    EXPECT_EQ(keys.reserve(alice.id, "k", jobPost, 1001, 0), std::nullopt) << "released: free again";
    keys.complete(bob.id, "k", 7);
    keys.release(bob.id, "k");
    const auto kept = keys.reserve(bob.id, "k", jobPost, 1002, 0);
    ASSERT_TRUE(kept) << "a completed key is not released";
    EXPECT_EQ(kept->objectId, 7);
}

// A use from before `notBeforeUnix` is forgotten: the key is reserved anew.
TEST_P(IdempotencyKeyStoreConformance, AKeyOlderThanTheWindowIsForgotten)
{
    const User alice = addUser("alice");
    auto& keys = store().idempotencyKeys();
    EXPECT_EQ(keys.reserve(alice.id, "old", jobPost, 1000, 0), std::nullopt);
    keys.complete(alice.id, "old", 5);
    EXPECT_TRUE(keys.reserve(alice.id, "old", jobPost, 2000, 1000)) << "made at the window's start: kept";
    EXPECT_EQ(keys.reserve(alice.id, "old", jobPost, 3000, 1001), std::nullopt) << "older: forgotten";
}

// Of attempts racing on one key on separate connections, exactly one reserves it.
TEST_P(IdempotencyKeyStoreConformance, OfRacingReservationsExactlyOneWins)
{
    const User alice = addUser("alice");
    std::atomic<int> reserved{0};
    std::vector<std::thread> attempts;
    for (int i = 0; i < 8; ++i)
        attempts.emplace_back([&] {
            if (!store().idempotencyKeys().reserve(alice.id, "race", jobPost, 1000, 0)) ++reserved;
        });
    for (auto& t : attempts) t.join();
    EXPECT_EQ(reserved, 1);
}

} // namespace
} // namespace tlmhub::test
