#include "server/store/Database.h"

#include <chrono>

namespace tlmhub::server {

Database::Database(const std::string& path)
    : mSql(path, SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE | SQLite::OPEN_FULLMUTEX)
{
    // Results are blobs of megabytes: large pages write them in few system calls. Takes
    // effect for a new database only (set before the journal mode).
    mSql.exec("PRAGMA page_size=65536");
    mSql.exec("PRAGMA journal_mode=WAL");
    mSql.exec("PRAGMA synchronous=NORMAL");  // WAL: durable at checkpoints, never corrupt
    mSql.exec("PRAGMA foreign_keys=ON");
    mSql.setBusyTimeout(5000);
}

long long unixNow()
{
    using namespace std::chrono;
    return duration_cast<seconds>(system_clock::now().time_since_epoch()).count();
}

} // namespace tlmhub::server
