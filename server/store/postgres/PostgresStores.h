#pragma once
// The PostgreSQL implementations of the store interfaces, one per aggregate (each in its own
// .cpp), all on one PostgresDatabase.
#include "server/store/ApiTokenStore.h"
#include "server/store/JobLeaseStore.h"
#include "server/store/JobStore.h"
#include "server/store/LabStore.h"
#include "server/store/LtiStore.h"
#include "server/store/IdempotencyKeyStore.h"
#include "server/store/MetaStore.h"
#include "server/store/ModelStore.h"
#include "server/store/ResultStore.h"
#include "server/store/SessionStore.h"
#include "server/store/SignInStore.h"
#include "server/store/StudyStore.h"
#include "server/store/UserStore.h"
#include "server/store/postgres/PostgresDatabase.h"

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>

namespace tlmhub::server {

class PostgresUserStore final : public UserStore {
public:
    explicit PostgresUserStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<User> insert(const std::string& username, const std::string& passwordHash,
                               const std::string& role) override;
    std::optional<Credentials> credentials(const std::string& username) override;
    std::optional<Credentials> credentials(std::int64_t id) override;
    bool setPasswordHash(std::int64_t id, const std::string& passwordHash) override;
    std::optional<std::string> preferences(std::int64_t id) override;
    bool setPreferences(std::int64_t id, const std::string& json) override;
    std::optional<User> find(std::int64_t id) override;
    std::optional<User> findByName(const std::string& username) override;
    std::vector<User> list() override;
    std::size_t count() override;
    UserChangeOutcome change(std::int64_t id, const UserChange& change, User& updated) override;
    std::vector<std::string> namesDifferingOnlyInCase() override;
    std::optional<User> findByIdentity(const std::string& provider, const std::string& subject) override;
    User insertLinked(const std::string& provider, const std::string& subject, const std::string& username,
                      const std::string& role) override;

private:
    PostgresDatabase& mDb;
};

class PostgresSessionStore final : public SessionStore {
public:
    explicit PostgresSessionStore(PostgresDatabase& db) : mDb(db) {}
    void insert(const std::string& tokenHash, std::int64_t userId, std::int64_t expiresAt,
                std::int64_t now) override;
    std::optional<std::int64_t> userOf(const std::string& tokenHash, std::int64_t now) override;
    void remove(const std::string& tokenHash) override;
    void removeAllFor(std::int64_t userId) override;

private:
    PostgresDatabase& mDb;
};

class PostgresModelStore final : public ModelStore {
public:
    explicit PostgresModelStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<std::int64_t> create(std::int64_t ownerId, const std::string& name,
                                       const std::string& hmf, bool isExample) override;
    std::optional<ModelSummary> summary(std::int64_t id) override;
    std::optional<std::string> hmf(std::int64_t id) override;
    bool update(std::int64_t id, const std::optional<std::string>& name,
                const std::optional<std::string>& hmf) override;
    bool remove(std::int64_t id) override;
    std::vector<ModelSummary> list() override;

private:
    PostgresDatabase& mDb;
};

class PostgresJobStore final : public JobStore {
public:
    explicit PostgresJobStore(PostgresDatabase& db) : mDb(db) {}
    std::int64_t create(const JobRequest& request, const JobInfo& resolved) override;
    Admission createWithinQueueLimit(const JobRequest& request, const JobInfo& resolved, int maxQueued) override;
    std::int64_t createFinished(const JobRequest& request, const JobInfo& resolved, std::uint64_t steps,
                                const std::string& resultBlob, const std::string& name) override;
    std::optional<JobInfo> info(std::int64_t id) override;
    std::optional<std::string> requestText(std::int64_t id) override;
    std::vector<JobInfo> listForOwner(std::int64_t ownerId) override;
    std::vector<JobInfo> listForModel(std::int64_t modelId, std::optional<std::int64_t> ownerId,
                                      std::optional<std::int64_t> beforeId, int limit) override;
    bool label(std::int64_t id, const std::optional<std::string>& name, std::optional<bool> pinned) override;
    int dropOldResults(std::int64_t modelId, int keep) override;
    bool dropResults(std::int64_t id) override;
    std::vector<JobInfo> listAll() override;
    std::vector<JobInfo> listInState(JobState state) override;
    bool markRunning(std::int64_t id) override;
    void setProgress(std::int64_t id, double progress) override;
    bool finish(std::int64_t id, JobState state, const std::string& error, std::uint64_t steps,
                const std::string* resultBlob) override;
    bool remove(std::int64_t id) override;
    int removeFinishedBefore(std::int64_t unixSeconds) override;

private:
    PostgresDatabase& mDb;
};

class PostgresJobLeaseStore final : public JobLeaseStore {
public:
    explicit PostgresJobLeaseStore(PostgresDatabase& db);
    ~PostgresJobLeaseStore() override;
    std::vector<JobLease> claim(const ClaimRequest& request) override;
    std::vector<std::int64_t> renew(const std::string& nodeId, const std::vector<JobLease>& leases,
                                    std::chrono::milliseconds leaseTime) override;
    std::vector<std::int64_t> cancelRequested(const std::vector<std::int64_t>& jobIds) override;
    CancelOutcome requestCancel(std::int64_t jobId) override;
    bool finishLeased(const JobLease& lease, JobState state, const std::string& error, std::uint64_t steps,
                      const std::string* resultBlob) override;
    void setProgressLeased(const JobLease& lease, double progress) override;
    bool release(const JobLease& lease) override;
    std::vector<ExpiredLease> expireLeases(int maxAttempts, std::chrono::milliseconds backoff,
                                           std::chrono::milliseconds maxBackoff) override;
    int queuedCount(std::int64_t ownerId) override;
    std::optional<LeaseHolder> holder(std::int64_t jobId) override;
    std::int64_t claims(std::int64_t jobId) override;
    void touchNode(const NodeInfo& node) override;
    void removeNode(const std::string& nodeId) override;
    std::vector<NodeInfo> liveNodes(std::chrono::milliseconds within) override;
    void notifyWork() override;
    bool waitForWork(std::chrono::milliseconds timeout) override;
    void interruptWait() override;

    // The LISTEN connection (PostgresJobLeaseStore.cpp).
    class Listener;

private:
    // Counts a wake-up and wakes this process's waiters.
    void wakeHere();

    PostgresDatabase& mDb;
    // Sent as the NOTIFY payload, so this store's listener skips its own notifications (its
    // waiters were woken in process already).
    std::string mNotifyTag;
    // One thread at a time listens on the connection; the others wait on mWake.
    std::mutex mListenMutex;
    std::unique_ptr<Listener> mListener;
    std::mutex mWakeMutex;
    std::condition_variable mWake;
    std::uint64_t mNotified = 0;   // wake-ups so far (this process's notifyWork and NOTIFYs heard)
    std::uint64_t mSeen = 0;       // mNotified when a waitForWork last returned woken
    std::atomic<bool> mInterrupted{false};
    int mWakeFd = -1;   // eventfd: wakes the listening thread out of poll() at once
};

class PostgresResultStore final : public ResultStore {
public:
    explicit PostgresResultStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<std::string> blob(std::int64_t jobId) override;
    bool has(std::int64_t jobId) override;
    std::size_t storedBytes(std::int64_t ownerId) override;

private:
    PostgresDatabase& mDb;
};

class PostgresMetaStore final : public MetaStore {
public:
    explicit PostgresMetaStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<std::string> get(const std::string& key) override;
    void set(const std::string& key, const std::string& value) override;
    bool insertIfAbsent(const std::string& key, const std::string& value) override;

private:
    PostgresDatabase& mDb;
};

class PostgresIdempotencyKeyStore final : public IdempotencyKeyStore {
public:
    explicit PostgresIdempotencyKeyStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<IdempotencyKey> reserve(std::int64_t ownerId, const std::string& key, const IdempotencyKey& use,
                                          std::int64_t nowUnix, std::int64_t notBeforeUnix) override;
    void complete(std::int64_t ownerId, const std::string& key, std::int64_t objectId) override;
    void release(std::int64_t ownerId, const std::string& key) override;

private:
    PostgresDatabase& mDb;
};

class PostgresApiTokenStore final : public ApiTokenStore {
public:
    explicit PostgresApiTokenStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<std::int64_t> insert(std::int64_t userId, const std::string& name, const std::string& tokenHash,
                                       std::int64_t createdAt, std::optional<std::int64_t> expiresAt) override;
    std::optional<ApiTokenInfo> use(const std::string& tokenHash, std::int64_t now) override;
    std::vector<ApiTokenInfo> list(std::int64_t userId) override;
    std::size_t count(std::int64_t userId) override;
    bool remove(std::int64_t userId, std::int64_t id) override;
    std::size_t removeAll(std::int64_t userId) override;

private:
    PostgresDatabase& mDb;
};

class PostgresStudyStore final : public StudyStore {
public:
    explicit PostgresStudyStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<std::int64_t> create(std::int64_t ownerId, std::optional<std::int64_t> modelId,
                                       const std::string& kind, const std::string& name,
                                       const std::string& request, std::int64_t runsTotal, const std::string& node,
                                       int maxActive) override;
    std::optional<StudyInfo> info(std::int64_t id) override;
    std::optional<std::string> request(std::int64_t id) override;
    std::vector<StudyInfo> listForOwner(std::int64_t ownerId) override;
    std::vector<StudyInfo> listInState(JobState state) override;
    int activeCount(std::int64_t ownerId) override;
    bool markRunning(std::int64_t id, const std::string& node) override;
    bool addRun(std::int64_t studyId, const StudyRun& run, const std::string* resultBlob) override;
    void setSummary(std::int64_t id, const std::string& summary) override;
    bool finish(std::int64_t id, JobState state, const std::string& error, const std::string& summary) override;
    std::vector<StudyInfo> adoptOrphans(const std::string& node, std::chrono::milliseconds within) override;
    void releaseQueued(const std::string& node) override;
    bool reopen(std::int64_t id, const std::string& node, int maxActive) override;
    std::vector<StudyRun> runs(std::int64_t studyId, std::int64_t fromIndex, std::size_t limit) override;
    std::optional<std::string> runResult(std::int64_t studyId, std::int64_t index) override;
    std::size_t storedBytes(std::int64_t ownerId) override;
    bool remove(std::int64_t id) override;

private:
    PostgresDatabase& mDb;
};

class PostgresLabStore final : public LabStore {
public:
    explicit PostgresLabStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<std::int64_t> createClass(std::int64_t ownerId, const std::string& name,
                                            const std::string& joinCode) override;
    std::optional<ClassInfo> classInfo(std::int64_t id) override;
    std::optional<ClassInfo> classByJoinCode(const std::string& code) override;
    std::vector<ClassInfo> listClasses() override;
    std::vector<Membership> classesOf(std::int64_t userId) override;
    bool setArchived(std::int64_t classId, bool archived) override;
    bool renameClass(std::int64_t classId, const std::string& name) override;
    bool removeClass(std::int64_t classId) override;
    bool setMember(std::int64_t classId, std::int64_t userId, const std::string& role) override;
    bool removeMember(std::int64_t classId, std::int64_t userId) override;
    std::optional<std::string> memberRole(std::int64_t classId, std::int64_t userId) override;
    std::vector<ClassMember> members(std::int64_t classId) override;
    bool supervisesCopy(std::int64_t staffId, std::int64_t modelId) override;
    std::optional<std::int64_t> createAssignment(const AssignmentInfo& info, const std::string& templateHmf,
                                                 const std::string& solutionHmf) override;
    std::optional<AssignmentInfo> assignment(std::int64_t id) override;
    std::vector<AssignmentInfo> assignmentsOf(std::int64_t classId) override;
    bool updateAssignment(const AssignmentInfo& info) override;
    std::optional<std::int64_t> setTemplate(std::int64_t id, const std::string& hmf) override;
    std::optional<std::string> templateHmf(std::int64_t id) override;
    bool setSolution(std::int64_t id, const std::string& hmf, const std::string& referenceBlob) override;
    std::optional<std::string> solutionHmf(std::int64_t id) override;
    std::optional<std::string> referenceResult(std::int64_t id) override;
    bool removeAssignment(std::int64_t id) override;
    bool replaceChecks(std::int64_t assignmentId, const std::vector<AssignmentCheck>& checks) override;
    std::vector<AssignmentCheck> checks(std::int64_t assignmentId) override;
    bool createCopy(const StudentCopy& copy) override;
    std::optional<StudentCopy> copy(std::int64_t assignmentId, std::int64_t studentId) override;
    std::optional<StudentCopy> copyByModel(std::int64_t modelId) override;
    std::vector<StudentCopy> copies(std::int64_t assignmentId) override;
    bool setCopyTemplateVersion(std::int64_t assignmentId, std::int64_t studentId, std::int64_t version) override;
    std::optional<HandIn> addHandIn(const HandIn& handIn) override;
    std::optional<HandIn> handIn(std::int64_t id) override;
    std::vector<HandIn> handIns(std::int64_t assignmentId, std::optional<std::int64_t> studentId) override;
    bool setGrade(std::int64_t handInId, std::optional<double> grade, std::int64_t gradedBy) override;
    std::optional<std::int64_t> addComment(std::int64_t handInId, std::int64_t authorId,
                                           const std::string& text) override;
    std::vector<HandInComment> comments(std::int64_t handInId) override;

private:
    PostgresDatabase& mDb;
};

class PostgresSignInStore final : public SignInStore {
public:
    explicit PostgresSignInStore(PostgresDatabase& db) : mDb(db) {}
    void add(const SignInAttempt& attempt) override;
    std::optional<SignInAttempt> take(const std::string& state, std::int64_t notBeforeUnix) override;
    std::size_t purge(std::int64_t notBeforeUnix) override;

private:
    PostgresDatabase& mDb;
};

class PostgresLtiStore final : public LtiStore {
public:
    explicit PostgresLtiStore(PostgresDatabase& db) : mDb(db) {}
    std::optional<std::int64_t> addPlatform(const LtiPlatform& platform) override;
    std::optional<LtiPlatform> platform(std::int64_t id) override;
    std::vector<LtiPlatform> platformsOf(const std::string& issuer) override;
    std::vector<LtiPlatform> listPlatforms() override;
    bool updatePlatform(const LtiPlatform& platform) override;
    bool removePlatform(std::int64_t id) override;
    std::optional<std::int64_t> classOfContext(std::int64_t platformId, const std::string& contextId) override;
    std::int64_t linkContext(std::int64_t platformId, const std::string& contextId, std::int64_t classId) override;
    void setLineItem(std::int64_t platformId, const std::string& url, std::int64_t assignmentId) override;
    std::optional<std::string> lineItemOf(std::int64_t platformId, std::int64_t assignmentId) override;
    std::vector<LtiScoreTarget> scoreTargets(std::int64_t assignmentId, std::int64_t userId) override;
    void addDeepLink(const LtiDeepLinkRequest& request, std::int64_t purgeBeforeUnix) override;
    std::optional<LtiDeepLinkRequest> deepLink(const std::string& key, std::int64_t notBeforeUnix, bool take) override;
    std::int64_t addScore(const LtiScore& score) override;
    std::vector<LtiScore> claimScores(std::int64_t nowUnix, std::int64_t leaseSeconds, std::size_t limit) override;
    bool markDelivered(std::int64_t id, std::int64_t lease, std::int64_t nowUnix) override;
    bool markFailed(std::int64_t id, std::int64_t lease, const std::string& error, std::int64_t nextAttemptAt,
                    bool giveUp) override;
    std::vector<LtiScore> scoresOf(std::int64_t assignmentId) override;

private:
    PostgresDatabase& mDb;
};

} // namespace tlmhub::server
