#include "StoreBackends.h"

#include "../TemporaryDirectory.h"
#include "../TemporaryPostgres.h"

#include "server/store/UnixTime.h"

#include <SQLiteCpp/Database.h>
#include <pqxx/pqxx>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace tlmhub::test {
namespace {

// One server per process: starting one takes seconds, a database on it milliseconds. A start
// that failed is not tried again for every test; each test fails with its message instead.
std::mutex gPostgresMutex;
std::unique_ptr<TemporaryPostgres> gPostgres;
std::string gPostgresFailure;
int gDatabasesMade = 0;
bool gTemplateMigrated = false;
constexpr const char* kMigratedTemplate = "migrated_template";

TemporaryPostgres& postgres()
{
    if (!gPostgresFailure.empty()) throw std::runtime_error(gPostgresFailure);
    if (!gPostgres) {
        try {
            gPostgres = std::make_unique<TemporaryPostgres>();
        } catch (const std::exception& e) {
            gPostgresFailure = std::string("PostgreSQL back end not tested: ") + e.what();
            throw;
        }
    }
    return *gPostgres;
}

// Every test's database is a copy of one the store migrated once per process: migrating a
// new database for each test took most of the suite's time (the schema upgrade itself is
// checked here by the template's own migration and by the PostgreSQL server tests). Called
// with gPostgresMutex held.
std::string migratedTemplate(TemporaryPostgres& server, pqxx::nontransaction& admin)
{
    if (!gTemplateMigrated) {
        admin.exec0(std::string("CREATE DATABASE ") + kMigratedTemplate);
        server::StorageConfig config;
        config.database = server.uri(kMigratedTemplate);
        config.maxConnections = 1;
        server::openStorage(config).reset();   // a template takes no copies while connected
        gTemplateMigrated = true;
    }
    return kMigratedTemplate;
}

class StopPostgresAtEnd : public ::testing::Environment {
public:
    void TearDown() override
    {
        std::lock_guard lock(gPostgresMutex);
        gPostgres.reset();
    }
};
[[maybe_unused]] ::testing::Environment* const gStopPostgres =
    ::testing::AddGlobalTestEnvironment(new StopPostgresAtEnd);

} // namespace

std::string backendName(const ::testing::TestParamInfo<Backend>& info)
{
    return info.param == Backend::SQLite ? "SQLite" : "PostgreSQL";
}

void PrintTo(Backend backend, std::ostream* out)
{
    *out << (backend == Backend::SQLite ? "SQLite" : "PostgreSQL");
}

server::JobRequest jobRequest(std::int64_t ownerId)
{
    server::JobRequest r;
    r.ownerId = ownerId;
    r.hmf = "<hopsanmodelfile/>";
    r.parameters = {{"Mass.m", "20"}};
    r.settings.stop = 2.0;
    return r;
}

server::JobInfo resolvedSettings()
{
    server::JobInfo settings;
    settings.start = 0.0;
    settings.step = 0.001;
    settings.stop = 2.0;
    settings.steps = 2000;
    settings.logSamples = 2048;
    return settings;
}

void runAtOnce(int threads, const std::function<void(int)>& work)
{
    std::atomic<int> ready = 0;
    std::vector<std::thread> running;
    for (int i = 0; i < threads; ++i)
        running.emplace_back([&, i] {
            ready.fetch_add(1);
            while (ready.load() < threads) std::this_thread::yield();
            try {
                work(i);
            } catch (const std::exception& e) {
                ADD_FAILURE() << "thread " << i << ": " << e.what();
            }
        });
    for (auto& t : running) t.join();
}

void waitForNextSecond()
{
    const long long before = server::unixNow();
    while (server::unixNow() == before) std::this_thread::sleep_for(std::chrono::milliseconds(20));
}

FreshDatabase::FreshDatabase(Backend backend) : mBackend(backend), mDir(makeTemporaryDirectory("tlmhub-store-"))
{
    if (backend == Backend::SQLite) {
        mDatabase = (mDir / "tlmhub.sqlite").string();
        return;
    }
    std::lock_guard lock(gPostgresMutex);
    TemporaryPostgres& server = postgres();
    mPostgresName = "t_" + std::to_string(++gDatabasesMade);
    pqxx::connection admin(server.uri("postgres") + "?connect_timeout=10");
    pqxx::nontransaction txn(admin);   // CREATE DATABASE cannot run in a transaction
    txn.exec0("CREATE DATABASE " + mPostgresName + " TEMPLATE " + migratedTemplate(server, txn) + " STRATEGY FILE_COPY");
    mDatabase = server.uri(mPostgresName);
}

FreshDatabase::~FreshDatabase()
{
    // Each database takes megabytes in the server's directory. A failure to drop one is no
    // test's business: the server and its directory go at the end anyway.
    if (!mPostgresName.empty()) {
        try {
            std::lock_guard lock(gPostgresMutex);
            pqxx::connection admin(postgres().uri("postgres") + "?connect_timeout=10");
            pqxx::nontransaction txn(admin);
            txn.exec0("DROP DATABASE " + mPostgresName + " WITH (FORCE)");
        } catch (const std::exception&) {
        }
    }
    std::error_code ignored;
    std::filesystem::remove_all(mDir, ignored);
}

std::unique_ptr<server::Storage> FreshDatabase::open(unsigned maxConnections) const
{
    server::StorageConfig config;
    config.database = mDatabase;
    config.maxConnections = maxConnections;
    return server::openStorage(config);
}

void FreshDatabase::exec(const std::string& sql) const
{
    if (mBackend == Backend::SQLite) {
        SQLite::Database raw(mDatabase, SQLite::OPEN_READWRITE);
        raw.setBusyTimeout(10'000);
        raw.exec(sql);
        return;
    }
    pqxx::connection raw(mDatabase + "?connect_timeout=10");
    pqxx::work txn(raw);
    txn.exec(sql);
    txn.commit();
}

void StoreTest::SetUp()
{
    db = std::make_unique<FreshDatabase>(GetParam());
    storage = db->open();
}

void StoreTest::TearDown()
{
    storage.reset();   // closed before its directory goes
    db.reset();
}

std::int64_t StoreTest::addJob(std::int64_t ownerId)
{
    return store().jobs().create(jobRequest(ownerId), resolvedSettings());
}

std::int64_t StoreTest::addFinishedJob(std::int64_t ownerId, const std::string* resultBlob)
{
    const std::int64_t id = addJob(ownerId);
    if (!store().jobs().markRunning(id) || !store().jobs().finish(id, server::JobState::Done, "", 2000, resultBlob))
        throw std::runtime_error("cannot run and finish job " + std::to_string(id));
    return id;
}

server::User StoreTest::addUser(const std::string& name, const std::string& role)
{
    auto user = store().users().insert(name, "hash of " + name, role);
    if (!user) throw std::runtime_error("cannot add user " + name);
    return *user;
}

} // namespace tlmhub::test
