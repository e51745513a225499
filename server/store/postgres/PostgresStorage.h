#pragma once
// The back end for several server nodes on one database: PostgreSQL (`--database
// postgresql://user@host:port/db`).
#include "server/store/Storage.h"
#include "server/store/postgres/PostgresStores.h"

#include <filesystem>
#include <memory>

namespace tlmhub::server {

class PostgresStorage final : public Storage {
public:
    // Connects and migrates the schema; throws StoreError (Unavailable naming the server when
    // it cannot be reached).
    explicit PostgresStorage(const StorageConfig& config);

    UserStore& users() override { return mUsers; }
    SessionStore& sessions() override { return mSessions; }
    ModelStore& models() override { return mModels; }
    JobStore& jobs() override { return mJobs; }
    JobLeaseStore& jobLeases() override { return mJobLeases; }
    ResultStore& results() override { return mResults; }
    MetaStore& meta() override { return mMeta; }
    IdempotencyKeyStore& idempotencyKeys() override { return mIdempotencyKeys; }
    SignInStore& signIns() override { return mSignIns; }
    ApiTokenStore& apiTokens() override { return mApiTokens; }
    StudyStore& studies() override { return mStudies; }
    LabStore& labs() override { return mLabs; }
    LtiStore& lti() override { return mLti; }
    int schemaVersion() override;
    std::string describe() const override;
    // Always throws: a PostgreSQL database is backed up with pg_dump.
    void backup(const std::filesystem::path& file) override;

private:
    PostgresDatabase mDb;
    PostgresUserStore mUsers{mDb};
    PostgresSessionStore mSessions{mDb};
    PostgresModelStore mModels{mDb};
    PostgresJobStore mJobs{mDb};
    PostgresJobLeaseStore mJobLeases{mDb};
    PostgresResultStore mResults{mDb};
    PostgresMetaStore mMeta{mDb};
    PostgresIdempotencyKeyStore mIdempotencyKeys{mDb};
    PostgresSignInStore mSignIns{mDb};
    PostgresApiTokenStore mApiTokens{mDb};
    PostgresStudyStore mStudies{mDb};
    PostgresLabStore mLabs{mDb};
    PostgresLtiStore mLti{mDb};
};

std::unique_ptr<Storage> openPostgresStorage(const StorageConfig& config);

} // namespace tlmhub::server
