// Storage as a whole on both back ends: opening and migrating, meta facts, text that is not
// ASCII, and a transaction that fails half way.
#include "StoreBackends.h"

#include "server/store/StoreError.h"

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class StorageConformance : public StoreTest {};
TLMHUB_STORE_CONFORMANCE(StorageConformance);

// The StoreError code `open` throws; fails the test when it throws none.
template <typename Open>
std::optional<StoreErrc> storeErrorOf(Open&& open)
{
    try {
        open();
    } catch (const StoreError& e) {
        return e.code();
    }
    ADD_FAILURE() << "no StoreError";
    return std::nullopt;
}

TEST_P(StorageConformance, SchemaIsAtTheCurrentVersionAfterOpening)
{
    EXPECT_EQ(store().schemaVersion(), kSchemaVersion);
}

TEST_P(StorageConformance, OpeningAgainMigratesNothingAndKeepsTheData)
{
    const User alice = addUser("alice");
    store().meta().set("seeded", "yes");
    // A second server on the same database while the first runs, then after it stopped.
    auto second = db->open();
    EXPECT_EQ(second->schemaVersion(), kSchemaVersion);
    storage.reset();
    second.reset();
    storage = db->open();
    EXPECT_EQ(store().schemaVersion(), kSchemaVersion);
    ASSERT_TRUE(store().users().find(alice.id));
    EXPECT_EQ(store().users().find(alice.id)->username, "alice");
    EXPECT_EQ(store().meta().get("seeded"), "yes");
}

TEST_P(StorageConformance, ADatabaseOfANewerSchemaIsRefusedAsCorrupt)
{
    storage.reset();
    db->exec("INSERT INTO schema_migrations(version, applied_at) VALUES(" + std::to_string(kSchemaVersion + 1) + ", 0)");
    EXPECT_EQ(storeErrorOf([&] { db->open(); }), StoreErrc::Corrupt);
}

TEST_P(StorageConformance, AnUnreachableDatabaseIsUnavailable)
{
    StorageConfig config;
    // Port 1 on loopback: nothing listens there.
    config.database = GetParam() == Backend::SQLite ? (db->directory() / "no such directory" / "x.sqlite").string()
                                                    : "postgresql://tlmhub@127.0.0.1:1/nothing?connect_timeout=5";
    EXPECT_EQ(storeErrorOf([&] { openStorage(config); }), StoreErrc::Unavailable);
}

TEST_P(StorageConformance, DescribeNamesTheBackEnd)
{
    const std::string prefix = GetParam() == Backend::SQLite ? "SQLite " : "PostgreSQL ";
    EXPECT_TRUE(store().describe().starts_with(prefix)) << store().describe();
}

TEST_P(StorageConformance, BackupWritesASnapshotOrIsRefusedByTheBackEnd)
{
    const User alice = addUser("alice");
    const auto snapshot = db->directory() / "snapshot.sqlite";
    if (GetParam() == Backend::PostgreSQL) {
        EXPECT_TRUE(storeErrorOf([&] { store().backup(snapshot); }));
        return;
    }
    store().backup(snapshot);
    addUser("after the backup");
    StorageConfig config;
    config.database = snapshot.string();
    auto copy = openStorage(config);
    EXPECT_EQ(copy->users().count(), 1u);
    EXPECT_EQ(copy->users().find(alice.id)->username, "alice");
}

TEST_P(StorageConformance, MetaGetsNothingForAnUnsetKeyAndTheLastValueSet)
{
    EXPECT_FALSE(store().meta().get("examples"));
    store().meta().set("examples", "a,b");
    store().meta().set("other", "");
    EXPECT_EQ(store().meta().get("examples"), "a,b");
    EXPECT_EQ(store().meta().get("other"), "");
    store().meta().set("examples", "a,b,c");
    EXPECT_EQ(store().meta().get("examples"), "a,b,c");
    EXPECT_FALSE(store().meta().get("Examples"));
}

// Nodes starting at once on one database seed each example once: the one that adds its
// marker seeds it (issue 37 R1).
TEST_P(StorageConformance, MetaInsertIfAbsentAddsAKeyOnceAndKeepsTheFirstValue)
{
    EXPECT_TRUE(store().meta().insertIfAbsent("seeded:a.hmf", "1"));
    EXPECT_FALSE(store().meta().insertIfAbsent("seeded:a.hmf", "2"));
    EXPECT_EQ(store().meta().get("seeded:a.hmf"), "1");
    store().meta().set("seeded:b.hmf", "3");
    EXPECT_FALSE(store().meta().insertIfAbsent("seeded:b.hmf", "4"));
    EXPECT_TRUE(store().meta().insertIfAbsent("seeded:c.hmf", ""));
}

TEST_P(StorageConformance, TextThatIsNotAsciiComesBackByteForByte)
{
    const std::string text = "Prüfstand 水圧 🚀";
    const auto user = store().users().insert(text, "hash " + text, kRoleTeacher);
    ASSERT_TRUE(user);
    EXPECT_EQ(user->username, text);
    EXPECT_EQ(store().users().findByName(text)->id, user->id);
    EXPECT_EQ(store().users().credentials(text)->id, user->id);
    EXPECT_EQ(store().users().credentials(user->id)->passwordHash, "hash " + text);
    EXPECT_EQ(store().users().list().at(0).username, text);

    const auto model = store().models().create(user->id, "Modell " + text, "<hmf name=\"" + text + "\"/>", false);
    ASSERT_TRUE(model);
    EXPECT_EQ(store().models().summary(*model)->name, "Modell " + text);
    EXPECT_EQ(store().models().summary(*model)->ownerName, text);
    EXPECT_EQ(store().models().hmf(*model), "<hmf name=\"" + text + "\"/>");
    ASSERT_TRUE(store().models().update(*model, text + " ✓", std::nullopt));
    EXPECT_EQ(store().models().list().at(0).name, text + " ✓");

    JobRequest request = jobRequest(user->id);
    request.hmf = "<hmf>" + text + "</hmf>";
    request.parameters = {{"Ventil·Δp", text}};
    const std::int64_t job = store().jobs().create(request, resolvedSettings());
    ASSERT_TRUE(store().jobs().finish(job, JobState::Failed, "Fehler im " + text, 0, nullptr));
    EXPECT_EQ(store().jobs().info(job)->error, "Fehler im " + text);
    EXPECT_EQ(store().jobs().request(job)->hmf, request.hmf);
    EXPECT_EQ(store().jobs().request(job)->parameters, request.parameters);

    store().meta().set(text, text + text);
    EXPECT_EQ(store().meta().get(text), text + text);
    store().sessions().insert(text, user->id, 1000, 100);
    EXPECT_EQ(store().sessions().userOf(text, 100), user->id);
}

TEST_P(StorageConformance, FinishThatFailsWritingTheResultLeavesTheJobAsItWas)
{
    const std::int64_t id = addJob(1);
    ASSERT_TRUE(store().jobs().markRunning(id));
    store().jobs().setProgress(id, 0.5);
    const JobInfo before = *store().jobs().info(id);
    // Both triggers fail the write as a constraint would (SQLite's RAISE(ABORT) is
    // SQLITE_CONSTRAINT_TRIGGER; PostgreSQL's class 23 is integrity constraint violation).
    if (GetParam() == Backend::SQLite) {
        db->exec("CREATE TRIGGER fail_results BEFORE INSERT ON job_results"
                 " BEGIN SELECT RAISE(ABORT, 'injected'); END");
    } else {
        db->exec("CREATE FUNCTION fail_results() RETURNS trigger LANGUAGE plpgsql AS $$"
                 " BEGIN RAISE EXCEPTION 'injected' USING ERRCODE = 'integrity_constraint_violation'; END $$;"
                 "CREATE TRIGGER fail_results BEFORE INSERT ON job_results"
                 " FOR EACH ROW EXECUTE FUNCTION fail_results()");
    }
    const std::string blob = "result";
    EXPECT_EQ(storeErrorOf([&] { store().jobs().finish(id, JobState::Done, "", 2000, &blob); }), StoreErrc::Constraint);
    const JobInfo after = *store().jobs().info(id);
    EXPECT_EQ(after.state, JobState::Running);
    EXPECT_EQ(after.progress, 0.5);
    EXPECT_EQ(after.error, "");
    EXPECT_EQ(after.steps, before.steps);
    EXPECT_EQ(after.finishedAt, 0);
    EXPECT_FALSE(store().results().has(id));
    EXPECT_EQ(store().jobs().listInState(JobState::Running).size(), 1u);

    // The store goes on working: without the trigger the same call succeeds.
    db->exec("DROP TRIGGER fail_results" + std::string(GetParam() == Backend::SQLite ? "" : " ON job_results"));
    EXPECT_TRUE(store().jobs().finish(id, JobState::Done, "", 2000, &blob));
    EXPECT_EQ(store().results().blob(id), blob);
}

} // namespace
} // namespace tlmhub::test
