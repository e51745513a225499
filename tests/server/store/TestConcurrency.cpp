// Many writers at once: every call succeeds (a back end waits for its turn rather than giving
// a Busy error to the caller) and nothing is lost.
#include "StoreBackends.h"

#include "server/store/StoreError.h"

#include <mutex>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class ConcurrencyConformance : public StoreTest {};
TLMHUB_STORE_CONFORMANCE(ConcurrencyConformance);

constexpr int kRounds = 25;

// What the writers could not do, by message; Busy counted apart as the case this is about.
struct Failures {
    std::mutex mutex;
    int busy = 0;
    std::vector<std::string> messages;

    void add(const std::string& what)
    {
        std::lock_guard lock(mutex);
        messages.push_back(what);
    }
};

std::string resultOf(int writer)
{
    return std::string(100 + writer, static_cast<char>('a' + writer));
}

// One writer's work: kRounds jobs run and finished with a result, models, sessions and
// accounts, all as `owner`.
void write(Storage& storage, const User& owner, int writer, Failures& failures)
{
    const std::string blob = resultOf(writer);
    for (int round = 0; round < kRounds; ++round) {
        const std::string tag = std::to_string(writer) + "-" + std::to_string(round);
        try {
            const std::int64_t job = storage.jobs().create(jobRequest(owner.id), resolvedSettings());
            if (!storage.jobs().markRunning(job)) failures.add("markRunning " + tag);
            storage.jobs().setProgress(job, 0.5);
            if (!storage.jobs().finish(job, JobState::Done, "", 2000, &blob)) failures.add("finish " + tag);
            if (!storage.models().create(owner.id, "model " + tag, "<hmf/>", false)) failures.add("model " + tag);
            storage.sessions().insert("token " + tag, owner.id, 2'000'000'000, 1'000'000'000);
            if (!storage.users().insert("user " + tag, "h", kRoleUser)) failures.add("user " + tag);
        } catch (const StoreError& e) {
            std::lock_guard lock(failures.mutex);
            failures.busy += e.code() == StoreErrc::Busy;
            failures.messages.push_back(std::string(storeErrcName(e.code())) + " at " + tag + ": " + e.what());
        }
    }
}

// Runs `writers` writers at once, writer i on storages[i % storages.size()], each as its own
// account, then checks that everything they wrote is there.
void writeConcurrently(const std::vector<Storage*>& storages, int writers)
{
    Storage& check = *storages.front();
    std::vector<User> owners;
    for (int i = 0; i < writers; ++i)
        owners.push_back(check.users().insert("owner " + std::to_string(i), "h", kRoleUser).value());
    Failures failures;
    runAtOnce(writers, [&](int i) {
        write(*storages[static_cast<std::size_t>(i) % storages.size()], owners[static_cast<std::size_t>(i)], i, failures);
    });
    EXPECT_EQ(failures.busy, 0);
    for (const std::string& m : failures.messages) ADD_FAILURE() << m;

    const std::size_t total = static_cast<std::size_t>(writers) * kRounds;
    EXPECT_EQ(check.jobs().listAll().size(), total);
    EXPECT_EQ(check.jobs().listInState(JobState::Done).size(), total);
    EXPECT_EQ(check.models().list().size(), total);
    EXPECT_EQ(check.users().count(), total + static_cast<std::size_t>(writers));
    for (int i = 0; i < writers; ++i) {
        const User& owner = owners[static_cast<std::size_t>(i)];
        const auto jobs = check.jobs().listForOwner(owner.id);
        EXPECT_EQ(jobs.size(), std::size_t{kRounds}) << owner.username;
        for (const JobInfo& j : jobs) EXPECT_EQ(check.results().blob(j.id), resultOf(i));
        EXPECT_EQ(check.results().storedBytes(owner.id), kRounds * resultOf(i).size()) << owner.username;
        for (int round = 0; round < kRounds; ++round)
            EXPECT_EQ(check.sessions().userOf("token " + std::to_string(i) + "-" + std::to_string(round), 1'000'000'000),
                      owner.id);
    }
}

TEST_P(ConcurrencyConformance, EightConcurrentWritersAllSucceedWithoutBusy)
{
    writeConcurrently({&store()}, 8);
}

// Submits of one user racing on every connection of the pool: exactly the limit gets in.
void submitConcurrently(const std::vector<Storage*>& storages, int submitters)
{
    constexpr int kLimit = 5;
    constexpr int kEach = 4;
    Storage& check = *storages.front();
    const User owner = check.users().insert("queuer", "h", kRoleUser).value();
    std::mutex mutex;
    int admitted = 0;
    std::vector<int> refusedAt;
    runAtOnce(submitters, [&](int i) {
        Storage& storage = *storages[static_cast<std::size_t>(i) % storages.size()];
        for (int k = 0; k < kEach; ++k) {
            const auto admission = storage.jobs().createWithinQueueLimit(jobRequest(owner.id), resolvedSettings(), kLimit);
            std::lock_guard lock(mutex);
            if (admission.id) ++admitted;
            else refusedAt.push_back(admission.queued);
        }
    });
    EXPECT_EQ(admitted, kLimit);
    EXPECT_EQ(check.jobLeases().queuedCount(owner.id), kLimit);
    EXPECT_EQ(refusedAt.size(), static_cast<std::size_t>(submitters * kEach - kLimit));
    for (const int queued : refusedAt) EXPECT_EQ(queued, kLimit);
}

TEST_P(ConcurrencyConformance, RacingSubmitsNeverPassTheQueuedLimit)
{
    submitConcurrently({&store()}, 8);
}

// Two servers (or a server and a backup tool) on one SQLite file: separate connection pools,
// so only SQLite's own locking keeps them apart.
TEST(SQLiteStore, TwoStoragesOnOneFileWriteConcurrentlyWithoutBusy)
{
    FreshDatabase db(Backend::SQLite);
    auto first = db.open();
    auto second = db.open();
    writeConcurrently({first.get(), second.get()}, 8);
}

TEST(SQLiteStore, RacingSubmitsThroughTwoStoragesNeverPassTheQueuedLimit)
{
    FreshDatabase db(Backend::SQLite);
    auto first = db.open();
    auto second = db.open();
    submitConcurrently({first.get(), second.get()}, 8);
}

} // namespace
} // namespace tlmhub::test
