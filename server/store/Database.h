#pragma once
// The server's one SQLite database (embedded, WAL journal). One connection is shared by all
// threads; every store takes mutex() around its statements, so SQLite never sees two
// statements at once and a reader never waits on the file lock of another thread.
#include <SQLiteCpp/Database.h>

#include <mutex>
#include <string>

namespace tlmhub::server {

class Database {
public:
    // Opens (creating if needed) the file at `path`; ":memory:" for tests.
    explicit Database(const std::string& path);

    SQLite::Database& sql() { return mSql; }
    std::mutex& mutex() { return mMutex; }

private:
    SQLite::Database mSql;
    std::mutex mMutex;
};

// Current time as unix seconds, the unit of every timestamp column.
long long unixNow();

} // namespace tlmhub::server
