// SignInStore's contract (server/store/SignInStore.h) on both back ends: an attempt is taken
// once (also by takes racing on several threads), not after its wait, and the unanswered ones
// are purged. Times are given by the caller, so the tests choose them.
#include "StoreBackends.h"

#include <atomic>
#include <thread>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class SignInStoreConformance : public StoreTest {
protected:
    static SignInAttempt attempt(const std::string& state, std::int64_t createdAt)
    {
        return {state, "uni", "nonce-" + state, "verifier-" + state, "browser-" + state, createdAt, 0};
    }
};
TLMHUB_STORE_CONFORMANCE(SignInStoreConformance);

TEST_P(SignInStoreConformance, AnAttemptIsTakenOnceWithWhatItWasStartedWith)
{
    auto& signIns = store().signIns();
    signIns.add(attempt("s1", 1000));
    signIns.add(attempt("s2", 1000));
    const auto taken = signIns.take("s1", 900);
    ASSERT_TRUE(taken);
    EXPECT_EQ(taken->state, "s1");
    EXPECT_EQ(taken->provider, "uni");
    EXPECT_EQ(taken->nonce, "nonce-s1");
    EXPECT_EQ(taken->codeVerifier, "verifier-s1");
    EXPECT_EQ(taken->browserKey, "browser-s1");
    EXPECT_EQ(taken->createdAt, 1000);
    EXPECT_FALSE(signIns.take("s1", 900)) << "a replayed answer finds nothing";
    EXPECT_FALSE(signIns.take("unknown", 0));
    EXPECT_EQ(taken->userId, 0);
    EXPECT_TRUE(signIns.take("s2", 900)) << "the other attempt is still there";
    SignInAttempt handOver = attempt("h1", 1000);
    handOver.userId = 42;
    signIns.add(handOver);
    EXPECT_EQ(signIns.take("h1", 900)->userId, 42);
}

TEST_P(SignInStoreConformance, AnAttemptPastItsWaitIsNotTakenAndTheUnansweredArePurged)
{
    auto& signIns = store().signIns();
    signIns.add(attempt("old", 1000));
    EXPECT_FALSE(signIns.take("old", 1001)) << "made before the time allowed";
    EXPECT_FALSE(signIns.take("old", 0)) << "and gone with that take";
    for (int i = 0; i < 5; ++i) signIns.add(attempt("a" + std::to_string(i), 2000 + i));
    EXPECT_EQ(signIns.purge(2003), 2U) << "a3 and a4 are left";
    EXPECT_FALSE(signIns.take("a2", 0));
    EXPECT_TRUE(signIns.take("a4", 0));
}

TEST_P(SignInStoreConformance, OfTakesRacingOnSeveralThreadsOneGetsTheAttempt)
{
    auto& signIns = store().signIns();
    for (int round = 0; round < 10; ++round) {
        const std::string state = "race-" + std::to_string(round);
        signIns.add(attempt(state, 5000));
        std::atomic<int> winners = 0;
        std::vector<std::thread> threads;
        for (int t = 0; t < 4; ++t)
            threads.emplace_back([&] {
                if (signIns.take(state, 0)) ++winners;
            });
        for (std::thread& thread : threads) thread.join();
        EXPECT_EQ(winners.load(), 1) << state;
    }
}

} // namespace
} // namespace tlmhub::test
