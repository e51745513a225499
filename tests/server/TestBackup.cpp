// Backing up and restoring the SQLite database: `tlmhub-server --backup/--restore` on a real
// server's data directory, and SqliteStorage::backup / restoreSqliteBackup in process.
#include "ServerHarness.h"

#include "server/store/Storage.h"
#include "server/store/sqlite/SqliteStorage.h"

#include <SQLiteCpp/Database.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <sys/wait.h>
#include <thread>

using namespace tlmhub::server;
using namespace tlmhub::test;
namespace http = boost::beast::http;
namespace fs = std::filesystem;

namespace {

const fs::path kExample = fs::path(TLMHUB_SOURCE_DIR) / "examples/pressure-build-up.hmf";

struct CommandResult {
    int exitCode = -1;
    std::string output;   // stdout and stderr
};

// Runs tlmhub-server with `args` (each quoted) and waits for it.
CommandResult runServerCommand(const std::vector<std::string>& args)
{
    std::string command = std::string("'") + TLMHUB_SERVER_BIN + "'";
    for (const auto& a : args) command += " '" + a + "'";
    command += " 2>&1";
    CommandResult r;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.output.append(buf, n);
    const int status = ::pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// A database at `file` with one user, `username`.
void makeDatabase(const fs::path& file, const std::string& username)
{
    const auto storage = openStorage({.database = file.string()});
    ASSERT_TRUE(storage->users().insert(username, "not-a-hash", "user"));
}

} // namespace

TEST(Backup, WhileTheServerRunsAndRestoredIntoAFreshDataDirectory)
{
    const fs::path dir = freshTempDir("backup-live");
    const fs::path backupFile = dir / "tlmhub.backup";
    std::int64_t model = 0, job = 0;
    std::string hmf, csv;
    {
        ServerProcess server(dir / "data");
        createTestUsers(server, {"alice"});
        HttpClient alice = loggedInAs(server, "alice");
        auto r = alice.request(http::verb::post, "/api/v1/models?name=pressure", readFile(kExample), "application/xml");
        ASSERT_EQ(r.status, 201) << r.body;
        model = r.json()["id"].get<std::int64_t>();
        r = alice.post("/api/v1/jobs", {{"model_id", model}, {"stop", 0.5}, {"log_samples", 51}});
        ASSERT_EQ(r.status, 201) << r.body;
        job = r.json()["id"].get<std::int64_t>();
        ASSERT_EQ(waitForJobEnd(alice, job)["state"], "done");
        hmf = alice.get("/api/v1/models/" + std::to_string(model) + "?format=hmf").body;
        csv = alice.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=csv").body;
        ASSERT_FALSE(csv.empty());

        // The server keeps running (and holds the database) while the backup is written.
        const auto backup = runServerCommand({"--data-dir", (dir / "data").string(), "--backup", backupFile.string()});
        EXPECT_EQ(backup.exitCode, 0) << backup.output;
        EXPECT_NE(backup.output.find("backup of SQLite " + (dir / "data" / "tlmhub.sqlite").string() +
                                     " written to " + backupFile.string() + " ("),
                  std::string::npos) << backup.output;
        EXPECT_NE(backup.output.find("schema version " + std::to_string(kSchemaVersion) + ")"), std::string::npos)
            << backup.output;
        EXPECT_EQ(alice.get("/api/v1/jobs/" + std::to_string(job)).status, 200);
        server.terminate();
    }

    const fs::path restored = dir / "restored";
    const auto restore = runServerCommand({"--data-dir", restored.string(), "--restore", backupFile.string()});
    ASSERT_EQ(restore.exitCode, 0) << restore.output;
    EXPECT_NE(restore.output.find("restored " + backupFile.string()), std::string::npos) << restore.output;

    ServerProcess server(restored);
    HttpClient alice = loggedInAs(server, "alice");
    EXPECT_EQ(alice.get("/api/v1/models/" + std::to_string(model) + "?format=hmf").body, hmf);
    const auto info = alice.get("/api/v1/jobs/" + std::to_string(job)).json();
    EXPECT_EQ(info["state"], "done") << info.dump();
    EXPECT_EQ(alice.get("/api/v1/jobs/" + std::to_string(job) + "/results?format=csv").body, csv);
    // The examples were seeded once, before the backup: not again.
    EXPECT_EQ(server.output().find("examples: added"), std::string::npos) << server.output();
    server.terminate();
    fs::remove_all(dir);
}

TEST(Backup, IsAConsistentSnapshotWhileAnotherThreadWrites)
{
    const fs::path dir = freshTempDir("backup-concurrent");
    const auto storage = openStorage({.database = (dir / "tlmhub.sqlite").string()});
    const auto owner = storage->users().insert("writer", "not-a-hash", "user");
    ASSERT_TRUE(owner);
    const std::string hmf(32 * 1024, 'x');
    for (int i = 0; i < 300; ++i) ASSERT_TRUE(storage->models().create(owner->id, "seed", hmf, false));

    std::atomic<bool> stop{false};
    std::atomic<int> written{0};
    std::thread writer([&] {
        while (!stop) {
            storage->models().create(owner->id, "model " + std::to_string(written), hmf, false);
            ++written;
        }
    });
    while (written < 10) std::this_thread::yield();
    const std::size_t before = storage->models().list().size();
    const fs::path snapshot = dir / "snapshot.sqlite";
    storage->backup(snapshot);
    const std::size_t after = storage->models().list().size();
    stop = true;
    writer.join();

    {
        SQLite::Database db(snapshot.string(), SQLite::OPEN_READONLY);
        EXPECT_EQ(db.execAndGet("PRAGMA integrity_check").getString(), "ok");
    }
    const auto copy = openStorage({.database = snapshot.string()});
    EXPECT_EQ(copy->schemaVersion(), kSchemaVersion);
    const std::size_t inSnapshot = copy->models().list().size();
    EXPECT_LE(before, inSnapshot);
    EXPECT_LE(inSnapshot, after);
    EXPECT_EQ(copy->models().hmf(copy->models().list().back().id), std::optional<std::string>(hmf));
    fs::remove_all(dir);
}

TEST(Backup, RestoreRefusesWhatIsNotATlmhubDatabaseAndADatabaseInUse)
{
    const fs::path dir = freshTempDir("restore-refuses");
    const fs::path database = dir / "tlmhub.sqlite";
    makeDatabase(database, "current");
    const std::string original = readFile(database);

    const auto refused = [&](const fs::path& backup, StoreErrc code, const std::string& why) {
        try {
            restoreSqliteBackup(backup, database);
            ADD_FAILURE() << backup << " was restored";
        } catch (const StoreError& e) {
            EXPECT_EQ(e.code(), code) << e.what();
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
        }
        EXPECT_TRUE(readFile(database) == original) << "the database changed";
        EXPECT_FALSE(fs::exists(database.string() + ".before-restore"));
        EXPECT_FALSE(fs::exists(database.string() + ".restoring"));
    };

    const fs::path text = dir / "notes.txt";
    std::ofstream(text) << "not a database\n";
    refused(text, StoreErrc::Corrupt, "'" + text.string() + "' is not an SQLite database");
    refused(dir / "missing.backup", StoreErrc::Unavailable, "cannot read the backup '" + (dir / "missing.backup").string());

    const fs::path other = dir / "other.sqlite";
    {
        SQLite::Database db(other.string(), SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
        db.exec("CREATE TABLE users (id INTEGER PRIMARY KEY, name TEXT)");
    }
    refused(other, StoreErrc::Corrupt, "'" + other.string() + "' is an SQLite database but not a tlmhub one");

    const fs::path newer = dir / "newer.backup";
    makeDatabase(dir / "newer.sqlite", "future");
    {
        SQLite::Database db((dir / "newer.sqlite").string(), SQLite::OPEN_READWRITE);
        db.exec("INSERT INTO schema_migrations(version, applied_at) VALUES(" + std::to_string(kSchemaVersion + 1) + ", 0)");
    }
    fs::copy_file(dir / "newer.sqlite", newer);
    refused(newer, StoreErrc::Corrupt, "is at schema version " + std::to_string(kSchemaVersion + 1));

    // A valid backup, while a storage (as a running server would) holds the database open.
    const fs::path good = dir / "good.backup";
    makeDatabase(dir / "good.sqlite", "restored");
    openStorage({.database = (dir / "good.sqlite").string()})->backup(good);
    {
        const auto running = openStorage({.database = database.string()});
        refused(good, StoreErrc::Busy, "is in use");
        EXPECT_TRUE(running->users().findByName("current"));
    }
    fs::remove_all(dir);
}

TEST(Backup, RestoreReplacesTheDatabaseAndKeepsTheOldOne)
{
    const fs::path dir = freshTempDir("restore");
    const fs::path database = dir / "tlmhub.sqlite";
    makeDatabase(database, "old");
    makeDatabase(dir / "source.sqlite", "new");
    openStorage({.database = (dir / "source.sqlite").string()})->backup(dir / "new.backup");
    const std::string backupBytes = readFile(dir / "new.backup");
    // A -wal left beside the old file (e.g. copied in by hand) must not meet the new one.
    std::ofstream(database.string() + "-wal") << "stale";

    restoreSqliteBackup(dir / "new.backup", database);
    EXPECT_TRUE(readFile(dir / "new.backup") == backupBytes) << "the backup changed";
    EXPECT_FALSE(fs::exists(database.string() + "-wal"));
    {
        const auto restored = openStorage({.database = database.string()});
        EXPECT_TRUE(restored->users().findByName("new"));
        EXPECT_FALSE(restored->users().findByName("old"));
        const auto kept = openStorage({.database = database.string() + ".before-restore"});
        EXPECT_TRUE(kept->users().findByName("old"));
    }
    // A second restore would overwrite what the first kept: refused.
    EXPECT_THROW(restoreSqliteBackup(dir / "new.backup", database), StoreError);

    // A database SQLite cannot read is no server's: it is replaced (and kept) too.
    const fs::path damagedDir = dir / "damaged";
    fs::create_directories(damagedDir);
    std::ofstream(damagedDir / "tlmhub.sqlite") << std::string(8192, 'x');
    restoreSqliteBackup(dir / "new.backup", damagedDir / "tlmhub.sqlite");
    EXPECT_TRUE(openStorage({.database = (damagedDir / "tlmhub.sqlite").string()})->users().findByName("new"));
    EXPECT_EQ(readFile(damagedDir / "tlmhub.sqlite.before-restore"), std::string(8192, 'x'));
    fs::remove_all(dir);
}

TEST(Backup, CommandRefusesAnExistingTargetAndPointsPostgresToPgDump)
{
    const fs::path dir = freshTempDir("backup-cli");
    makeDatabase(dir / "tlmhub.sqlite", "someone");
    const fs::path target = dir / "existing.backup";
    std::ofstream(target) << "keep me";

    auto r = runServerCommand({"--data-dir", dir.string(), "--backup", target.string()});
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("'" + target.string() + "' already exists"), std::string::npos) << r.output;
    EXPECT_EQ(readFile(target), "keep me");

    r = runServerCommand({"--data-dir", (dir / "nothing-here").string(), "--backup", (dir / "a.backup").string()});
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("there is no database"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "nothing-here"));

    r = runServerCommand({"--database", "postgresql://tlmhub@127.0.0.1:1/tlmhub", "--backup", (dir / "b").string()});
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("pg_dump"), std::string::npos) << r.output;
    r = runServerCommand({"--database", "postgres://tlmhub@127.0.0.1:1/tlmhub", "--restore", target.string()});
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("pg_restore"), std::string::npos) << r.output;

    r = runServerCommand({"--database", (dir / "tlmhub.sqlite").string()});
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("SQLite is chosen with --data-dir"), std::string::npos) << r.output;
    fs::remove_all(dir);
}
