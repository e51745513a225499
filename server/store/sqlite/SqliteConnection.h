#pragma once
// One connection to the SQLite file, used by one thread at a time (leased from the pool).
// It keeps every statement it has prepared, so a store prepares each SQL text once per
// connection, not once per call.
#include "server/store/StoreError.h"

#include <SQLiteCpp/Database.h>
#include <SQLiteCpp/Exception.h>
#include <SQLiteCpp/Statement.h>

#include <chrono>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>

namespace tlmhub::server {

class SqliteConnection {
public:
    // Opens `path` (creating it) in WAL mode with a busy handler, so a writer waits for
    // another (up to kBusyTimeoutMs) instead of failing with SQLITE_BUSY.
    // `syncEveryCommit`: synchronous=FULL rather than NORMAL (see StorageConfig).
    SqliteConnection(const std::string& path, bool syncEveryCommit);
    // The busy handler keeps a pointer to the connection.
    SqliteConnection(const SqliteConnection&) = delete;
    SqliteConnection& operator=(const SqliteConnection&) = delete;

    SQLite::Database& db() { return mDb; }

    // A statement of this connection, prepared on first use; reset and unbound when the
    // handle goes. `sql` must be a string literal (the cache keeps a view of it).
    class Statement {
    public:
        explicit Statement(SQLite::Statement& s) : mStatement(s) {}
        ~Statement()
        {
            // tryReset: reset() repeats the last step's error (e.g. a constraint), which was
            // already thrown. sqlite3_clear_bindings cannot fail.
            mStatement.tryReset();
            mStatement.clearBindings();
        }
        Statement(const Statement&) = delete;
        Statement& operator=(const Statement&) = delete;
        SQLite::Statement* operator->() { return &mStatement; }
        SQLite::Statement& operator*() { return mStatement; }

    private:
        SQLite::Statement& mStatement;
    };
    Statement prepared(const char* sql);

    static constexpr int kBusyTimeoutMs = 10000;
    // How long a writer that found the database locked sleeps before its `attempt`-th next
    // try: 0.1 ms at first (most writes hold the lock for well under a millisecond), then
    // 1 ms. SQLite's own handler (sqlite3_busy_timeout) sleeps 1, 2, 5, ... 25, 50, 100 ms, so
    // a writer went on up to that long after the lock was free: in a lab of 40 students
    // starting runs at once, job inserts slept up to 25 ms at a time, 78 ms in all.
    static std::chrono::microseconds busyRetryDelay(int attempt);
    // The busy handler: sleeps busyRetryDelay and tries again (1) until kBusyTimeoutMs have
    // passed since the first try of this wait, then gives up (0: SQLITE_BUSY).
    static int retryWhileBusy(void* connection, int attempt);

private:
    SQLite::Database mDb;
    std::chrono::steady_clock::time_point mBusySince;
    std::unordered_map<std::string_view, std::unique_ptr<SQLite::Statement>> mStatements;
};

// The StoreError for a failure SQLite reported (disk full, busy, constraint, corrupt, ...).
StoreError toStoreError(const SQLite::Exception& e);
// SQLITE_FULL, or an I/O error (growing the WAL index on a full disk fails as one).
bool isDiskFull(const SQLite::Exception& e);

} // namespace tlmhub::server
