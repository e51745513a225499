#include "TemporaryDirectory.h"
#include "TemporarySqliteStorage.h"
#include "server/protocol/EmbeddedProtocol.h"
#include "server/store/StoreError.h"
#include "server/store/sqlite/SqliteConnection.h"

#include <SQLiteCpp/Statement.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <thread>

using namespace tlmhub::server;

TEST(SqliteStorage, OpensFileInWalModeAtTheCurrentSchemaVersion)
{
    tlmhub::test::TemporarySqliteStorage storage;
    SQLite::Statement q(storage.raw(), "PRAGMA journal_mode");
    ASSERT_TRUE(q.executeStep());
    EXPECT_EQ(q.getColumn(0).getString(), "wal");
    EXPECT_EQ(storage->schemaVersion(), kSchemaVersion);
}

// Each writer holds the write lock only for its statement or transaction; the others wait for
// it (busy timeout, IMMEDIATE transactions) instead of failing.
TEST(SqliteStorage, ConcurrentWritersNeverSeeBusy)
{
    tlmhub::test::TemporarySqliteStorage storage;
    constexpr int kThreads = 8, kJobsEach = 40;
    std::atomic<int> failures{0};
    std::vector<std::thread> writers;
    for (int t = 0; t < kThreads; ++t)
        writers.emplace_back([&, t] {
            const std::string blob(64 * 1024, static_cast<char>('a' + t));
            for (int i = 0; i < kJobsEach; ++i) {
                try {
                    JobRequest request;
                    request.ownerId = t + 1;
                    const std::int64_t id = storage->jobs().create(request, JobInfo{});
                    storage->jobs().markRunning(id);
                    storage->jobs().setProgress(id, 0.5);
                    if (!storage->jobs().finish(id, JobState::Done, "", 10, &blob)) ++failures;
                    storage->meta().set("writer" + std::to_string(t), std::to_string(i));
                } catch (const StoreError& e) {
                    ADD_FAILURE() << storeErrcName(e.code()) << ": " << e.what();
                    ++failures;
                }
            }
        });
    for (auto& w : writers) w.join();
    EXPECT_EQ(failures, 0);
    EXPECT_EQ(storage->jobs().listInState(JobState::Done).size(), std::size_t(kThreads * kJobsEach));
    for (int t = 0; t < kThreads; ++t)
        EXPECT_EQ(storage->results().storedBytes(t + 1), std::size_t(kJobsEach) * 64 * 1024);
}

// A writer that finds the database locked tries again within a millisecond, however long it
// has waited (SQLite's own handler sleeps up to 100 ms between tries), and gives up with
// SQLITE_BUSY once the busy timeout has passed since its first try.
TEST(SqliteStorage, AWriterWaitingForTheLockTriesAgainEveryMillisecondUntilTheTimeout)
{
    using std::chrono::microseconds;
    for (int attempt = 0; attempt < 20'000; ++attempt) {
        ASSERT_GT(SqliteConnection::busyRetryDelay(attempt), microseconds(0)) << attempt;
        ASSERT_LE(SqliteConnection::busyRetryDelay(attempt), microseconds(1000)) << attempt;
    }
    const auto dir = tlmhub::test::makeTemporaryDirectory("tlmhub-busy-");
    {
        SqliteConnection connection((dir / "busy.db").string(), false);
        EXPECT_EQ(SqliteConnection::retryWhileBusy(&connection, 0), 1);
        EXPECT_EQ(SqliteConnection::retryWhileBusy(&connection, 1), 1);
    }
    std::filesystem::remove_all(dir);
}

// Two connections to one file: the second's write waits while the first holds the write lock
// and goes through once it commits.
TEST(SqliteStorage, AWriteBehindAnotherConnectionsTransactionGoesThroughAfterItsCommit)
{
    const auto dir = tlmhub::test::makeTemporaryDirectory("tlmhub-busy-");
    const std::string file = (dir / "two.db").string();
    auto holder = std::make_unique<SqliteConnection>(file, false);
    auto waiter = std::make_unique<SqliteConnection>(file, false);
    holder->db().exec("CREATE TABLE t(x INTEGER)");
    holder->db().exec("BEGIN IMMEDIATE");
    holder->db().exec("INSERT INTO t VALUES (1)");
    std::atomic<bool> written{false};
    std::thread writer([&] {
        waiter->db().exec("INSERT INTO t VALUES (2)");
        written = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_FALSE(written) << "the write did not wait for the lock";
    holder->db().exec("COMMIT");
    writer.join();
    EXPECT_TRUE(written);
    EXPECT_EQ(holder->db().execAndGet("SELECT count(*) FROM t").getInt(), 2);
    holder.reset();
    waiter.reset();
    std::filesystem::remove_all(dir);
}

TEST(EmbeddedProtocol, HoldsEveryProtocolFile)
{
    std::size_t onDisk = 0;
    for (const auto& e : std::filesystem::directory_iterator(TLMHUB_SOURCE_DIR "/protocol"))
        if (e.path().extension() == ".json") ++onDisk;
    EXPECT_EQ(embeddedProtocolFiles().size(), onDisk);
    EXPECT_GT(onDisk, 0u);
}
