// SessionStore's contract (server/store/SessionStore.h) on both back ends. Times are given by
// the caller, so the tests choose them.
#include "StoreBackends.h"

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class SessionStoreConformance : public StoreTest {};
TLMHUB_STORE_CONFORMANCE(SessionStoreConformance);

TEST_P(SessionStoreConformance, ASessionNamesItsUserUntilItExpires)
{
    const User alice = addUser("alice");
    store().sessions().insert("token-a", alice.id, 1000, 100);
    EXPECT_EQ(store().sessions().userOf("token-a", 100), alice.id);
    EXPECT_EQ(store().sessions().userOf("token-a", 999), alice.id);
    EXPECT_FALSE(store().sessions().userOf("token-a", 1000)) << "a session has expired at its expiry time";
    EXPECT_FALSE(store().sessions().userOf("no such token", 100));
}

TEST_P(SessionStoreConformance, AnExpiredSessionIsDeletedWhenLookedUp)
{
    const User alice = addUser("alice");
    store().sessions().insert("token-a", alice.id, 1000, 100);
    EXPECT_FALSE(store().sessions().userOf("token-a", 2000));
    // Gone, not just expired: an earlier time does not bring it back.
    EXPECT_FALSE(store().sessions().userOf("token-a", 500));
}

TEST_P(SessionStoreConformance, InsertDeletesSessionsExpiredAtItsTime)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    store().sessions().insert("short", alice.id, 200, 100);
    store().sessions().insert("until 300", alice.id, 300, 100);
    store().sessions().insert("long", bob.id, 5000, 100);
    store().sessions().insert("new", alice.id, 5000, 300);
    // Looked up at a time before they expire: only the ones deleted are missing.
    EXPECT_FALSE(store().sessions().userOf("short", 150));
    EXPECT_FALSE(store().sessions().userOf("until 300", 150));
    EXPECT_EQ(store().sessions().userOf("long", 150), bob.id);
    EXPECT_EQ(store().sessions().userOf("new", 150), alice.id);
}

TEST_P(SessionStoreConformance, RemoveEndsOnlyThatSession)
{
    const User alice = addUser("alice");
    store().sessions().insert("one", alice.id, 1000, 100);
    store().sessions().insert("two", alice.id, 1000, 100);
    store().sessions().remove("one");
    store().sessions().remove("never issued");
    EXPECT_FALSE(store().sessions().userOf("one", 100));
    EXPECT_EQ(store().sessions().userOf("two", 100), alice.id);
}

TEST_P(SessionStoreConformance, RemoveAllForEndsEverySessionOfThatUserOnly)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    store().sessions().insert("a1", alice.id, 1000, 100);
    store().sessions().insert("a2", alice.id, 1000, 100);
    store().sessions().insert("b1", bob.id, 1000, 100);
    store().sessions().removeAllFor(alice.id);
    EXPECT_FALSE(store().sessions().userOf("a1", 100));
    EXPECT_FALSE(store().sessions().userOf("a2", 100));
    EXPECT_EQ(store().sessions().userOf("b1", 100), bob.id);
}

} // namespace
} // namespace tlmhub::test
