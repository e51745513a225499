#include "server/store/Database.h"

#include <sqlite3.h>

#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <sys/statvfs.h>
#include <unistd.h>

namespace tlmhub::server {

Database::Database(const std::string& path, std::size_t reserveBytes)
    : mSql(path, SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE | SQLite::OPEN_FULLMUTEX),
      mReservePath(path == ":memory:" || reserveBytes == 0 ? "" : path + ".reserve"),
      mReserveBytes(reserveBytes)
{
    // Results are blobs of megabytes: large pages write them in few system calls. Takes
    // effect for a new database only (set before the journal mode).
    mSql.exec("PRAGMA page_size=65536");
    mSql.exec("PRAGMA journal_mode=WAL");
    mSql.exec("PRAGMA synchronous=NORMAL");  // WAL: durable at checkpoints, never corrupt
    mSql.exec("PRAGMA foreign_keys=ON");
    // The WAL shrinks back after checkpoints instead of keeping its largest size.
    mSql.exec("PRAGMA journal_size_limit=16777216");
    mSql.setBusyTimeout(5000);
    restoreReserve();
}

// SQLITE_FULL for a write that found no space; an I/O error too, since growing the WAL
// index (-shm) on a full disk fails as one. Either way one retry after freeing space is safe.
bool Database::isDiskFull(const SQLite::Exception& e)
{
    return (e.getErrorCode() & 0xff) == SQLITE_FULL || (e.getErrorCode() & 0xff) == SQLITE_IOERR;
}

bool Database::releaseReserve()
{
    if (mReservePath.empty()) return false;
    std::error_code ec;
    return std::filesystem::remove(mReservePath, ec);
}

void Database::restoreReserve()
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

long long unixNow()
{
    using namespace std::chrono;
    return duration_cast<seconds>(system_clock::now().time_since_epoch()).count();
}

} // namespace tlmhub::server
