#include "TemporarySqliteStorage.h"
#include "server/store/UnixTime.h"

#include <SQLiteCpp/Statement.h>
#include <gtest/gtest.h>

#include <algorithm>

using namespace tlmhub::server;

namespace {

// Users are inserted directly (no password), so these tests cost no argon2 hashing.
struct ModelStoreTest : ::testing::Test {
    tlmhub::test::TemporarySqliteStorage storage;
    SQLite::Database& db = storage.raw();
    ModelStore& models = storage->models();

    User addUser(const std::string& name, const std::string& role)
    {
        SQLite::Statement insert(db, "INSERT INTO users(username, role) VALUES(?, ?)");
        insert.bind(1, name);
        insert.bind(2, role);
        insert.exec();
        return User{db.getLastInsertRowid(), name, role};
    }

    static std::vector<std::string> names(const std::vector<ModelSummary>& list)
    {
        std::vector<std::string> out;
        for (const ModelSummary& s : list) out.push_back(s.name);
        return out;
    }
};

using Names = std::vector<std::string>;

} // namespace

TEST_F(ModelStoreTest, CreateThenReadSummaryAndText)
{
    const User alice = addUser("alice", "user");
    const std::int64_t before = unixNow();
    const std::int64_t id = *models.create(alice.id, "Pump", "<hopsanmodelfile/>", false);
    EXPECT_GT(id, 0);

    const std::optional<ModelSummary> s = models.summary(id);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->id, id);
    EXPECT_EQ(s->name, "Pump");
    EXPECT_EQ(s->ownerId, alice.id);
    EXPECT_EQ(s->ownerName, "alice");
    EXPECT_EQ(s->ownerRole, "user");
    EXPECT_FALSE(s->isExample);
    EXPECT_GE(s->createdAt, before);
    EXPECT_EQ(s->updatedAt, s->createdAt);
    EXPECT_EQ(models.hmf(id), "<hopsanmodelfile/>");

    EXPECT_FALSE(models.summary(id + 1));
    EXPECT_FALSE(models.hmf(id + 1));
}

TEST_F(ModelStoreTest, NamesNeedNotBeUnique)
{
    const User alice = addUser("alice", "user");
    const std::int64_t a = *models.create(alice.id, "Same", "a", false);
    const std::int64_t b = *models.create(alice.id, "Same", "b", false);
    EXPECT_NE(a, b);
    EXPECT_EQ(models.hmf(a), "a");
    EXPECT_EQ(models.hmf(b), "b");
}

TEST_F(ModelStoreTest, UpdateChangesOnlyGivenFields)
{
    const User alice = addUser("alice", "user");
    const std::int64_t id = *models.create(alice.id, "Old", "text 1", false);
    // Age the row so the updated_at change is visible without sleeping.
    db.exec("UPDATE models SET created_at = 100, updated_at = 100");

    EXPECT_TRUE(models.update(id, std::string("New"), std::nullopt));
    EXPECT_EQ(models.summary(id)->name, "New");
    EXPECT_EQ(models.hmf(id), "text 1");
    EXPECT_GT(models.summary(id)->updatedAt, 100);
    EXPECT_EQ(models.summary(id)->createdAt, 100);

    EXPECT_TRUE(models.update(id, std::nullopt, std::string("text 2")));
    EXPECT_EQ(models.summary(id)->name, "New");
    EXPECT_EQ(models.hmf(id), "text 2");

    EXPECT_TRUE(models.update(id, std::string(""), std::string("")));
    EXPECT_EQ(models.summary(id)->name, "");
    EXPECT_EQ(models.hmf(id), "");

    EXPECT_FALSE(models.update(id + 1, std::string("x"), std::nullopt));
}

TEST_F(ModelStoreTest, RemoveDeletesOnce)
{
    const User alice = addUser("alice", "user");
    const std::int64_t id = *models.create(alice.id, "Gone", "x", false);
    EXPECT_TRUE(models.remove(id));
    EXPECT_FALSE(models.summary(id));
    EXPECT_FALSE(models.remove(id));
}

TEST_F(ModelStoreTest, OwnerMustExist)
{
    EXPECT_FALSE(models.create(999, "Orphan", "x", false));
}

TEST_F(ModelStoreTest, ListVisibleToFollowsRoles)
{
    const User admin = addUser("admin", "admin");
    const User teacher = addUser("teacher", "teacher");
    const User teacher2 = addUser("teacher2", "teacher");
    const User alice = addUser("alice", "user");
    const User bob = addUser("bob", "user");
    models.create(admin.id, "Example", "x", true);
    models.create(admin.id, "AdminPrivate", "x", false);
    models.create(teacher.id, "TeacherOwn", "x", false);
    models.create(teacher2.id, "Teacher2Own", "x", false);
    models.create(alice.id, "AliceOwn", "x", false);
    models.create(bob.id, "BobOwn", "x", false);

    EXPECT_EQ(names(models.listVisibleTo(admin)),
              (Names{"Example", "AdminPrivate", "TeacherOwn", "Teacher2Own", "AliceOwn", "BobOwn"}));
    // A teacher's role alone shows no one else's models (students' copies: through a class).
    EXPECT_EQ(names(models.listVisibleTo(teacher)), (Names{"Example", "TeacherOwn"}));
    EXPECT_EQ(names(models.listVisibleTo(alice)), (Names{"Example", "AliceOwn"}));
    EXPECT_EQ(names(models.listVisibleTo(bob)), (Names{"Example", "BobOwn"}));

    const std::vector<ModelSummary> forAlice = models.listVisibleTo(alice);
    EXPECT_TRUE(forAlice[0].isExample);
    EXPECT_EQ(forAlice[0].ownerName, "admin");
    EXPECT_FALSE(forAlice[1].isExample);
}
