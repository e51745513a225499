// UserStore's contract (server/store/UserStore.h) on both back ends.
#include "StoreBackends.h"

#include <vector>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class UserStoreConformance : public StoreTest {};
TLMHUB_STORE_CONFORMANCE(UserStoreConformance);

void expectSameUser(const User& a, const User& b)
{
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.username, b.username);
    EXPECT_EQ(a.role, b.role);
    EXPECT_EQ(a.disabled, b.disabled);
}

UserChange roleTo(const std::string& role)
{
    UserChange c;
    c.role = role;
    return c;
}

UserChange disabledTo(bool disabled)
{
    UserChange c;
    c.disabled = disabled;
    return c;
}

UserChange both(const std::string& role, bool disabled)
{
    UserChange c;
    c.role = role;
    c.disabled = disabled;
    return c;
}

int enabledAdmins(UserStore& users)
{
    int n = 0;
    for (const User& u : users.list()) n += u.role == kRoleAdmin && !u.disabled;
    return n;
}

TEST_P(UserStoreConformance, InsertReturnsTheNewAccountAsFindShowsIt)
{
    const auto alice = store().users().insert("alice", "h-alice", kRoleTeacher);
    ASSERT_TRUE(alice);
    EXPECT_GT(alice->id, 0);
    EXPECT_EQ(alice->username, "alice");
    EXPECT_EQ(alice->role, kRoleTeacher);
    EXPECT_FALSE(alice->disabled);
    const auto found = store().users().find(alice->id);
    ASSERT_TRUE(found);
    expectSameUser(*found, *alice);
    const auto bob = store().users().insert("bob", "h-bob", kRoleUser);
    ASSERT_TRUE(bob);
    EXPECT_NE(bob->id, alice->id);
}

TEST_P(UserStoreConformance, InsertRefusesANameTakenInAnyCase)
{
    addUser("alice");
    EXPECT_FALSE(store().users().insert("alice", "h", kRoleUser));
    EXPECT_FALSE(store().users().insert("ALICE", "h", kRoleUser));
    EXPECT_FALSE(store().users().insert("Alice", "h", kRoleAdmin));
    EXPECT_EQ(store().users().count(), 1u);
}

TEST_P(UserStoreConformance, ConcurrentInsertsOfOneNameInDifferentCasesMakeOneAccount)
{
    const std::vector<std::string> spellings{"carol", "CAROL", "Carol", "cArOl", "caROL", "CARol", "carOL", "CaRoL"};
    std::vector<int> made(spellings.size(), 0);
    runAtOnce(static_cast<int>(spellings.size()), [&](int i) {
        made[static_cast<std::size_t>(i)] = store().users().insert(spellings[static_cast<std::size_t>(i)], "h", kRoleUser).has_value();
    });
    int total = 0;
    for (int m : made) total += m;
    EXPECT_EQ(total, 1);
    EXPECT_EQ(store().users().count(), 1u);
}

TEST_P(UserStoreConformance, CredentialsByNameMatchTheExactNameElseAnyCase)
{
    const User alice = addUser("alice");
    const User bob = addUser("Bob");
    const auto exact = store().users().credentials("alice");
    ASSERT_TRUE(exact);
    EXPECT_EQ(exact->id, alice.id);
    EXPECT_EQ(exact->passwordHash, "hash of alice");
    const auto upper = store().users().credentials("ALICE");
    ASSERT_TRUE(upper);
    EXPECT_EQ(upper->id, alice.id);
    const auto lower = store().users().credentials("bob");
    ASSERT_TRUE(lower);
    EXPECT_EQ(lower->id, bob.id);
    EXPECT_EQ(lower->passwordHash, "hash of Bob");
    EXPECT_FALSE(store().users().credentials("carol"));
    EXPECT_FALSE(store().users().credentials("alic"));
    EXPECT_FALSE(store().users().credentials(""));
}

TEST_P(UserStoreConformance, CredentialsByIdGiveTheHashOrNothingForAnUnknownId)
{
    const User alice = addUser("alice");
    const auto c = store().users().credentials(alice.id);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->id, alice.id);
    EXPECT_EQ(c->passwordHash, "hash of alice");
    EXPECT_FALSE(store().users().credentials(alice.id + 1000));
}

TEST_P(UserStoreConformance, SetPasswordHashReplacesOnlyThatAccountsHash)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob");
    EXPECT_TRUE(store().users().setPasswordHash(alice.id, "new hash"));
    EXPECT_EQ(store().users().credentials(alice.id)->passwordHash, "new hash");
    EXPECT_EQ(store().users().credentials("alice")->passwordHash, "new hash");
    EXPECT_EQ(store().users().credentials(bob.id)->passwordHash, "hash of bob");
    EXPECT_FALSE(store().users().setPasswordHash(bob.id + 1000, "x"));
}

TEST_P(UserStoreConformance, FindByNameMatchesOnlyTheExactName)
{
    const User alice = addUser("alice", kRoleAdmin);
    const auto found = store().users().findByName("alice");
    ASSERT_TRUE(found);
    expectSameUser(*found, alice);
    EXPECT_FALSE(store().users().findByName("ALICE"));
    EXPECT_FALSE(store().users().findByName("alice "));
    EXPECT_FALSE(store().users().find(alice.id + 1000));
}

TEST_P(UserStoreConformance, ListIsInIdOrderAndCountAgrees)
{
    EXPECT_TRUE(store().users().list().empty());
    EXPECT_EQ(store().users().count(), 0u);
    // Names in reverse alphabetical order, so an order by name would show.
    const User z = addUser("zed", kRoleAdmin);
    const User m = addUser("mia", kRoleTeacher);
    const User a = addUser("abe");
    const auto list = store().users().list();
    ASSERT_EQ(list.size(), 3u);
    expectSameUser(list[0], z);
    expectSameUser(list[1], m);
    expectSameUser(list[2], a);
    EXPECT_LT(list[0].id, list[1].id);
    EXPECT_LT(list[1].id, list[2].id);
    EXPECT_EQ(store().users().count(), 3u);
}

TEST_P(UserStoreConformance, ChangeSetsRoleAndDisabledAndLeavesOtherFields)
{
    addUser("root", kRoleAdmin);
    const User u = addUser("u");
    User updated;
    ASSERT_EQ(store().users().change(u.id, roleTo(kRoleTeacher), updated), UserChangeOutcome::Changed);
    EXPECT_EQ(updated.id, u.id);
    EXPECT_EQ(updated.username, "u");
    EXPECT_EQ(updated.role, kRoleTeacher);
    EXPECT_FALSE(updated.disabled);
    ASSERT_EQ(store().users().change(u.id, disabledTo(true), updated), UserChangeOutcome::Changed);
    EXPECT_EQ(updated.role, kRoleTeacher);
    EXPECT_TRUE(updated.disabled);
    expectSameUser(*store().users().find(u.id), updated);
    ASSERT_EQ(store().users().change(u.id, both(kRoleUser, false), updated), UserChangeOutcome::Changed);
    EXPECT_EQ(updated.role, kRoleUser);
    EXPECT_FALSE(updated.disabled);
    expectSameUser(*store().users().find(u.id), updated);
    EXPECT_EQ(store().users().credentials(u.id)->passwordHash, "hash of u");
}

TEST_P(UserStoreConformance, ChangeOfAnUnknownAccountIsNoSuchUser)
{
    const User root = addUser("root", kRoleAdmin);
    User updated;
    EXPECT_EQ(store().users().change(root.id + 1000, roleTo(kRoleUser), updated), UserChangeOutcome::NoSuchUser);
}

TEST_P(UserStoreConformance, ChangeRefusesToDemoteOrDisableTheLastEnabledAdminAndChangesNothing)
{
    const User root = addUser("root", kRoleAdmin);
    const User dormant = addUser("dormant", kRoleAdmin);
    User updated;
    ASSERT_EQ(store().users().change(dormant.id, disabledTo(true), updated), UserChangeOutcome::Changed);
    // A disabled admin does not administer the server: root is the last one.
    EXPECT_EQ(store().users().change(root.id, roleTo(kRoleTeacher), updated), UserChangeOutcome::LastAdmin);
    EXPECT_EQ(store().users().change(root.id, disabledTo(true), updated), UserChangeOutcome::LastAdmin);
    // Giving a field the value it has already does not let a demotion through.
    EXPECT_EQ(store().users().change(root.id, both(kRoleUser, false), updated),
              UserChangeOutcome::LastAdmin);
    expectSameUser(*store().users().find(root.id), root);
    // With the other admin enabled again, root may go.
    ASSERT_EQ(store().users().change(dormant.id, disabledTo(false), updated), UserChangeOutcome::Changed);
    EXPECT_EQ(store().users().change(root.id, roleTo(kRoleUser), updated), UserChangeOutcome::Changed);
    EXPECT_EQ(enabledAdmins(store().users()), 1);
}

TEST_P(UserStoreConformance, TwoAdminsDemotingEachOtherAtOnceLeaveOneAdmin)
{
    User survivor = addUser("admin0", kRoleAdmin);
    for (int round = 1; round <= 20; ++round) {
        const User newcomer = addUser("admin" + std::to_string(round), kRoleAdmin);
        // Alternate demoting and disabling: both take away an administrator.
        const UserChange takeAway = round % 2 ? roleTo(kRoleUser) : disabledTo(true);
        UserChangeOutcome outcomes[2] = {UserChangeOutcome::NoSuchUser, UserChangeOutcome::NoSuchUser};
        User updated[2];
        const std::int64_t ids[2] = {survivor.id, newcomer.id};
        runAtOnce(2, [&](int i) { outcomes[i] = store().users().change(ids[i], takeAway, updated[i]); });
        ASSERT_EQ(enabledAdmins(store().users()), 1) << "round " << round;
        const int changed = (outcomes[0] == UserChangeOutcome::Changed) + (outcomes[1] == UserChangeOutcome::Changed);
        const int refused = (outcomes[0] == UserChangeOutcome::LastAdmin) + (outcomes[1] == UserChangeOutcome::LastAdmin);
        ASSERT_EQ(changed, 1) << "round " << round;
        ASSERT_EQ(refused, 1) << "round " << round;
        survivor = outcomes[0] == UserChangeOutcome::Changed ? newcomer : survivor;
    }
}

TEST_P(UserStoreConformance, NamesDifferingOnlyInCaseIsEmptyWhenInsertKeepsNamesApart)
{
    EXPECT_TRUE(store().users().namesDifferingOnlyInCase().empty());
    addUser("alice");
    addUser("bob");
    EXPECT_FALSE(store().users().insert("ALICE", "h", kRoleUser));
    EXPECT_TRUE(store().users().namesDifferingOnlyInCase().empty());
}

// Databases from before names were compared regardless of case may hold "alice" and "ALICE".
// Only SQLite's schema lets such rows exist (PostgreSQL's unique index is on lower(name)), so
// they are made past the store.
TEST(SQLiteStore, AccountsWhoseNamesDifferOnlyInCaseAreListedAndNotGuessedBetween)
{
    FreshDatabase db(Backend::SQLite);
    auto storage = db.open();
    const auto alice = storage->users().insert("alice", "h-alice", kRoleUser);
    ASSERT_TRUE(alice);
    storage->users().insert("bob", "h-bob", kRoleUser);
    db.exec("INSERT INTO users(username, password_hash, role, created_at) VALUES('ALICE', 'h-ALICE', 'user', 0)");
    db.exec("INSERT INTO users(username, password_hash, role, created_at) VALUES('Alice', 'h-Alice', 'user', 0)");
    EXPECT_EQ(storage->users().namesDifferingOnlyInCase(), std::vector<std::string>{"alice, ALICE, Alice"});
    EXPECT_EQ(storage->users().credentials("alice")->id, alice->id) << "the exact name still logs in";
    EXPECT_EQ(storage->users().credentials("ALICE")->passwordHash, "h-ALICE");
    EXPECT_FALSE(storage->users().credentials("aLiCe")) << "ambiguous";
    EXPECT_EQ(storage->users().credentials("BOB")->passwordHash, "h-bob");
}

// An account's own settings (GET/PUT /preferences): "{}" until set, replaced whole, one
// account's never another's, none for an account that does not exist.
TEST_P(UserStoreConformance, PreferencesStartEmptyAndAreReplacedWholePerAccount)
{
    const auto alice = addUser("alice");
    const auto bob = addUser("bob");
    EXPECT_EQ(store().users().preferences(alice.id), "{}");
    const std::string units = R"({"units":{"Flow":"l/min","Pressure":"bar","Temperature":"°C"}})";
    ASSERT_TRUE(store().users().setPreferences(alice.id, units));
    EXPECT_EQ(store().users().preferences(alice.id), units);
    EXPECT_EQ(store().users().preferences(bob.id), "{}");
    ASSERT_TRUE(store().users().setPreferences(alice.id, R"({"units":{}})"));
    EXPECT_EQ(store().users().preferences(alice.id), R"({"units":{}})");
    EXPECT_FALSE(store().users().preferences(bob.id + 1000));
    EXPECT_FALSE(store().users().setPreferences(bob.id + 1000, units));
}

TEST_P(UserStoreConformance, AnIdentityGetsItsOwnPasswordlessAccountNeverALocalOneOfTheSameName)
{
    UserStore& users = store().users();
    const std::string ldap = "ldap ldaps://directory.example.org";
    const auto local = users.insert("admin", "h-admin", kRoleAdmin);
    ASSERT_TRUE(local);
    EXPECT_FALSE(users.findByIdentity(ldap, "uid=admin,ou=people,dc=example,dc=org"));

    // The directory's "admin" is someone else: a new account, named apart, that has no password.
    const User theirs = users.insertLinked(ldap, "uid=admin,ou=people,dc=example,dc=org", "admin", kRoleUser);
    EXPECT_NE(theirs.id, local->id);
    EXPECT_EQ(theirs.username, "admin-2");
    EXPECT_EQ(theirs.role, kRoleUser);
    ASSERT_TRUE(users.credentials(theirs.id));
    EXPECT_FALSE(users.credentials(theirs.id)->passwordHash);
    const auto found = users.findByIdentity(ldap, "uid=admin,ou=people,dc=example,dc=org");
    ASSERT_TRUE(found);
    expectSameUser(*found, theirs);
    // Signing in again finds the same account; the subject elsewhere, or another one, does not.
    expectSameUser(users.insertLinked(ldap, "uid=admin,ou=people,dc=example,dc=org", "admin", kRoleTeacher), theirs);
    EXPECT_FALSE(users.findByIdentity("ldap ldaps://other.example.org", "uid=admin,ou=people,dc=example,dc=org"));
    EXPECT_FALSE(users.findByIdentity(ldap, "uid=Admin,ou=people,dc=example,dc=org"));
    EXPECT_EQ(users.insertLinked(ldap, "uid=third,dc=example,dc=org", "admin", kRoleUser).username, "admin-3");
    // A long name keeps to 64 characters with its number.
    const std::string longName(64, 'x');
    ASSERT_TRUE(users.insert(longName, "h", kRoleUser));
    EXPECT_EQ(users.insertLinked(ldap, "uid=long", longName, kRoleUser).username, std::string(62, 'x') + "-2");
}

TEST_P(UserStoreConformance, ConcurrentFirstSignInsOfOnePersonMakeOneAccount)
{
    constexpr int kAttempts = 8;
    std::vector<std::int64_t> ids(kAttempts, 0);
    runAtOnce(kAttempts, [&](int i) {
        ids[static_cast<std::size_t>(i)] =
            store().users().insertLinked("ldap ldap://x", "uid=dora,dc=x", "dora", kRoleUser).id;
    });
    for (std::int64_t id : ids) EXPECT_EQ(id, ids[0]);
    EXPECT_EQ(store().users().count(), 1u);
}

} // namespace
} // namespace tlmhub::test
