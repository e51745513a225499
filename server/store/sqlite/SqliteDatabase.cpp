#include "server/store/sqlite/SqliteDatabase.h"

#include <fcntl.h>
#include <filesystem>
#include <sys/statvfs.h>
#include <unistd.h>

namespace tlmhub::server {

SqliteDatabase::SqliteDatabase(const StorageConfig& config)
    : mPath(config.database),
      mPool([path = config.database, sync = config.syncEveryCommit] { return std::make_unique<SqliteConnection>(path, sync); },
            config.database == ":memory:" ? 1 : config.maxConnections),
      mReservePath(config.database == ":memory:" || config.reserveBytes == 0 ? "" : config.database + ".reserve"),
      mReserveBytes(config.reserveBytes)
{
    restoreReserve();
}

ConnectionPool<SqliteConnection>::Lease SqliteDatabase::acquire()
{
    try {
        return mPool.acquire();
    } catch (const SQLite::Exception& e) {
        throw StoreError(isDiskFull(e) ? StoreErrc::DiskFull : StoreErrc::Unavailable,
                         "cannot open the SQLite database " + mPath + ": " + e.what());
    }
}

bool SqliteDatabase::releaseReserve()
{
    if (mReservePath.empty()) return false;
    std::error_code ec;
    return std::filesystem::remove(mReservePath, ec);
}

void SqliteDatabase::restoreReserve()
{
    if (mReservePath.empty()) return;
    std::error_code ec;
    if (std::filesystem::file_size(mReservePath, ec) == mReserveBytes) return;
    const auto parent = std::filesystem::path(mReservePath).parent_path();
    struct statvfs fs {};
    if (::statvfs(parent.empty() ? "." : parent.c_str(), &fs) != 0) return;
    const unsigned long long available = static_cast<unsigned long long>(fs.f_bavail) * fs.f_frsize;
    if (available < 2ull * mReserveBytes) return;   // leave the room to the data for now
    const int fd = ::open(mReservePath.c_str(), O_WRONLY | O_CREAT, 0600);
    if (fd < 0) return;
    const bool made = ::posix_fallocate(fd, 0, static_cast<off_t>(mReserveBytes)) == 0;
    ::close(fd);
    if (!made) std::filesystem::remove(mReservePath, ec);
}

} // namespace tlmhub::server
