#pragma once
// The store conformance suite (issue 16): every test runs against both back ends on a fresh
// database without data. SQLite gets a new file in a new temporary directory; PostgreSQL a
// new database on the one TemporaryPostgres server of this process (started by the first test
// that needs it, stopped when the tests end), copied from one with the current schema. A
// PostgreSQL that cannot be started fails the test.
#include "server/store/Storage.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace tlmhub::test {

enum class Backend { SQLite, PostgreSQL };

// "SQLite" / "PostgreSQL": the last part of every test name, which ctest's two filters match.
std::string backendName(const ::testing::TestParamInfo<Backend>& info);
// So a failure says "GetParam() = PostgreSQL" rather than showing the enum's bytes.
void PrintTo(Backend backend, std::ostream* out);

class FreshDatabase {
public:
    explicit FreshDatabase(Backend backend);
    ~FreshDatabase();
    FreshDatabase(const FreshDatabase&) = delete;
    FreshDatabase& operator=(const FreshDatabase&) = delete;

    Backend backend() const { return mBackend; }
    // What StorageConfig::database is set to: the SQLite file or the postgresql:// URI.
    const std::string& database() const { return mDatabase; }
    // A temporary directory of this test's own (removed afterwards).
    const std::filesystem::path& directory() const { return mDir; }

    std::unique_ptr<server::Storage> open(unsigned maxConnections = 16) const;
    // Runs `sql` on a connection of the test's own, past the store (to inject faults).
    void exec(const std::string& sql) const;

private:
    Backend mBackend;
    std::filesystem::path mDir;
    std::string mDatabase;
    std::string mPostgresName;   // PostgreSQL: the database made for this test
};

// A request of `ownerId` and the settings it resolved to, as the job queue gives them.
server::JobRequest jobRequest(std::int64_t ownerId);
server::JobInfo resolvedSettings();

// Runs work(0) .. work(threads - 1) on as many threads, released together: each spins until
// all are up (a latch's wake-ups are spread too far apart for two short calls to overlap).
// An exception a thread throws fails the test.
void runAtOnce(int threads, const std::function<void(int)>& work);

// Returns once unixNow() has moved on to the next second, so a timestamp the store writes
// afterwards is later than one it wrote before (timestamps are whole seconds).
void waitForNextSecond();

// The fixture of every conformance test: `storage` is open on a fresh database.
class StoreTest : public ::testing::TestWithParam<Backend> {
protected:
    void SetUp() override;
    void TearDown() override;

    server::Storage& store() { return *storage; }
    // A new account (hash "hash of <name>"); throws, ending the test, if it cannot be made.
    server::User addUser(const std::string& name, const std::string& role = server::kRoleUser);
    // A new queued job of `ownerId` with plain settings.
    std::int64_t addJob(std::int64_t ownerId);
    // A new job run and finished done with `resultBlob` (none when null); fails the test if
    // the store refuses a step.
    std::int64_t addFinishedJob(std::int64_t ownerId, const std::string* resultBlob);

    std::unique_ptr<FreshDatabase> db;
    std::unique_ptr<server::Storage> storage;
};

// Instantiates a conformance suite (a subclass of StoreTest) for both back ends.
#define TLMHUB_STORE_CONFORMANCE(Suite)                                                            \
    INSTANTIATE_TEST_SUITE_P(Backends, Suite,                                                      \
                             ::testing::Values(::tlmhub::test::Backend::SQLite,                    \
                                               ::tlmhub::test::Backend::PostgreSQL),               \
                             ::tlmhub::test::backendName)

} // namespace tlmhub::test
