// ApiTokenStore's contract (server/store/ApiTokenStore.h) on both back ends. Times are given
// by the caller, so the tests choose them.
#include "StoreBackends.h"

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class ApiTokenStoreConformance : public StoreTest {
protected:
    std::int64_t addToken(std::int64_t userId, const std::string& hash, std::optional<std::int64_t> expiresAt = {},
                          std::int64_t createdAt = 100)
    {
        const auto id = store().apiTokens().insert(userId, "token " + hash, hash, createdAt, expiresAt);
        if (!id) throw std::runtime_error("cannot add token " + hash);
        return *id;
    }
};
TLMHUB_STORE_CONFORMANCE(ApiTokenStoreConformance);

TEST_P(ApiTokenStoreConformance, ATokenIsListedWithWhatItWasCreatedWith)
{
    const User alice = addUser("alice");
    const auto id = store().apiTokens().insert(alice.id, "nightly sweep \xc3\xa5", "hash-a", 1234, 99999);
    ASSERT_TRUE(id);
    const auto tokens = store().apiTokens().list(alice.id);
    ASSERT_EQ(tokens.size(), 1u);
    EXPECT_EQ(tokens[0].id, *id);
    EXPECT_EQ(tokens[0].userId, alice.id);
    EXPECT_EQ(tokens[0].name, "nightly sweep \xc3\xa5");
    EXPECT_EQ(tokens[0].createdAt, 1234);
    EXPECT_EQ(tokens[0].expiresAt, 99999);
    EXPECT_EQ(tokens[0].lastUsedAt, std::nullopt) << "never used";
}

TEST_P(ApiTokenStoreConformance, ATokenWithoutExpiryHasNone)
{
    const User alice = addUser("alice");
    addToken(alice.id, "hash-a");
    EXPECT_EQ(store().apiTokens().list(alice.id).at(0).expiresAt, std::nullopt);
    EXPECT_TRUE(store().apiTokens().use("hash-a", 4'000'000'000)) << "it lasts until it is deleted";
}

TEST_P(ApiTokenStoreConformance, InsertForAMissingUserIsRefused)
{
    EXPECT_EQ(store().apiTokens().insert(4242, "orphan", "hash-x", 100, std::nullopt), std::nullopt);
    EXPECT_EQ(store().apiTokens().count(4242), 0u);
}

TEST_P(ApiTokenStoreConformance, TheSameHashCannotBeStoredTwice)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    addToken(alice.id, "hash-a");
    try {
        store().apiTokens().insert(bob.id, "copy", "hash-a", 100, std::nullopt);
        FAIL() << "a second token with the same hash was stored";
    } catch (const StoreError& e) {
        EXPECT_EQ(e.code(), StoreErrc::Constraint) << e.what();
    }
    EXPECT_EQ(store().apiTokens().use("hash-a", 200)->userId, alice.id);
}

TEST_P(ApiTokenStoreConformance, ListIsTheUsersOwnNewestFirstAndCountAgrees)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    const auto first = addToken(alice.id, "a1");
    addToken(bob.id, "b1");
    const auto second = addToken(alice.id, "a2");
    const auto tokens = store().apiTokens().list(alice.id);
    ASSERT_EQ(tokens.size(), 2u);
    EXPECT_EQ(tokens[0].id, second);
    EXPECT_EQ(tokens[1].id, first);
    EXPECT_EQ(store().apiTokens().count(alice.id), 2u);
    EXPECT_EQ(store().apiTokens().count(bob.id), 1u);
    EXPECT_TRUE(store().apiTokens().list(4242).empty());
}

TEST_P(ApiTokenStoreConformance, UseFindsTheTokenUntilItExpires)
{
    const User alice = addUser("alice");
    const auto id = addToken(alice.id, "hash-a", 1000);
    const auto used = store().apiTokens().use("hash-a", 999);
    ASSERT_TRUE(used);
    EXPECT_EQ(used->id, id);
    EXPECT_EQ(used->userId, alice.id);
    EXPECT_EQ(used->expiresAt, 1000);
    EXPECT_FALSE(store().apiTokens().use("hash-a", 1000)) << "a token has expired at its expiry time";
    EXPECT_FALSE(store().apiTokens().use("hash-a", 5000));
    EXPECT_FALSE(store().apiTokens().use("no such hash", 500));
    // Expired, not deleted: still listed until its owner deletes it.
    EXPECT_EQ(store().apiTokens().list(alice.id).size(), 1u);
}

TEST_P(ApiTokenStoreConformance, UseRecordsTheLastUseAtMostOnceAMinute)
{
    const User alice = addUser("alice");
    addToken(alice.id, "hash-a");
    EXPECT_EQ(store().apiTokens().use("hash-a", 1000)->lastUsedAt, 1000);
    EXPECT_EQ(store().apiTokens().list(alice.id).at(0).lastUsedAt, 1000);
    // Within the minute: not written again.
    EXPECT_EQ(store().apiTokens().use("hash-a", 1059)->lastUsedAt, 1000);
    EXPECT_EQ(store().apiTokens().list(alice.id).at(0).lastUsedAt, 1000);
    // A minute later: written.
    EXPECT_EQ(store().apiTokens().use("hash-a", 1060)->lastUsedAt, 1060);
    EXPECT_EQ(store().apiTokens().list(alice.id).at(0).lastUsedAt, 1060);
}

TEST_P(ApiTokenStoreConformance, RemoveDeletesOnlyTheUsersOwnToken)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    const auto aliceToken = addToken(alice.id, "hash-a");
    const auto bobToken = addToken(bob.id, "hash-b");
    EXPECT_FALSE(store().apiTokens().remove(bob.id, aliceToken)) << "bob deleted alice's token";
    EXPECT_TRUE(store().apiTokens().use("hash-a", 200));
    EXPECT_TRUE(store().apiTokens().remove(alice.id, aliceToken));
    EXPECT_FALSE(store().apiTokens().remove(alice.id, aliceToken)) << "gone already";
    EXPECT_FALSE(store().apiTokens().use("hash-a", 200));
    EXPECT_TRUE(store().apiTokens().list(alice.id).empty());
    EXPECT_EQ(store().apiTokens().use("hash-b", 200)->id, bobToken);
}

// Disabling an account revokes its tokens (issue 37 L3): all of that user's, nobody else's.
TEST_P(ApiTokenStoreConformance, RemoveAllDeletesEveryTokenOfTheUserOnly)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    addToken(alice.id, "hash-a1");
    addToken(alice.id, "hash-a2");
    const auto bobToken = addToken(bob.id, "hash-b");
    EXPECT_EQ(store().apiTokens().removeAll(alice.id), 2u);
    EXPECT_FALSE(store().apiTokens().use("hash-a1", 200));
    EXPECT_FALSE(store().apiTokens().use("hash-a2", 200));
    EXPECT_EQ(store().apiTokens().count(alice.id), 0u);
    EXPECT_EQ(store().apiTokens().removeAll(alice.id), 0u);
    EXPECT_EQ(store().apiTokens().use("hash-b", 200)->id, bobToken);
}

// No store deletes users yet; the schema already takes their tokens with them.
TEST_P(ApiTokenStoreConformance, DeletingAUserDeletesItsTokens)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    addToken(alice.id, "hash-a");
    addToken(bob.id, "hash-b");
    const std::string enforceKeys = GetParam() == Backend::SQLite ? "PRAGMA foreign_keys=ON; " : "";
    db->exec(enforceKeys + "DELETE FROM users WHERE id = " + std::to_string(alice.id));
    EXPECT_FALSE(store().apiTokens().use("hash-a", 200));
    EXPECT_EQ(store().apiTokens().count(alice.id), 0u);
    EXPECT_TRUE(store().apiTokens().use("hash-b", 200));
}

} // namespace
} // namespace tlmhub::test
