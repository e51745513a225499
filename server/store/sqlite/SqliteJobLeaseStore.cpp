#include "server/store/UnixTime.h"
#include "server/store/sqlite/SqliteStores.h"

#include <SQLiteCpp/Transaction.h>

namespace tlmhub::server {

namespace {

// The claim's order (JobLeaseStore::claim): a user's k-th available queued job, oldest first,
// is their (running + k)-th; jobs go by that place, then the user served longest ago first
// (their latest claim: round robin), then by id, up to the per-user limit.
// ?1 now, ?2 maxRunningPerUser, ?3 idle owners only (place 1 is a user with nothing running
// and their oldest job), ?4 count.
constexpr const char* kCandidates =
    "WITH running AS (SELECT owner_id, COUNT(*) AS n FROM jobs WHERE state = 'running' GROUP BY owner_id),"
    " ranked AS (SELECT j.id AS id, COALESCE(r.n, 0) + ROW_NUMBER() OVER (PARTITION BY j.owner_id ORDER BY j.id)"
    " AS place, (SELECT MAX(s.claimed_at) FROM jobs s WHERE s.owner_id = j.owner_id) AS served"
    " FROM jobs j LEFT JOIN running r ON r.owner_id = j.owner_id"
    " WHERE j.state = 'queued' AND j.available_at <= ?1)"
    " SELECT id FROM ranked WHERE place <= ?2 AND (?3 = 0 OR place = 1) ORDER BY place, served, id LIMIT ?4";

// Ids as a JSON array, for "id IN (SELECT value FROM json_each(?))": one prepared text for any
// number of ids.
std::string jsonIds(const std::vector<std::int64_t>& ids)
{
    std::string out = "[";
    for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? "," : "") + std::to_string(ids[i]);
    return out + "]";
}

} // namespace

std::vector<JobLease> SqliteJobLeaseStore::claim(const ClaimRequest& request)
{
    if (request.count == 0 || request.maxRunningPerUser <= 0) return {};
    const std::int64_t now = unixNowMillis();
    return mDb.run([&](SqliteConnection& c) {
        // IMMEDIATE: the write lock from the start, so claims of every connection (and
        // process) take turns and each sees the running counts the one before left.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        std::vector<std::int64_t> ids;
        {
            auto q = c.prepared(kCandidates);
            q->bind(1, now);
            q->bind(2, request.maxRunningPerUser);
            q->bind(3, request.idleOwnersOnly ? 1 : 0);
            q->bind(4, static_cast<std::int64_t>(request.count));
            while (q->executeStep()) ids.push_back(q->getColumn(0).getInt64());
        }
        std::vector<JobLease> claimed;
        for (const std::int64_t id : ids) {
            auto q = c.prepared("UPDATE jobs SET state = 'running',"
                                " started_at = CASE WHEN started_at = 0 THEN ? ELSE started_at END,"
                                " progress = 0, lease_node = ?, lease_expires_at = ?, lease = lease + 1,"
                                " cancel_requested = 0, claimed_at = ?"
                                " WHERE id = ? AND state = 'queued' RETURNING owner_id, lease");
            q->bind(1, now / 1000);
            q->bind(2, request.nodeId);
            q->bind(3, now + request.leaseTime.count());
            q->bind(4, now);
            q->bind(5, id);
            if (q->executeStep())
                claimed.push_back(JobLease{id, q->getColumn(0).getInt64(), q->getColumn(1).getInt64()});
        }
        transaction.commit();
        return claimed;
    });
}

std::vector<std::int64_t> SqliteJobLeaseStore::renew(const std::string& nodeId, const std::vector<JobLease>& leases,
                                                     std::chrono::milliseconds leaseTime)
{
    if (leases.empty()) return {};
    const std::int64_t expires = unixNowMillis() + leaseTime.count();
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        std::vector<std::int64_t> lost;
        for (const auto& lease : leases) {
            auto q = c.prepared("UPDATE jobs SET lease_expires_at = ?"
                                " WHERE id = ? AND lease_node = ? AND lease = ? AND state = 'running'");
            q->bind(1, expires);
            q->bind(2, lease.jobId);
            q->bind(3, nodeId);
            q->bind(4, lease.lease);
            if (q->exec() != 1) lost.push_back(lease.jobId);
        }
        transaction.commit();
        return lost;
    });
}

std::vector<std::int64_t> SqliteJobLeaseStore::cancelRequested(const std::vector<std::int64_t>& jobIds)
{
    if (jobIds.empty()) return {};
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT id FROM jobs WHERE id IN (SELECT value FROM json_each(?))"
                            " AND state = 'running' AND cancel_requested = 1 ORDER BY id");
        q->bind(1, jsonIds(jobIds));
        std::vector<std::int64_t> ids;
        while (q->executeStep()) ids.push_back(q->getColumn(0).getInt64());
        return ids;
    });
}

JobLeaseStore::CancelOutcome SqliteJobLeaseStore::requestCancel(std::int64_t jobId)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    const auto outcome = mDb.runFreeingSpace([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        auto result = CancelOutcome::NotActive;
        {
            auto queued = c.prepared("UPDATE jobs SET state = 'cancelled', finished_at = ?"
                                     " WHERE id = ? AND state = 'queued'");
            queued->bind(1, now);
            queued->bind(2, jobId);
            if (queued->exec() == 1) result = CancelOutcome::Cancelled;
        }
        if (result == CancelOutcome::NotActive) {
            auto running = c.prepared("UPDATE jobs SET cancel_requested = 1 WHERE id = ? AND state = 'running'");
            running->bind(1, jobId);
            if (running->exec() == 1) result = CancelOutcome::Cancelling;
        }
        transaction.commit();
        return result;
    });
    if (outcome == CancelOutcome::Cancelling) notifyWork();
    return outcome;
}

bool SqliteJobLeaseStore::finishLeased(const JobLease& lease, JobState state, const std::string& error,
                                       std::uint64_t steps, const std::string* resultBlob)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto q = c.prepared("UPDATE jobs SET state = ?, error = ?, steps = ?, finished_at = ?,"
                                " progress = CASE WHEN ? THEN 1 ELSE progress END,"
                                " lease_node = NULL, lease_expires_at = 0"
                                " WHERE id = ? AND state = 'running' AND lease = ?");
            q->bind(1, jobStateName(state));
            q->bind(2, error);
            q->bind(3, static_cast<std::int64_t>(steps));
            q->bind(4, now);
            q->bind(5, state == JobState::Done ? 1 : 0);
            q->bind(6, lease.jobId);
            q->bind(7, lease.lease);
            if (q->exec() != 1) return false;   // taken over, finished or gone: nothing written
        }
        if (resultBlob) {
            auto insert = c.prepared("INSERT OR REPLACE INTO job_results(job_id, data) VALUES(?, ?)");
            insert->bind(1, lease.jobId);
            insert->bindNoCopy(2, resultBlob->data(), static_cast<int>(resultBlob->size()));
            insert->exec();
        }
        transaction.commit();
        return true;
    });
}

void SqliteJobLeaseStore::setProgressLeased(const JobLease& lease, double progress)
{
    mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE jobs SET progress = ? WHERE id = ? AND state = 'running' AND lease = ?");
        q->bind(1, progress);
        q->bind(2, lease.jobId);
        q->bind(3, lease.lease);
        q->exec();
    });
}

bool SqliteJobLeaseStore::release(const JobLease& lease)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE jobs SET state = CASE WHEN cancel_requested THEN 'cancelled' ELSE 'queued' END,"
                            " finished_at = CASE WHEN cancel_requested THEN ? ELSE finished_at END,"
                            " lease_node = NULL, lease_expires_at = 0, available_at = 0"
                            " WHERE id = ? AND state = 'running' AND lease = ?");
        q->bind(1, static_cast<std::int64_t>(unixNow()));
        q->bind(2, lease.jobId);
        q->bind(3, lease.lease);
        return q->exec() == 1;
    });
}

std::vector<ExpiredLease> SqliteJobLeaseStore::expireLeases(int maxAttempts, std::chrono::milliseconds backoff,
                                                            std::chrono::milliseconds maxBackoff)
{
    const std::int64_t now = unixNowMillis();
    const auto nowSeconds = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        struct Expired {
            std::int64_t id, lease;
            std::string node;
            bool cancelRequested;
        };
        std::vector<Expired> found;
        {
            auto q = c.prepared("SELECT id, lease, COALESCE(lease_node, ''), cancel_requested FROM jobs WHERE state = 'running'"
                                " AND lease_expires_at > 0 AND lease_expires_at < ? ORDER BY id");
            q->bind(1, now);
            while (q->executeStep())
                found.push_back({q->getColumn(0).getInt64(), q->getColumn(1).getInt64(), q->getColumn(2).getString(),
                                 q->getColumn(3).getInt() != 0});
        }
        std::vector<ExpiredLease> expired;
        for (const auto& job : found) {
            JobState state = JobState::Queued;
            if (job.cancelRequested) {
                state = JobState::Cancelled;
                auto q = c.prepared("UPDATE jobs SET state = 'cancelled', finished_at = ?,"
                                    " lease_node = NULL, lease_expires_at = 0 WHERE id = ?");
                q->bind(1, nowSeconds);
                q->bind(2, job.id);
                q->exec();
            } else if (job.lease >= maxAttempts) {
                state = JobState::Dead;
                auto q = c.prepared("UPDATE jobs SET state = 'dead', finished_at = ?, error = ?,"
                                    " lease_node = NULL, lease_expires_at = 0 WHERE id = ?");
                q->bind(1, nowSeconds);
                q->bind(2, deadLeaseError(job.lease, job.node));
                q->bind(3, job.id);
                q->exec();
            } else {
                auto q = c.prepared("UPDATE jobs SET state = 'queued', available_at = ?,"
                                    " lease_node = NULL, lease_expires_at = 0 WHERE id = ?");
                q->bind(1, now + leaseBackoff(job.lease, backoff, maxBackoff).count());
                q->bind(2, job.id);
                q->exec();
            }
            expired.push_back(ExpiredLease{job.id, state});
        }
        transaction.commit();
        return expired;
    });
}

int SqliteJobLeaseStore::queuedCount(std::int64_t ownerId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT COUNT(*) FROM jobs WHERE owner_id = ? AND state = 'queued'");
        q->bind(1, ownerId);
        q->executeStep();
        return q->getColumn(0).getInt();
    });
}

std::optional<LeaseHolder> SqliteJobLeaseStore::holder(std::int64_t jobId)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<LeaseHolder> {
        auto q = c.prepared("SELECT j.lease_node, COALESCE(n.address, ''), j.lease FROM jobs j"
                            " LEFT JOIN nodes n ON n.id = j.lease_node"
                            " WHERE j.id = ? AND j.state = 'running' AND j.lease_node IS NOT NULL");
        q->bind(1, jobId);
        if (!q->executeStep()) return std::nullopt;
        return LeaseHolder{q->getColumn(0).getString(), q->getColumn(1).getString(), q->getColumn(2).getInt64()};
    });
}

std::int64_t SqliteJobLeaseStore::claims(std::int64_t jobId)
{
    return mDb.run([&](SqliteConnection& c) -> std::int64_t {
        auto q = c.prepared("SELECT lease FROM jobs WHERE id = ?");
        q->bind(1, jobId);
        if (!q->executeStep()) return 0;
        return q->getColumn(0).getInt64();
    });
}

void SqliteJobLeaseStore::touchNode(const NodeInfo& node)
{
    const std::int64_t now = unixNowMillis();
    mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("INSERT INTO nodes(id, role, address, last_seen) VALUES(?, ?, ?, ?)"
                            " ON CONFLICT(id) DO UPDATE SET role = excluded.role, address = excluded.address,"
                            " last_seen = excluded.last_seen");
        q->bind(1, node.id);
        q->bind(2, node.role);
        q->bind(3, node.address);
        q->bind(4, now);
        q->exec();
    });
}

void SqliteJobLeaseStore::removeNode(const std::string& nodeId)
{
    mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("DELETE FROM nodes WHERE id = ?");
        q->bind(1, nodeId);
        q->exec();
    });
}

std::vector<NodeInfo> SqliteJobLeaseStore::liveNodes(std::chrono::milliseconds within)
{
    const std::int64_t since = unixNowMillis() - within.count();
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT id, role, address, last_seen FROM nodes WHERE last_seen >= ? ORDER BY id");
        q->bind(1, since);
        std::vector<NodeInfo> nodes;
        while (q->executeStep())
            nodes.push_back(NodeInfo{q->getColumn(0).getString(), q->getColumn(1).getString(),
                                     q->getColumn(2).getString(), q->getColumn(3).getInt64()});
        return nodes;
    });
}

void SqliteJobLeaseStore::notifyWork()
{
    {
        std::lock_guard lock(mWakeMutex);
        ++mNotified;
    }
    mWake.notify_all();
}

bool SqliteJobLeaseStore::waitForWork(std::chrono::milliseconds timeout)
{
    std::unique_lock lock(mWakeMutex);
    // A notifyWork since the last wait that returned woken counts: the caller may have been
    // claiming when it came.
    const std::uint64_t seen = mSeen;
    const bool woken = mWake.wait_for(lock, timeout, [&] { return mInterrupted || mNotified != seen; });
    if (!woken || mInterrupted) {
        mInterrupted = false;   // one interruption ends one wait
        return false;
    }
    mSeen = mNotified;
    return true;
}

void SqliteJobLeaseStore::interruptWait()
{
    {
        std::lock_guard lock(mWakeMutex);
        mInterrupted = true;
    }
    mWake.notify_all();
}

} // namespace tlmhub::server
