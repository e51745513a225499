#include "server/store/sqlite/SqliteConnection.h"

#include <sqlite3.h>

#include <thread>

namespace tlmhub::server {

SqliteConnection::SqliteConnection(const std::string& path, bool syncEveryCommit)
    : mDb(path, SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE | SQLite::OPEN_NOMUTEX)
{
    // Before anything else: a writer on another connection makes this one wait, not fail.
    sqlite3_busy_handler(mDb.getHandle(), &SqliteConnection::retryWhileBusy, this);
    // Results are blobs of megabytes: large pages write them in few system calls. Takes
    // effect for a new database only (set before the journal mode).
    mDb.exec("PRAGMA page_size=65536");
    mDb.exec("PRAGMA journal_mode=WAL");
    mDb.exec(syncEveryCommit ? "PRAGMA synchronous=FULL" : "PRAGMA synchronous=NORMAL");
    mDb.exec("PRAGMA foreign_keys=ON");
    // The WAL shrinks back after checkpoints instead of keeping its largest size.
    mDb.exec("PRAGMA journal_size_limit=16777216");
}

std::chrono::microseconds SqliteConnection::busyRetryDelay(int attempt)
{
    return std::chrono::microseconds(attempt < 10 ? 100 : 1000);
}

int SqliteConnection::retryWhileBusy(void* connection, int attempt)
{
    auto& self = *static_cast<SqliteConnection*>(connection);
    const auto now = std::chrono::steady_clock::now();
    if (attempt == 0) self.mBusySince = now;
    if (now - self.mBusySince >= std::chrono::milliseconds(kBusyTimeoutMs)) return 0;
    std::this_thread::sleep_for(busyRetryDelay(attempt));
    return 1;
}

SqliteConnection::Statement SqliteConnection::prepared(const char* sql)
{
    auto& slot = mStatements[sql];
    if (!slot) slot = std::make_unique<SQLite::Statement>(mDb, sql);
    return Statement(*slot);
}

bool isDiskFull(const SQLite::Exception& e)
{
    const int primary = e.getErrorCode() & 0xff;
    return primary == SQLITE_FULL || primary == SQLITE_IOERR;
}

StoreError toStoreError(const SQLite::Exception& e)
{
    const std::string what = std::string("SQLite: ") + e.what();
    if (isDiskFull(e)) return StoreError(StoreErrc::DiskFull, what);
    switch (e.getErrorCode() & 0xff) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED: return StoreError(StoreErrc::Busy, what);
    case SQLITE_CONSTRAINT: return StoreError(StoreErrc::Constraint, what);
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB: return StoreError(StoreErrc::Corrupt, what);
    case SQLITE_CANTOPEN:
    case SQLITE_PERM:
    case SQLITE_READONLY: return StoreError(StoreErrc::Unavailable, what);
    default: return StoreError(StoreErrc::Internal, what);
    }
}

} // namespace tlmhub::server
