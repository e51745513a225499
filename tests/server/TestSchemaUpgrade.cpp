// A data directory written by the released server (before schema migrations existed: no
// schema_migrations table, version 0) upgrades in place, and every row reads back through
// the stores.
//
// The fixture tests/server/data/tlmhub-bc8980a.sql is `sqlite3 tlmhub.sqlite .dump` of a
// data directory made by tlmhub-server built from commit bc8980a:
//   TLMHUB_ADMIN_PASSWORD=admin-secret-pw tlmhub-server --data-dir D --listen 127.0.0.1:0
//       --examples-dir examples --workers 1          (seeds example model 1, pressure-build-up)
//   then through its REST API: admin logs in; POST /users bob (teacher, "bob-password-1") and
//   carol (user, "carol-password-1"); PATCH carol {disabled: true}; bob logs in and saves
//   examples/pressure-build-up.hmf as model 2 named "Druckaufbau Ölpumpe – 試験 ✓"; bob runs
//   job 1 on it (start 0, step 0.001, stop 0.5, log_samples 11) to done; SIGTERM.
// So it holds 3 users, 2 sessions (admin's and bob's, expiring 12 h after they were made),
// 2 models, 1 finished job with its result and one meta row.
#include "ServerHarness.h"

#include "server/auth/Accounts.h"
#include "server/store/Storage.h"

#include <SQLiteCpp/Database.h>
#include <SQLiteCpp/Statement.h>
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <set>

using namespace tlmhub::server;
using namespace tlmhub::test;
namespace fs = std::filesystem;

namespace {

const fs::path kFixture = fs::path(TLMHUB_SOURCE_DIR) / "tests/server/data/tlmhub-bc8980a.sql";
// When the fixture was made: its sessions are valid then (they expire 12 h later).
constexpr std::int64_t kFixtureTime = 1796288186;
const std::string kModelName = "Druckaufbau Ölpumpe – 試験 ✓";

// A new SQLite file holding the fixture, made with the dump's own SQL.
fs::path loadFixture(const std::string& name)
{
    const fs::path file = freshTempDir(name) / "tlmhub.sqlite";
    sqlite3* db = nullptr;
    EXPECT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
    char* error = nullptr;
    EXPECT_EQ(sqlite3_exec(db, readFile(kFixture).c_str(), nullptr, nullptr, &error), SQLITE_OK)
        << (error ? error : "");
    sqlite3_free(error);
    sqlite3_close(db);
    return file;
}

std::set<std::string> indexesOf(SQLite::Database& db, const std::string& table)
{
    std::set<std::string> names;
    SQLite::Statement q(db, "PRAGMA index_list(" + table + ")");
    while (q.executeStep()) names.insert(q.getColumn(1).getString());
    return names;
}

std::vector<std::pair<int, std::int64_t>> migrationsOf(const fs::path& file)
{
    SQLite::Database db(file.string(), SQLite::OPEN_READONLY);
    std::vector<std::pair<int, std::int64_t>> rows;
    SQLite::Statement q(db, "SELECT version, applied_at FROM schema_migrations ORDER BY version");
    while (q.executeStep()) rows.emplace_back(q.getColumn(0).getInt(), q.getColumn(1).getInt64());
    return rows;
}

} // namespace

TEST(SchemaUpgrade, FixtureIsFromBeforeMigrations)
{
    const fs::path file = loadFixture("upgrade-fixture");
    SQLite::Database db(file.string(), SQLite::OPEN_READONLY);
    EXPECT_FALSE(db.tableExists("schema_migrations"));
    EXPECT_EQ(indexesOf(db, "sessions").count("sessions_user"), 0u);
    fs::remove_all(file.parent_path());
}

TEST(SchemaUpgrade, ReleasedDataDirectoryUpgradesInPlace)
{
    const fs::path file = loadFixture("upgrade");
    // The rows as the released server wrote them, read before the upgrade.
    std::string jobRequest, resultBlob;
    {
        SQLite::Database raw(file.string(), SQLite::OPEN_READONLY);
        jobRequest = raw.execAndGet("SELECT request FROM jobs WHERE id = 1").getString();
        resultBlob = raw.execAndGet("SELECT data FROM job_results WHERE job_id = 1").getString();
    }
    ASSERT_FALSE(resultBlob.empty());

    {
        const auto storage = openStorage({.database = file.string()});
        EXPECT_EQ(storage->schemaVersion(), kSchemaVersion);

        Accounts accounts(storage->users());
        const std::vector<User> users = storage->users().list();
        ASSERT_EQ(users.size(), 3u);
        const std::tuple<const char*, const char*, bool, const char*> expectedUsers[] = {
            {"admin", "admin", false, "admin-secret-pw"},
            {"bob", "teacher", false, "bob-password-1"},
            {"carol", "user", true, "carol-password-1"}};
        for (std::size_t i = 0; i < users.size(); ++i) {
            const auto& [name, role, disabled, password] = expectedUsers[i];
            EXPECT_EQ(users[i].id, static_cast<std::int64_t>(i + 1));
            EXPECT_EQ(users[i].username, name);
            EXPECT_EQ(users[i].role, role);
            EXPECT_EQ(users[i].disabled, disabled);
            // The old password still logs in (the argon2id hash is kept as it was).
            const auto loggedIn = accounts.authenticate(name, password);
            ASSERT_TRUE(loggedIn) << name;
            EXPECT_EQ(loggedIn->id, users[i].id);
            EXPECT_FALSE(accounts.authenticate(name, "wrong-password")) << name;
        }

        EXPECT_EQ(storage->sessions().userOf(
                      "d5b3c3833ca89da335dc36708aef52c0fece09d92a5c3bf72a179cd3fefaaccf", kFixtureTime),
                  std::optional<std::int64_t>(1));
        EXPECT_EQ(storage->sessions().userOf(
                      "3782b3fca1f1f0f5c2853406c00603ec14240c22eaadf67aafd26f955689439c", kFixtureTime),
                  std::optional<std::int64_t>(2));

        const std::vector<ModelSummary> models = storage->models().list();
        ASSERT_EQ(models.size(), 2u);
        EXPECT_EQ(models[0].name, "pressure-build-up");
        EXPECT_TRUE(models[0].isExample);
        EXPECT_EQ(models[0].ownerName, "admin");
        EXPECT_EQ(models[1].id, 2);
        EXPECT_EQ(models[1].name, kModelName);
        EXPECT_FALSE(models[1].isExample);
        EXPECT_EQ(models[1].ownerId, 2);
        EXPECT_EQ(models[1].ownerName, "bob");
        EXPECT_EQ(models[1].ownerRole, "teacher");
        EXPECT_EQ(models[1].createdAt, kFixtureTime);
        EXPECT_EQ(models[1].updatedAt, kFixtureTime);
        const auto hmf = storage->models().hmf(2);
        ASSERT_TRUE(hmf);
        EXPECT_EQ(hmf->size(), 2865u);
        EXPECT_NE(hmf->find("<system name=\"PressureBuildUp\""), std::string::npos);

        const auto job = storage->jobs().info(1);
        ASSERT_TRUE(job);
        EXPECT_EQ(job->ownerId, 2);
        EXPECT_EQ(job->modelId, std::optional<std::int64_t>(2));
        EXPECT_EQ(job->state, JobState::Done);
        EXPECT_EQ(job->progress, 1.0);
        EXPECT_EQ(job->error, "");
        EXPECT_EQ(job->createdAt, kFixtureTime);
        EXPECT_EQ(job->startedAt, kFixtureTime);
        EXPECT_EQ(job->finishedAt, kFixtureTime);
        EXPECT_EQ(job->steps, 500u);
        EXPECT_EQ(job->start, 0.0);
        EXPECT_EQ(job->step, 0.001);
        EXPECT_EQ(job->stop, 0.5);
        EXPECT_EQ(job->logSamples, 11u);
        EXPECT_EQ(storage->jobs().requestText(1), std::optional<std::string>(jobRequest));
        const auto request = storage->jobs().request(1);
        ASSERT_TRUE(request);
        EXPECT_EQ(request->ownerId, 2);
        EXPECT_EQ(request->hmf, *hmf);
        EXPECT_EQ(storage->jobs().listForOwner(2).size(), 1u);

        EXPECT_TRUE(storage->results().has(1));
        EXPECT_EQ(storage->results().blob(1), std::optional<std::string>(resultBlob));
        EXPECT_EQ(storage->results().storedBytes(2), resultBlob.size());
        const auto result = storage->results().result(1);
        ASSERT_TRUE(result);
        ASSERT_EQ(result->time.size(), 11u);
        EXPECT_DOUBLE_EQ(result->time.back(), 0.5);
        const auto* pressure = result->column("ChamberPressure#P1#Pressure");
        ASSERT_TRUE(pressure);
        // The value of the released server's CSV of this job.
        EXPECT_EQ(pressure->data.back(), 10071068.841344679);
        EXPECT_EQ(result->columns.size(), 58u);

        EXPECT_EQ(storage->meta().get("seeded:pressure-build-up.hmf"), std::optional<std::string>("1796288184"));

        // Version 3's tables take rows of the old accounts and models.
        const auto token = storage->apiTokens().insert(2, "bob's script", "hash of bob's token", kFixtureTime, std::nullopt);
        ASSERT_TRUE(token);
        EXPECT_EQ(storage->apiTokens().use("hash of bob's token", kFixtureTime)->userId, 2);
        const auto study = storage->studies().create(2, 2, "sweep", "pump size", "{}", 4, "node-1", 2);
        ASSERT_TRUE(study);
        EXPECT_EQ(storage->studies().info(*study)->modelId, std::optional<std::int64_t>(2));
        // Version 9's: the study is held by the node that created it, and only it starts it.
        EXPECT_FALSE(storage->studies().markRunning(*study, "node-2"));
        EXPECT_TRUE(storage->studies().markRunning(*study, "node-1"));

        // Version 4's too: bob's class, with carol in it and a copy of hers.
        const auto lab = storage->labs().createClass(2, "Hydraulics", "ABCDEFGHJKLM");
        ASSERT_TRUE(lab);
        ASSERT_TRUE(storage->labs().setMember(*lab, 3, kClassStudent));
        AssignmentInfo assignment;
        assignment.classId = *lab;
        assignment.title = "Pressure build-up";
        assignment.editMode = "free";
        assignment.parameters = "[]";
        const auto assignmentId = storage->labs().createAssignment(assignment, "<template/>", "");
        ASSERT_TRUE(assignmentId);
        const auto carolsCopy = storage->models().create(3, "Pressure build-up", "<template/>", false);
        ASSERT_TRUE(carolsCopy);
        ASSERT_TRUE(storage->labs().createCopy(StudentCopy{*assignmentId, 3, *carolsCopy, 1, 0}));
        EXPECT_TRUE(storage->labs().supervisesCopy(2, *carolsCopy));

        // Version 5's: the old job was never claimed and holds no lease; nodes register.
        EXPECT_EQ(storage->jobLeases().claims(1), 0);
        EXPECT_FALSE(storage->jobLeases().holder(1));
        EXPECT_EQ(storage->jobLeases().queuedCount(2), 0);
        storage->jobLeases().touchNode(NodeInfo{"node-1", "all", "http://127.0.0.1:8080", 0});
        EXPECT_EQ(storage->jobLeases().liveNodes(std::chrono::seconds(60)).size(), 1u);
    }

    // The migrations are recorded, version 2's to 5's indexes exist, and opening again
    // applies nothing more.
    const auto applied = migrationsOf(file);
    ASSERT_EQ(applied.size(), static_cast<std::size_t>(kSchemaVersion));
    for (int v = 1; v <= kSchemaVersion; ++v) EXPECT_EQ(applied[static_cast<std::size_t>(v - 1)].first, v);
    {
        SQLite::Database raw(file.string(), SQLite::OPEN_READONLY);
        const auto indexes = indexesOf(raw, "sessions");
        EXPECT_EQ(indexes.count("sessions_user"), 1u);
        EXPECT_EQ(indexes.count("sessions_expiry"), 1u);
        EXPECT_EQ(indexesOf(raw, "api_tokens").count("api_tokens_user"), 1u);
        EXPECT_EQ(indexesOf(raw, "studies").count("studies_owner"), 1u);
        EXPECT_EQ(indexesOf(raw, "class_members").count("class_members_user"), 1u);
        EXPECT_EQ(indexesOf(raw, "jobs").count("jobs_claim"), 1u);
        EXPECT_EQ(indexesOf(raw, "jobs").count("jobs_lease_expiry"), 1u);
    }
    {
        const auto again = openStorage({.database = file.string()});
        EXPECT_EQ(again->schemaVersion(), kSchemaVersion);
        EXPECT_EQ(again->models().list().size(), 3u);   // the fixture's two and carol's copy
    }
    EXPECT_EQ(migrationsOf(file), applied);
    fs::remove_all(file.parent_path());
}
