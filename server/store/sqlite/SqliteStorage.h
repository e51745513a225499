#pragma once
// The embedded back end: one SQLite file in WAL mode (the default, `--data-dir`).
#include "server/store/Storage.h"
#include "server/store/sqlite/SqliteStores.h"

#include <filesystem>
#include <memory>

namespace tlmhub::server {

class SqliteStorage final : public Storage {
public:
    // Opens (creating) the file and migrates it; throws StoreError.
    explicit SqliteStorage(const StorageConfig& config);

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
    void backup(const std::filesystem::path& file) override;

private:
    SqliteDatabase mDb;
    SqliteUserStore mUsers{mDb};
    SqliteSessionStore mSessions{mDb};
    SqliteModelStore mModels{mDb};
    SqliteJobStore mJobs{mDb};
    SqliteJobLeaseStore mJobLeases{mDb};
    SqliteResultStore mResults{mDb};
    SqliteMetaStore mMeta{mDb};
    SqliteIdempotencyKeyStore mIdempotencyKeys{mDb};
    SqliteSignInStore mSignIns{mDb};
    SqliteApiTokenStore mApiTokens{mDb};
    SqliteStudyStore mStudies{mDb};
    SqliteLabStore mLabs{mDb};
    SqliteLtiStore mLti{mDb};
};

// Replaces the database at `databasePath` with the snapshot `backupFile` (written by
// backup()), with the server stopped: checks that the snapshot is a tlmhub database this
// build can migrate, then moves it into place in one rename (the old file is kept as
// `databasePath`.before-restore). Throws StoreError naming what is wrong.
void restoreSqliteBackup(const std::filesystem::path& backupFile, const std::filesystem::path& databasePath);

} // namespace tlmhub::server
