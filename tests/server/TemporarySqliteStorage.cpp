#include "TemporarySqliteStorage.h"

#include "TemporaryDirectory.h"

namespace tlmhub::test {

TemporarySqliteStorage::TemporarySqliteStorage()
{
    mDir = makeTemporaryDirectory("tlmhub-store-");
    mFile = mDir / "tlmhub.sqlite";
    mStorage = server::openStorage(server::StorageConfig{.database = mFile.string(), .reserveBytes = 0});
}

TemporarySqliteStorage::~TemporarySqliteStorage()
{
    mRaw.reset();
    mStorage.reset();
    std::error_code ec;
    std::filesystem::remove_all(mDir, ec);
}

SQLite::Database& TemporarySqliteStorage::raw()
{
    if (!mRaw) {
        mRaw = std::make_unique<SQLite::Database>(mFile.string(), SQLite::OPEN_READWRITE);
        mRaw->setBusyTimeout(10000);
    }
    return *mRaw;
}

} // namespace tlmhub::test
