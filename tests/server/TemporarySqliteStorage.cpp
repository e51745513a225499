#include "TemporarySqliteStorage.h"

#include <cstdlib>
#include <stdexcept>

namespace tlmhub::test {

TemporarySqliteStorage::TemporarySqliteStorage()
{
    std::string pattern = (std::filesystem::temp_directory_path() / "tlmhub-store-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    mDir = pattern;
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
