#include "server/store/UnixTime.h"
#include "server/store/postgres/PostgresStores.h"

#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <functional>
#include <random>
#include <unordered_set>

namespace tlmhub::server {

namespace {

// The key of the advisory lock claims hold ("tlmhub\0\2"; migrations use "tlmhub\0\1").
constexpr long long kClaimLock = 0x746c6d6875620002;
constexpr const char* kChannel = "tlmhub_jobs";

constexpr PgStatement kNow{"leases_now", "SELECT " TLMHUB_NOW_MS};
constexpr PgStatement kClaimLockStatement{"leases_claim_lock", "SELECT pg_advisory_xact_lock($1)"};
// The claim's order (JobLeaseStore::claim): a user's k-th available queued job, oldest first,
// is their (running + k)-th; jobs go by that place, then the user served longest ago first
// (their latest claim: round robin), then by id, up to the per-user limit.
// $3: idle owners only (place 1 is a user with nothing running and their oldest job).
constexpr PgStatement kCandidates{
    "leases_candidates",
    "WITH running AS (SELECT owner_id, COUNT(*) AS n FROM jobs WHERE state = 'running' GROUP BY owner_id),"
    " ranked AS (SELECT j.id AS id, COALESCE(r.n, 0) + ROW_NUMBER() OVER (PARTITION BY j.owner_id ORDER BY j.id)"
    " AS place, (SELECT MAX(s.claimed_at) FROM jobs s WHERE s.owner_id = j.owner_id) AS served"
    " FROM jobs j LEFT JOIN running r ON r.owner_id = j.owner_id"
    " WHERE j.state = 'queued' AND j.available_at <= $1)"
    " SELECT id FROM ranked WHERE place <= $2 AND (NOT $3::boolean OR place = 1) ORDER BY place, served, id LIMIT $4"};
// Rows another transaction holds (a cancel, a delete) are skipped rather than waited for.
constexpr PgStatement kClaim{"leases_claim",
                             "UPDATE jobs SET state = 'running',"
                             " started_at = CASE WHEN started_at = 0 THEN $2 ELSE started_at END,"
                             " progress = 0, lease_node = $3, lease_expires_at = $4, lease = lease + 1,"
                             " cancel_requested = FALSE, claimed_at = $5"
                             " WHERE id IN (SELECT id FROM jobs WHERE id = ANY($1::bigint[]) AND state = 'queued'"
                             " FOR UPDATE SKIP LOCKED) RETURNING id, owner_id, lease"};
constexpr PgStatement kRenew{"leases_renew",
                             "UPDATE jobs j SET lease_expires_at = " TLMHUB_NOW_MS " + $4"
                             " FROM unnest($1::bigint[], $2::bigint[]) AS l(id, lease)"
                             " WHERE j.id = l.id AND j.lease = l.lease AND j.lease_node = $3 AND j.state = 'running'"
                             " RETURNING j.id"};
constexpr PgStatement kCancelRequested{"leases_cancel_requested",
                                       "SELECT id FROM jobs WHERE id = ANY($1::bigint[]) AND state = 'running'"
                                       " AND cancel_requested ORDER BY id"};
constexpr PgStatement kCancelQueued{"leases_cancel_queued",
                                    "UPDATE jobs SET state = 'cancelled', finished_at = $2"
                                    " WHERE id = $1 AND state = 'queued'"};
constexpr PgStatement kCancelRunning{"leases_cancel_running",
                                     "UPDATE jobs SET cancel_requested = TRUE WHERE id = $1 AND state = 'running'"};
constexpr PgStatement kFinish{"leases_finish",
                              "UPDATE jobs SET state = $1, error = $2, steps = $3, finished_at = $4,"
                              " progress = CASE WHEN $5 THEN 1 ELSE progress END,"
                              " lease_node = NULL, lease_expires_at = 0"
                              " WHERE id = $6 AND state = 'running' AND lease = $7"};
constexpr PgStatement kStoreResult{"leases_store_result",
                                   "INSERT INTO job_results(job_id, data) VALUES($1, $2)"
                                   " ON CONFLICT (job_id) DO UPDATE SET data = EXCLUDED.data"};
constexpr PgStatement kSetProgress{"leases_set_progress",
                                   "UPDATE jobs SET progress = $1 WHERE id = $2 AND state = 'running' AND lease = $3"};
constexpr PgStatement kRelease{"leases_release",
                               "UPDATE jobs SET state = CASE WHEN cancel_requested THEN 'cancelled' ELSE 'queued' END,"
                               " finished_at = CASE WHEN cancel_requested THEN $3 ELSE finished_at END,"
                               " lease_node = NULL, lease_expires_at = 0, available_at = 0"
                               " WHERE id = $1 AND state = 'running' AND lease = $2"};
constexpr PgStatement kExpired{"leases_expired",
                               "SELECT id, lease, COALESCE(lease_node, ''), cancel_requested FROM jobs WHERE state = 'running'"
                               " AND lease_expires_at > 0 AND lease_expires_at < $1 ORDER BY id FOR UPDATE SKIP LOCKED"};
constexpr PgStatement kExpireCancelled{"leases_expire_cancelled",
                                       "UPDATE jobs SET state = 'cancelled', finished_at = $2, lease_node = NULL,"
                                       " lease_expires_at = 0 WHERE id = $1"};
constexpr PgStatement kExpireDead{"leases_expire_dead",
                                  "UPDATE jobs SET state = 'dead', finished_at = $2, error = $3,"
                                  " lease_node = NULL, lease_expires_at = 0 WHERE id = $1"};
constexpr PgStatement kExpireQueued{"leases_expire_queued",
                                    "UPDATE jobs SET state = 'queued', available_at = $2,"
                                    " lease_node = NULL, lease_expires_at = 0 WHERE id = $1"};
constexpr PgStatement kQueuedCount{"leases_queued_count",
                                   "SELECT COUNT(*) FROM jobs WHERE owner_id = $1 AND state = 'queued'"};
constexpr PgStatement kHolder{"leases_holder",
                              "SELECT j.lease_node, COALESCE(n.address, ''), j.lease FROM jobs j"
                              " LEFT JOIN nodes n ON n.id = j.lease_node"
                              " WHERE j.id = $1 AND j.state = 'running' AND j.lease_node IS NOT NULL"};
constexpr PgStatement kClaims{"leases_claims", "SELECT lease FROM jobs WHERE id = $1"};
constexpr PgStatement kTouchNode{"leases_touch_node",
                                 "INSERT INTO nodes(id, role, address, last_seen) VALUES($1, $2, $3, " TLMHUB_NOW_MS ")"
                                 " ON CONFLICT (id) DO UPDATE SET role = EXCLUDED.role, address = EXCLUDED.address,"
                                 " last_seen = EXCLUDED.last_seen"};
constexpr PgStatement kRemoveNode{"leases_remove_node", "DELETE FROM nodes WHERE id = $1"};
constexpr PgStatement kLiveNodes{"leases_live_nodes",
                                 "SELECT id, role, address, last_seen FROM nodes"
                                 " WHERE last_seen >= " TLMHUB_NOW_MS " - $1 ORDER BY id"};
constexpr PgStatement kNotify{"leases_notify", "SELECT pg_notify('tlmhub_jobs', $1)"};

#undef TLMHUB_NOW_MS

// A PostgreSQL array literal of ids: "{1,2,3}".
std::string arrayOf(const std::vector<std::int64_t>& ids)
{
    std::string out = "{";
    for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? "," : "") + std::to_string(ids[i]);
    return out + "}";
}

// Wakes a thread in poll() on the eventfd (its count only has to be non-zero).
void signalEventFd(int fd)
{
    if (fd < 0) return;
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto written = ::write(fd, &one, sizeof one);
}

std::string randomTag()
{
    std::random_device random;
    const std::uint64_t value = (static_cast<std::uint64_t>(random()) << 32) ^ random();
    return "tlmhub-" + std::to_string(value);
}

} // namespace

// The connection that LISTENs on tlmhub_jobs, and its receiver (which issued the LISTEN).
class PostgresJobLeaseStore::Listener {
public:
    Listener(const std::string& uri, std::function<void(const std::string&)> onNotify)
        : mConnection(uri), mReceiver(std::make_unique<Receiver>(mConnection, std::move(onNotify)))
    {
    }
    // The receiver goes first: it unregisters from the connection.
    ~Listener() { mReceiver.reset(); }

    pqxx::connection& connection() { return mConnection; }

private:
    class Receiver final : public pqxx::notification_receiver {
    public:
        Receiver(pqxx::connection& c, std::function<void(const std::string&)> onNotify)
            : pqxx::notification_receiver(c, kChannel), mOnNotify(std::move(onNotify))
        {
        }
        void operator()(const std::string& payload, int) override { mOnNotify(payload); }

    private:
        std::function<void(const std::string&)> mOnNotify;
    };

    pqxx::connection mConnection;
    std::unique_ptr<Receiver> mReceiver;
};

PostgresJobLeaseStore::PostgresJobLeaseStore(PostgresDatabase& db)
    : mDb(db), mNotifyTag(randomTag()), mWakeFd(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC))
{
}

PostgresJobLeaseStore::~PostgresJobLeaseStore()
{
    mListener.reset();
    if (mWakeFd >= 0) ::close(mWakeFd);
}

std::vector<JobLease> PostgresJobLeaseStore::claim(const ClaimRequest& request)
{
    if (request.count == 0 || request.maxRunningPerUser <= 0) return {};
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        // Claims of every node take turns: each sees the running counts the one before left.
        c.exec(tx, kClaimLockStatement, kClaimLock);
        const auto now = c.exec(tx, kNow)[0][0].as<std::int64_t>();
        std::vector<std::int64_t> ids;
        for (const auto& row : c.exec(tx, kCandidates, now, request.maxRunningPerUser, request.idleOwnersOnly,
                                      static_cast<std::int64_t>(request.count)))
            ids.push_back(row[0].as<std::int64_t>());
        std::vector<JobLease> claimed;
        if (!ids.empty()) {
            const auto rows = c.exec(tx, kClaim, arrayOf(ids), now / 1000, request.nodeId,
                                     now + static_cast<std::int64_t>(request.leaseTime.count()), now);
            // RETURNING comes in no particular order: put the claims in the fair order.
            for (const std::int64_t id : ids)
                for (const auto& row : rows)
                    if (row[0].as<std::int64_t>() == id)
                        claimed.push_back(JobLease{id, row[1].as<std::int64_t>(), row[2].as<std::int64_t>()});
        }
        tx.commit();
        return claimed;
    });
}

std::vector<std::int64_t> PostgresJobLeaseStore::renew(const std::string& nodeId, const std::vector<JobLease>& leases,
                                                       std::chrono::milliseconds leaseTime)
{
    if (leases.empty()) return {};
    std::vector<std::int64_t> ids, numbers;
    for (const auto& lease : leases) {
        ids.push_back(lease.jobId);
        numbers.push_back(lease.lease);
    }
    // Setting the expiry again is harmless, so a lost connection runs it once more.
    const auto renewed = mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::unordered_set<std::int64_t> held;
        for (const auto& row : c.exec(tx, kRenew, arrayOf(ids), arrayOf(numbers), nodeId,
                                      static_cast<std::int64_t>(leaseTime.count())))
            held.insert(row[0].as<std::int64_t>());
        return held;
    });
    std::vector<std::int64_t> lost;
    for (const std::int64_t id : ids)
        if (!renewed.contains(id)) lost.push_back(id);
    return lost;
}

std::vector<std::int64_t> PostgresJobLeaseStore::cancelRequested(const std::vector<std::int64_t>& jobIds)
{
    if (jobIds.empty()) return {};
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<std::int64_t> ids;
        for (const auto& row : c.exec(tx, kCancelRequested, arrayOf(jobIds))) ids.push_back(row[0].as<std::int64_t>());
        return ids;
    });
}

JobLeaseStore::CancelOutcome PostgresJobLeaseStore::requestCancel(std::int64_t jobId)
{
    const auto outcome = mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        auto result = CancelOutcome::NotActive;
        if (c.exec(tx, kCancelQueued, jobId, static_cast<std::int64_t>(unixNow())).affected_rows() == 1)
            result = CancelOutcome::Cancelled;
        else if (c.exec(tx, kCancelRunning, jobId).affected_rows() == 1)
            result = CancelOutcome::Cancelling;
        tx.commit();
        return result;
    });
    if (outcome == CancelOutcome::Cancelling) notifyWork();
    return outcome;
}

bool PostgresJobLeaseStore::finishLeased(const JobLease& lease, JobState state, const std::string& error,
                                         std::uint64_t steps, const std::string* resultBlob)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        const auto updated = c.exec(tx, kFinish, jobStateName(state), error, static_cast<std::int64_t>(steps),
                                    static_cast<std::int64_t>(unixNow()), state == JobState::Done, lease.jobId,
                                    lease.lease);
        if (updated.affected_rows() != 1) return false;   // taken over, finished or gone: nothing written
        if (resultBlob)
            c.exec(tx, kStoreResult, lease.jobId, pqxx::binarystring(resultBlob->data(), resultBlob->size()));
        tx.commit();
        return true;
    });
}

void PostgresJobLeaseStore::setProgressLeased(const JobLease& lease, double progress)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kSetProgress, progress, lease.jobId, lease.lease);
    });
}

bool PostgresJobLeaseStore::release(const JobLease& lease)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRelease, lease.jobId, lease.lease, static_cast<std::int64_t>(unixNow())).affected_rows() == 1;
    });
}

std::vector<ExpiredLease> PostgresJobLeaseStore::expireLeases(int maxAttempts, std::chrono::milliseconds backoff,
                                                              std::chrono::milliseconds maxBackoff)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        const auto now = c.exec(tx, kNow)[0][0].as<std::int64_t>();
        std::vector<ExpiredLease> expired;
        // Locked until the commit; another node expiring at the same time skips these rows.
        for (const auto& row : c.exec(tx, kExpired, now)) {
            const auto id = row[0].as<std::int64_t>();
            const auto claims = row[1].as<std::int64_t>();
            JobState state = JobState::Queued;
            if (row[3].as<bool>()) {
                state = JobState::Cancelled;
                c.exec(tx, kExpireCancelled, id, now / 1000);
            } else if (claims >= maxAttempts) {
                state = JobState::Dead;
                c.exec(tx, kExpireDead, id, now / 1000, deadLeaseError(claims, row[2].as<std::string>()));
            } else {
                c.exec(tx, kExpireQueued, id,
                       now + static_cast<std::int64_t>(leaseBackoff(claims, backoff, maxBackoff).count()));
            }
            expired.push_back(ExpiredLease{id, state});
        }
        tx.commit();
        return expired;
    });
}

int PostgresJobLeaseStore::queuedCount(std::int64_t ownerId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kQueuedCount, ownerId)[0][0].as<int>();
    });
}

std::optional<LeaseHolder> PostgresJobLeaseStore::holder(std::int64_t jobId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<LeaseHolder> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kHolder, jobId);
        if (r.empty()) return std::nullopt;
        return LeaseHolder{r[0][0].as<std::string>(), r[0][1].as<std::string>(), r[0][2].as<std::int64_t>()};
    });
}

std::int64_t PostgresJobLeaseStore::claims(std::int64_t jobId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::int64_t {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kClaims, jobId);
        return r.empty() ? 0 : r[0][0].as<std::int64_t>();
    });
}

void PostgresJobLeaseStore::touchNode(const NodeInfo& node)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kTouchNode, node.id, node.role, node.address);
    });
}

void PostgresJobLeaseStore::removeNode(const std::string& nodeId)
{
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kRemoveNode, nodeId);
    });
}

std::vector<NodeInfo> PostgresJobLeaseStore::liveNodes(std::chrono::milliseconds within)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<NodeInfo> nodes;
        for (const auto& row : c.exec(tx, kLiveNodes, static_cast<std::int64_t>(within.count())))
            nodes.push_back(NodeInfo{row[0].as<std::string>(), row[1].as<std::string>(), row[2].as<std::string>(),
                                     row[3].as<std::int64_t>()});
        return nodes;
    });
}

void PostgresJobLeaseStore::wakeHere()
{
    {
        std::lock_guard lock(mWakeMutex);
        ++mNotified;
    }
    mWake.notify_all();
    // The thread listening sits in poll(), not on mWake.
    signalEventFd(mWakeFd);
}

void PostgresJobLeaseStore::notifyWork()
{
    // This process's waiters at once; other nodes through the database. The payload tells
    // this store's own listener that it has woken its waiters already.
    wakeHere();
    mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        c.exec(tx, kNotify, mNotifyTag);
    });
}

bool PostgresJobLeaseStore::waitForWork(std::chrono::milliseconds timeout)
{
    using Clock = std::chrono::steady_clock;
    // Slices of at most this long, so interruptWait and a new listener are noticed soon.
    constexpr std::chrono::milliseconds kSlice{100};
    const auto deadline = Clock::now() + timeout;
    std::uint64_t seen = 0;
    {
        std::lock_guard lock(mWakeMutex);
        // A wake-up since the last wait that returned woken counts: the caller may have been
        // claiming when it came.
        seen = mSeen;
    }
    const auto woken = [&] { return mInterrupted.load() || mNotified != seen; };
    bool listenerFailed = false;   // in this call: then no reconnecting until the next call
    for (;;) {
        {
            std::lock_guard lock(mWakeMutex);
            if (mInterrupted.exchange(false)) return false;   // one interruption ends one wait
            if (mNotified != seen) {
                mSeen = mNotified;
                return true;
            }
        }
        const auto now = Clock::now();
        if (now >= deadline) return false;
        const auto slice = std::min(kSlice, std::chrono::ceil<std::chrono::milliseconds>(deadline - now));
        std::unique_lock listening(mListenMutex, std::try_to_lock);
        if (listening.owns_lock() && !listenerFailed) {
            try {
                if (!mListener)
                    mListener = std::make_unique<Listener>(mDb.uri(), [this](const std::string& payload) {
                        if (payload != mNotifyTag) wakeHere();
                    });
                auto& connection = mListener->connection();
                connection.get_notifs();   // any that arrived with the last reply
                pollfd fds[2] = {{connection.sock(), POLLIN, 0}, {mWakeFd, POLLIN, 0}};
                if (fds[0].fd < 0) throw pqxx::broken_connection("the LISTEN connection is closed");
                if (::poll(fds, 2, static_cast<int>(slice.count())) > 0) {
                    if (fds[1].revents & POLLIN) {
                        std::uint64_t count = 0;
                        [[maybe_unused]] const auto got = ::read(mWakeFd, &count, sizeof count);
                    }
                    if (fds[0].revents) connection.get_notifs();
                }
                continue;
            } catch (const std::exception&) {
                // Dropped; the next call opens a new one. Until then this call waits for
                // this process's wake-ups only.
                mListener.reset();
                listenerFailed = true;
            }
        }
        if (listening.owns_lock()) listening.unlock();
        std::unique_lock lock(mWakeMutex);
        mWake.wait_for(lock, slice, woken);
    }
}

void PostgresJobLeaseStore::interruptWait()
{
    {
        std::lock_guard lock(mWakeMutex);
        mInterrupted = true;
    }
    mWake.notify_all();
    signalEventFd(mWakeFd);
}

} // namespace tlmhub::server
