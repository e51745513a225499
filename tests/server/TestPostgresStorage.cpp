// What only the PostgreSQL back end has to get right (issue 16): servers migrating one database
// at the same time, bytea round trips, connections the server ended, an unreachable server, and
// races that SQLite's single writer rules out. The behaviour both back ends share is tested by
// the store conformance suite.
#include "TemporaryPostgres.h"

#include "server/store/Storage.h"
#include "server/store/StoreError.h"
#include "server/store/postgres/PostgresConnection.h"
#include "server/store/postgres/PostgresDatabase.h"

#include <gtest/gtest.h>
#include <pqxx/pqxx>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace tlmhub::test {
namespace {

using server::JobInfo;
using server::JobRequest;
using server::JobState;
using server::Storage;
using server::StoreErrc;
using server::StoreError;

std::unique_ptr<Storage> open(const std::string& uri, unsigned maxConnections = 4)
{
    server::StorageConfig config;
    config.database = uri;
    config.maxConnections = maxConnections;
    return server::openStorage(config);
}

std::int64_t newJob(Storage& storage, std::int64_t ownerId)
{
    JobRequest request;
    request.ownerId = ownerId;
    request.hmf = "<hopsanmodelfile/>";
    JobInfo resolved;
    resolved.steps = 10;
    resolved.start = 0.0;
    resolved.step = 0.1;
    resolved.stop = 1.0;
    resolved.logSamples = 10;
    return storage.jobs().create(request, resolved);
}

// A loopback port nobody listens on (bound for a moment by the kernel's choice, then freed).
unsigned short unusedPort()
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    EXPECT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    EXPECT_EQ(::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length), 0);
    ::close(fd);
    return ntohs(address.sin_port);
}

TEST(PostgresStorage, TwoServersStartingTogetherApplyEachMigrationOnce)
{
    TemporaryPostgres pg;
    std::unique_ptr<Storage> first, second;
    std::atomic<int> ready{0};
    std::string failures;
    std::mutex failuresMutex;
    auto start = [&](std::unique_ptr<Storage>& storage) {
        ++ready;
        while (ready < 2) std::this_thread::yield();   // both connect at the same moment
        try {
            storage = open(pg.uri());
        } catch (const std::exception& e) {
            std::lock_guard lock(failuresMutex);
            failures += e.what();
        }
    };
    std::thread a(start, std::ref(first)), b(start, std::ref(second));
    a.join();
    b.join();
    ASSERT_EQ(failures, "");
    ASSERT_TRUE(first && second);
    EXPECT_EQ(first->schemaVersion(), server::kSchemaVersion);
    EXPECT_EQ(second->schemaVersion(), server::kSchemaVersion);
    EXPECT_EQ(first->describe(), "PostgreSQL tlmhub@127.0.0.1:" + std::to_string(pg.port()) + "/tlmhub_test");

    // Opening again (a restart) applies nothing new.
    EXPECT_EQ(open(pg.uri())->schemaVersion(), server::kSchemaVersion);
    pqxx::connection check(pg.uri());
    pqxx::nontransaction tx(check);
    const pqxx::row applied = tx.exec1("SELECT COUNT(*), MIN(version), MAX(version) FROM schema_migrations");
    EXPECT_EQ(applied[0].as<int>(), server::kSchemaVersion);
    EXPECT_EQ(applied[1].as<int>(), 1);
    EXPECT_EQ(applied[2].as<int>(), server::kSchemaVersion);

    // Both work on the one database.
    const auto alice = first->users().insert("alice", "hash", "admin");
    ASSERT_TRUE(alice);
    EXPECT_EQ(second->users().findByName("alice")->id, alice->id);
}

TEST(PostgresStorage, RefusesADatabaseANewerServerMigrated)
{
    TemporaryPostgres pg;
    open(pg.uri());
    {
        pqxx::connection admin(pg.uri());
        pqxx::work tx(admin);
        tx.exec_params0("INSERT INTO schema_migrations(version, applied_at) VALUES($1, 0)",
                        server::kSchemaVersion + 1);
        tx.commit();
    }
    try {
        open(pg.uri());
        FAIL() << "opened a database at a newer schema version";
    } catch (const StoreError& e) {
        EXPECT_EQ(e.code(), StoreErrc::Corrupt) << e.what();
    }
}

TEST(PostgresStorage, ResultBlobsRoundTripByteForByte)
{
    TemporaryPostgres pg;
    auto storage = open(pg.uri());
    const auto owner = storage->users().insert("owner", "hash", "user");
    ASSERT_TRUE(owner);

    std::string everyByte(256, '\0');
    for (int i = 0; i < 256; ++i) everyByte[static_cast<std::size_t>(i)] = static_cast<char>(i);
    // 5 MB of every byte value in an irregular order, with runs of backslashes and NULs at the
    // ends (what bytea in text form, escaped wrongly, would mangle or cut off).
    std::string large(5 * 1024 * 1024, '\0');
    for (std::size_t i = 0; i < large.size(); ++i) large[i] = static_cast<char>((i * 2654435761u) >> 7);
    large.replace(0, 1000, 1000, '\\');
    large.replace(large.size() - 1000, 1000, 1000, '\0');

    const std::int64_t small = newJob(*storage, owner->id), big = newJob(*storage, owner->id);
    ASSERT_TRUE(storage->jobs().finish(small, JobState::Done, "", 10, &everyByte));
    ASSERT_TRUE(storage->jobs().finish(big, JobState::Done, "", 10, &large));

    const auto smallBack = storage->results().blob(small);
    ASSERT_TRUE(smallBack);
    EXPECT_EQ(*smallBack, everyByte);
    const auto bigBack = storage->results().blob(big);
    ASSERT_TRUE(bigBack);
    EXPECT_EQ(bigBack->size(), large.size());
    EXPECT_TRUE(*bigBack == large) << "the 5 MB blob read back differs";
    EXPECT_EQ(storage->results().storedBytes(owner->id), everyByte.size() + large.size());
    EXPECT_EQ(storage->jobs().info(big)->state, JobState::Done);
}

TEST(PostgresStorage, RealsAndNullsRoundTripExactly)
{
    TemporaryPostgres pg;
    auto storage = open(pg.uri());
    const auto owner = storage->users().insert("owner", "hash", "user");
    ASSERT_TRUE(owner);
    JobRequest request;
    request.ownerId = owner->id;
    request.modelId = 42;
    JobInfo resolved;
    resolved.start = 1.0 / 3.0;
    resolved.step = 1e-7 / 3.0;
    resolved.stop = 123.456789012345678;
    resolved.logSamples = 7;
    const auto withModel = storage->jobs().info(storage->jobs().create(request, resolved));
    ASSERT_TRUE(withModel);
    EXPECT_EQ(withModel->modelId, std::optional<std::int64_t>(42));
    EXPECT_EQ(withModel->start, resolved.start);   // bit for bit, not just close
    EXPECT_EQ(withModel->step, resolved.step);
    EXPECT_EQ(withModel->stop, resolved.stop);
    request.modelId.reset();
    EXPECT_EQ(storage->jobs().info(storage->jobs().create(request, resolved))->modelId, std::nullopt);

    // An absent field is a NULL parameter: the stored value stays.
    const auto model = storage->models().create(owner->id, "first", "<hmf/>", false);
    ASSERT_TRUE(model);
    ASSERT_TRUE(storage->models().update(*model, std::string("renamed"), std::nullopt));
    EXPECT_EQ(storage->models().hmf(*model), std::optional<std::string>("<hmf/>"));
    EXPECT_EQ(storage->models().summary(*model)->name, "renamed");
}

// Client connections to the test database other than `admin`'s own (an autovacuum worker may
// be at work on the database too).
constexpr const char* kOtherClients = "SELECT COUNT(*) FROM pg_stat_activity WHERE pid <> pg_backend_pid()"
                                      " AND datname = current_database() AND backend_type = 'client backend'";

// Ends every other client connection to the database, as an administrator or a restarting
// server would, and returns how many once they are gone (pg_terminate_backend only signals).
int endOtherClients(pqxx::connection& admin)
{
    pqxx::nontransaction tx(admin);
    const int ended = tx.exec1("SELECT COUNT(pg_terminate_backend(pid)) FROM pg_stat_activity"
                               " WHERE pid <> pg_backend_pid() AND datname = current_database()"
                               " AND backend_type = 'client backend'")[0]
                          .as<int>();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (tx.exec1(kOtherClients)[0].as<int>() > 0) {
        if (std::chrono::steady_clock::now() > deadline) throw std::runtime_error("backends not ended in 10 s");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return ended;
}

TEST(PostgresStorage, ReplacesConnectionsTheServerEnded)
{
    TemporaryPostgres pg;
    auto storage = open(pg.uri(), 4);
    ASSERT_TRUE(storage->users().insert("admin", "hash", "admin"));
    pqxx::connection admin(pg.uri());
    // Several threads at once until the pool holds more than one connection, so the call
    // after the ending meets a dead connection again if it is retried on a pooled one.
    for (int round = 0; round < 50 && pqxx::nontransaction(admin).exec1(kOtherClients)[0].as<int>() < 2; ++round) {
        std::vector<std::thread> threads;
        for (int t = 0; t < 4; ++t)
            threads.emplace_back([&] {
                for (int i = 0; i < 20; ++i) storage->users().count();
            });
        for (auto& t : threads) t.join();
    }
    ASSERT_GE(endOtherClients(admin), 2);

    // A read runs again on a fresh connection; the connections opened before are not reused,
    // so a write after it finds a working one too.
    EXPECT_EQ(storage->users().count(), 1u);
    EXPECT_TRUE(storage->users().insert("second", "hash", "user"));
    EXPECT_EQ(storage->users().list().size(), 2u);
}

TEST(PostgresStorage, ATransactionOnAnEndedConnectionStartsAgain)
{
    TemporaryPostgres pg;
    auto storage = open(pg.uri(), 2);
    const auto user = storage->users().insert("user", "hash", "user");
    ASSERT_TRUE(user);
    pqxx::connection admin(pg.uri());
    ASSERT_EQ(endOtherClients(admin), 1);
    // A login (a write, in a transaction) as the first call after the server ended the
    // connection: nothing reached the server before the connection was found dead, so it runs
    // again on a fresh one instead of failing.
    storage->sessions().insert("token", user->id, 2'000'000'000, 1'000'000'000);
    EXPECT_EQ(storage->sessions().userOf("token", 1'000'000'000), user->id);
}

TEST(PostgresStorage, FailuresBecomeStoreErrorCodes)
{
    auto code = [](const std::exception& e) { return server::toStoreError(e).code(); };
    EXPECT_EQ(code(pqxx::broken_connection("gone")), StoreErrc::Unavailable);
    EXPECT_EQ(code(pqxx::in_doubt_error("commit unknown")), StoreErrc::Unavailable);
    EXPECT_EQ(code(pqxx::serialization_failure("40001")), StoreErrc::Busy);
    EXPECT_EQ(code(pqxx::deadlock_detected("40P01")), StoreErrc::Busy);
    EXPECT_EQ(code(pqxx::sql_error("unique", "INSERT", "23505")), StoreErrc::Constraint);
    EXPECT_EQ(code(pqxx::sql_error("foreign key", "INSERT", "23503")), StoreErrc::Constraint);
    EXPECT_EQ(code(pqxx::sql_error("disk full", "INSERT", "53100")), StoreErrc::DiskFull);
    EXPECT_EQ(code(pqxx::sql_error("out of memory", "SELECT", "53200")), StoreErrc::DiskFull);
    EXPECT_EQ(code(pqxx::sql_error("serialization", "UPDATE", "40001")), StoreErrc::Busy);
    EXPECT_EQ(code(pqxx::sql_error("data corrupted", "SELECT", "XX001")), StoreErrc::Corrupt);
    EXPECT_EQ(code(pqxx::sql_error("index corrupted", "SELECT", "XX002")), StoreErrc::Corrupt);
    EXPECT_EQ(code(pqxx::sql_error("no such table", "SELECT", "42P01")), StoreErrc::Internal);
    EXPECT_EQ(code(std::runtime_error("other")), StoreErrc::Internal);

    // Through the stores, on a real server.
    TemporaryPostgres pg;
    auto storage = open(pg.uri());
    try {
        storage->sessions().insert("token", 12345, 100, 0);   // no such user
        FAIL() << "a session of a user that does not exist was stored";
    } catch (const StoreError& e) {
        EXPECT_EQ(e.code(), StoreErrc::Constraint) << e.what();
    }
    EXPECT_EQ(storage->models().create(12345, "orphan", "<hmf/>", false), std::nullopt);
    try {
        storage->backup("/tmp/never-written");
        FAIL() << "backup() of a PostgreSQL database did something";
    } catch (const StoreError& e) {
        EXPECT_NE(std::string(e.what()).find("pg_dump"), std::string::npos) << e.what();
    }
}

TEST(PostgresStorage, DescribesTheServerWithoutThePassword)
{
    EXPECT_EQ(server::postgresEndpoint("postgresql://tlmhub:secret@db.example:5433/lab?sslmode=require"),
              "tlmhub@db.example:5433/lab");
    EXPECT_EQ(server::postgresEndpoint("postgres://db.example/lab"), "db.example:5432/lab");
    EXPECT_EQ(server::postgresEndpoint("postgresql://tlmhub@[::1]:6000/lab"), "tlmhub@[::1]:6000/lab");
    EXPECT_EQ(server::postgresEndpoint("postgresql://tlmhub@[::1]/lab"), "tlmhub@[::1]:5432/lab");
    // libpq's defaults: the local server, and a database named as the user.
    EXPECT_EQ(server::postgresEndpoint("postgresql://tlmhub@"), "tlmhub@localhost:5432/tlmhub");
}

TEST(PostgresStorage, UnreachableServerIsUnavailableAtOnce)
{
    const unsigned short port = unusedPort();
    const auto started = std::chrono::steady_clock::now();
    try {
        open("postgresql://tlmhub:secret@127.0.0.1:" + std::to_string(port) + "/tlmhub");
        FAIL() << "opened a server that does not exist";
    } catch (const StoreError& e) {
        EXPECT_EQ(e.code(), StoreErrc::Unavailable) << e.what();
        const std::string message = e.what();
        EXPECT_NE(message.find("127.0.0.1:" + std::to_string(port)), std::string::npos) << message;
        EXPECT_EQ(message.find("secret"), std::string::npos) << message;
    }
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
}

TEST(PostgresStorage, ConcurrentInsertsOfOneNameMakeOneAccount)
{
    TemporaryPostgres pg;
    auto storage = open(pg.uri(), 8);
    // The same name several times as typed, and in other cases.
    const std::vector<std::string> spellings{"carol", "carol", "Carol", "CAROL",
                                             "carol", "cArOl", "CAROL", "carol"};
    std::atomic<int> made{0}, failed{0}, ready{0};
    std::vector<std::thread> threads;
    for (const std::string& name : spellings)
        threads.emplace_back([&, name] {
            ++ready;
            while (ready < static_cast<int>(spellings.size())) std::this_thread::yield();
            try {
                if (storage->users().insert(name, "hash", "user")) ++made;
            } catch (const StoreError&) {   // a taken name must come back as nullopt
                ++failed;
            }
        });
    for (auto& t : threads) t.join();
    EXPECT_EQ(failed, 0);
    EXPECT_EQ(made, 1);
    EXPECT_EQ(storage->users().count(), 1u);
}

TEST(PostgresStorage, ConcurrentDemotionsLeaveAnAdministrator)
{
    TemporaryPostgres pg;
    auto storage = open(pg.uri(), 8);
    // Each round: two administrators, each demoted by its own thread at once. Without the
    // lock both would see the other still an administrator and both changes would pass.
    for (int round = 0; round < 20; ++round) {
        const auto a = storage->users().insert("a" + std::to_string(round), "hash", "admin");
        const auto b = storage->users().insert("b" + std::to_string(round), "hash", "admin");
        ASSERT_TRUE(a && b);
        for (const auto& u : storage->users().list()) {
            if (u.id == a->id || u.id == b->id || u.role != "admin") continue;
            server::User ignored;
            ASSERT_EQ(storage->users().change(u.id, {.role = "user", .disabled = {}}, ignored),
                      server::UserChangeOutcome::Changed);
        }
        std::atomic<int> ready{0};
        server::UserChangeOutcome outcomeA{}, outcomeB{};
        auto demote = [&](std::int64_t id, server::UserChangeOutcome& outcome) {
            ++ready;
            while (ready < 2) std::this_thread::yield();
            server::User updated;
            try {
                outcome = storage->users().change(id, {.role = "user", .disabled = {}}, updated);
            } catch (const StoreError& e) {
                ADD_FAILURE() << e.what();
            }
        };
        std::thread ta(demote, a->id, std::ref(outcomeA)), tb(demote, b->id, std::ref(outcomeB));
        ta.join();
        tb.join();
        using server::UserChangeOutcome;
        EXPECT_EQ((outcomeA == UserChangeOutcome::Changed) + (outcomeB == UserChangeOutcome::Changed), 1)
            << "round " << round;
        int admins = 0;
        for (const auto& u : storage->users().list()) admins += u.role == "admin" && !u.disabled;
        ASSERT_EQ(admins, 1) << "round " << round;
    }
}

} // namespace
} // namespace tlmhub::test
