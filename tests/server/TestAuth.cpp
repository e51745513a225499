#include "server/auth/AccessPolicy.h"
#include "server/auth/LoginRateLimiter.h"
#include "server/auth/PasswordHasher.h"
#include "server/auth/TokenService.h"
#include "server/auth/Accounts.h"
#include "server/store/UnixTime.h"
#include "TemporarySqliteStorage.h"

#include <SQLiteCpp/Statement.h>
#include <gtest/gtest.h>

using namespace tlmhub::server;
using namespace std::chrono_literals;

TEST(PasswordHasher, HashIsArgon2idAndVerifiesOnlyTheRightPassword)
{
    const std::string hash = hashPassword("correct horse");
    EXPECT_EQ(hash.rfind("$argon2id$", 0), 0u) << hash;
    EXPECT_TRUE(verifyPassword(hash, "correct horse"));
    EXPECT_FALSE(verifyPassword(hash, "correct horsE"));
    EXPECT_FALSE(verifyPassword(hash, ""));
}

TEST(PasswordHasher, SamePasswordGetsDifferentSalt)
{
    EXPECT_NE(hashPassword("same password"), hashPassword("same password"));
}

TEST(PasswordHasher, MalformedHashNeverVerifies)
{
    EXPECT_FALSE(verifyPassword("", ""));
    EXPECT_FALSE(verifyPassword("not a hash", "not a hash"));
    EXPECT_FALSE(verifyPassword(std::string(500, 'x'), "x"));
}

namespace {

// Every test gets its own database; nothing is shared between tests.
struct AuthFixture : ::testing::Test {
    tlmhub::test::TemporarySqliteStorage storage;
    SQLite::Database& db = storage.raw();
    Accounts users{storage->users()};

    User makeUser(const std::string& name, const std::string& role = "user",
                  const std::string& password = "password1")
    {
        std::string error;
        std::optional<User> u = users.create(name, password, role, error);
        EXPECT_TRUE(u) << error;
        return u.value_or(User{});
    }
};

using UserStoreTest = AuthFixture;
using TokenServiceTest = AuthFixture;

} // namespace

TEST_F(UserStoreTest, CreatedUserCanBeFoundByIdAndName)
{
    const User alice = makeUser("alice", "teacher");
    EXPECT_GT(alice.id, 0);
    EXPECT_EQ(alice.username, "alice");
    EXPECT_EQ(alice.role, "teacher");
    const std::optional<User> byId = users.find(alice.id);
    ASSERT_TRUE(byId);
    EXPECT_EQ(byId->username, "alice");
    EXPECT_EQ(byId->role, "teacher");
    const std::optional<User> byName = users.findByName("alice");
    ASSERT_TRUE(byName);
    EXPECT_EQ(byName->id, alice.id);
    EXPECT_FALSE(users.find(alice.id + 1));
    EXPECT_FALSE(users.findByName("Alice"));
}

TEST_F(UserStoreTest, DuplicateNameIsRefusedAsTaken)
{
    makeUser("bob");
    std::string error;
    EXPECT_FALSE(users.create("bob", "otherpassword", "admin", error));
    EXPECT_EQ(error, kUsernameTaken);
    EXPECT_EQ(users.count(), 1u);
    EXPECT_EQ(users.findByName("bob")->role, "user");
}

TEST_F(UserStoreTest, BadRoleShortPasswordAndBadNameAreRefused)
{
    std::string error;
    EXPECT_FALSE(users.create("carol", "password1", "root", error));
    EXPECT_EQ(error, kBadRole);
    EXPECT_FALSE(users.create("carol", "1234567", "user", error));
    EXPECT_EQ(error, kShortPassword);
    EXPECT_FALSE(users.create("", "password1", "user", error));
    EXPECT_EQ(error, kBadUsername);
    EXPECT_FALSE(users.create("car ol", "password1", "user", error));
    EXPECT_EQ(error, kBadUsername);
    EXPECT_FALSE(users.create(std::string(65, 'a'), "password1", "user", error));
    EXPECT_EQ(error, kBadUsername);
    EXPECT_EQ(users.count(), 0u);
    // Boundaries that are allowed: 64 characters, all permitted punctuation, 8-char password.
    EXPECT_TRUE(users.create(std::string(64, 'a'), "12345678", "user", error)) << error;
    EXPECT_TRUE(users.create("A.b_c-9", "12345678", "user", error)) << error;
}

TEST_F(UserStoreTest, SchemaRejectsUnknownRoleEvenWithoutTheStore)
{
    EXPECT_THROW(db.exec("INSERT INTO users(username, role) VALUES('x', 'root')"),
                 SQLite::Exception);
}

TEST_F(UserStoreTest, AuthenticateNeedsTheRightPassword)
{
    const User dave = makeUser("dave", "user", "davespassword");
    const std::optional<User> ok = users.authenticate("dave", "davespassword");
    ASSERT_TRUE(ok);
    EXPECT_EQ(ok->id, dave.id);
    EXPECT_FALSE(users.authenticate("dave", "wrongpassword"));
    EXPECT_FALSE(users.authenticate("nobody", "davespassword"));
}

TEST_F(UserStoreTest, ChangePasswordChecksOldPasswordAndLength)
{
    const User erin = makeUser("erin", "user", "firstpassword");
    std::string error;
    EXPECT_FALSE(users.changePassword(erin.id, "wrongpassword", "secondpassword", error));
    EXPECT_EQ(error, kWrongPassword);
    EXPECT_FALSE(users.changePassword(erin.id, "firstpassword", "short", error));
    EXPECT_EQ(error, kShortPassword);
    EXPECT_FALSE(users.changePassword(erin.id + 100, "firstpassword", "secondpassword", error));
    EXPECT_EQ(error, kNoSuchUser);
    EXPECT_TRUE(users.authenticate("erin", "firstpassword"));

    EXPECT_TRUE(users.changePassword(erin.id, "firstpassword", "secondpassword", error)) << error;
    EXPECT_FALSE(users.authenticate("erin", "firstpassword"));
    EXPECT_TRUE(users.authenticate("erin", "secondpassword"));
}

TEST_F(UserStoreTest, ListIsInCreationOrder)
{
    makeUser("zed", "admin");
    makeUser("amy", "user");
    const std::vector<User> all = users.list();
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].username, "zed");
    EXPECT_EQ(all[0].role, "admin");
    EXPECT_EQ(all[1].username, "amy");
    EXPECT_EQ(users.count(), 2u);
}

TEST_F(TokenServiceTest, IssuedTokenValidatesToItsUser)
{
    const User frank = makeUser("frank");
    TokenService tokens(storage->sessions(), storage->users(), 3600s);
    const TokenService::Issued issued = tokens.issue(frank);
    EXPECT_EQ(issued.token.size(), 64u);
    EXPECT_EQ(issued.token.find_first_not_of("0123456789abcdef"), std::string::npos);
    EXPECT_NEAR(static_cast<double>(issued.expiresAt), static_cast<double>(unixNow() + 3600), 5);
    const std::optional<User> who = tokens.validate(issued.token);
    ASSERT_TRUE(who);
    EXPECT_EQ(who->id, frank.id);
    EXPECT_EQ(who->username, "frank");
    EXPECT_NE(tokens.issue(frank).token, issued.token);
}

TEST_F(TokenServiceTest, UnknownOrAlteredTokenIsInvalid)
{
    const User gina = makeUser("gina");
    TokenService tokens(storage->sessions(), storage->users(), 3600s);
    std::string token = tokens.issue(gina).token;
    EXPECT_FALSE(tokens.validate(""));
    EXPECT_FALSE(tokens.validate(std::string(64, '0')));
    token[0] = token[0] == 'a' ? 'b' : 'a';
    EXPECT_FALSE(tokens.validate(token));
}

TEST_F(TokenServiceTest, OnlyTheTokenHashIsStored)
{
    const User hank = makeUser("hank");
    TokenService tokens(storage->sessions(), storage->users(), 3600s);
    const std::string token = tokens.issue(hank).token;
    SQLite::Statement q(db, "SELECT token_hash, user_id FROM sessions");
    ASSERT_TRUE(q.executeStep());
    EXPECT_NE(q.getColumn(0).getString(), token);
    EXPECT_EQ(q.getColumn(1).getInt64(), hank.id);
}

TEST_F(TokenServiceTest, RevokedTokenIsInvalidOthersStayValid)
{
    const User ivan = makeUser("ivan");
    TokenService tokens(storage->sessions(), storage->users(), 3600s);
    const std::string first = tokens.issue(ivan).token;
    const std::string second = tokens.issue(ivan).token;
    tokens.revoke(first);
    EXPECT_FALSE(tokens.validate(first));
    EXPECT_TRUE(tokens.validate(second));
    tokens.revokeAllFor(ivan.id);
    EXPECT_FALSE(tokens.validate(second));
}

TEST_F(TokenServiceTest, ExpiredTokenIsInvalidAndDeleted)
{
    const User judy = makeUser("judy");
    for (const std::chrono::seconds ttl : {0s, -10s}) {
        TokenService tokens(storage->sessions(), storage->users(), ttl);
        const std::string token = tokens.issue(judy).token;
        EXPECT_FALSE(tokens.validate(token)) << "ttl " << ttl.count();
        SQLite::Statement q(db, "SELECT COUNT(*) FROM sessions");
        ASSERT_TRUE(q.executeStep());
        EXPECT_EQ(q.getColumn(0).getInt64(), 0) << "ttl " << ttl.count();
    }
}

TEST(LoginRateLimiter, BlocksAfterMaxFailuresUntilWindowPasses)
{
    auto now = LoginRateLimiter::Clock::time_point{};
    LoginRateLimiter limiter(3, 60s, [&] { return now; });
    const std::string key = "alice|10.0.0.1";
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(limiter.allowed(key)) << i;
        limiter.recordFailure(key);
        now += 10s;
    }
    EXPECT_FALSE(limiter.allowed(key));
    EXPECT_TRUE(limiter.allowed("alice|10.0.0.2"));
    // The first failure was at t=0: it leaves the window at t=60.
    now = LoginRateLimiter::Clock::time_point{} + 59s;
    EXPECT_FALSE(limiter.allowed(key));
    now += 1s;
    EXPECT_TRUE(limiter.allowed(key));
    // One more failure brings it back to three inside the window (t=10, 20, 60).
    limiter.recordFailure(key);
    EXPECT_FALSE(limiter.allowed(key));
}

TEST(LoginRateLimiter, RetryAfterIsWhenTheOldestFailureLeavesTheWindow)
{
    auto now = LoginRateLimiter::Clock::time_point{};
    LoginRateLimiter limiter(2, 60s, [&] { return now; });
    EXPECT_EQ(limiter.retryAfter("k"), 1s) << "no failures: at once (at least a second)";
    limiter.recordFailure("k");
    now += 15s;
    limiter.recordFailure("k");
    now += 500ms;
    EXPECT_EQ(limiter.retryAfter("k"), 45s) << "44.5 s, rounded up";
    now += 44s;
    EXPECT_EQ(limiter.retryAfter("k"), 1s);
}

TEST(LoginRateLimiter, SuccessClearsFailures)
{
    LoginRateLimiter limiter(2, 60s);
    limiter.recordFailure("k");
    limiter.recordSuccess("k");
    limiter.recordFailure("k");
    EXPECT_TRUE(limiter.allowed("k"));
    limiter.recordFailure("k");
    EXPECT_FALSE(limiter.allowed("k"));
}

TEST(AccessPolicy, ReadAndWriteTable)
{
    const User admin{1, "admin", "admin"};
    const User teacher{2, "t", "teacher"};
    const User alice{3, "alice", "user"};
    const User bob{4, "bob", "user"};

    struct Row {
        const User& who;
        std::int64_t ownerId;
        bool isExample, read, write;
    };
    const Row rows[] = {
        // own objects
        {alice, 3, false, true, true},
        {teacher, 2, false, true, true},
        // someone else's: a teacher reads students' work through a class (LabAccess), not by role
        {alice, 4, false, false, false},
        {alice, 2, false, false, false},
        {teacher, 3, false, false, false},
        {teacher, 5, false, false, false},
        {teacher, 1, false, false, false},
        {admin, 3, false, true, true},
        {admin, 2, false, true, true},
        // examples (owned by admin)
        {alice, 1, true, true, false},
        {teacher, 1, true, true, false},
        {admin, 1, true, true, true},
    };
    for (const Row& r : rows) {
        EXPECT_EQ(canRead(r.who, r.ownerId, r.isExample), r.read)
            << r.who.username << " reads owner " << r.ownerId << " example " << r.isExample;
        EXPECT_EQ(canWrite(r.who, r.ownerId, r.isExample), r.write)
            << r.who.username << " writes owner " << r.ownerId << " example " << r.isExample;
    }
}

TEST(AccessPolicy, JobsAndAdministration)
{
    const User admin{1, "admin", "admin"};
    const User teacher{2, "t", "teacher"};
    const User alice{3, "alice", "user"};

    EXPECT_TRUE(canControlJob(alice, 3));
    EXPECT_FALSE(canControlJob(alice, 4));
    EXPECT_FALSE(canControlJob(teacher, 3));   // a teacher supervising a student's job does not stop it
    EXPECT_TRUE(canControlJob(admin, 3));

    EXPECT_TRUE(canRerunJob(alice, 3));
    EXPECT_FALSE(canRerunJob(admin, 3));       // the new job would be the admin's
    EXPECT_FALSE(canRerunJob(teacher, 3));

    EXPECT_TRUE(isAdministrator(admin));
    EXPECT_FALSE(isAdministrator(teacher));
    EXPECT_FALSE(isAdministrator(alice));
}
