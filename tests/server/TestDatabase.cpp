#include "TemporarySqliteStorage.h"
#include "server/protocol/EmbeddedProtocol.h"
#include "server/store/StoreError.h"

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

TEST(EmbeddedProtocol, HoldsEveryProtocolFile)
{
    std::size_t onDisk = 0;
    for (const auto& e : std::filesystem::directory_iterator(TLMHUB_SOURCE_DIR "/protocol"))
        if (e.path().extension() == ".json") ++onDisk;
    EXPECT_EQ(embeddedProtocolFiles().size(), onDisk);
    EXPECT_GT(onDisk, 0u);
}
