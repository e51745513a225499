#pragma once
// One connection to the SQLite file, used by one thread at a time (leased from the pool).
// It keeps every statement it has prepared, so a store prepares each SQL text once per
// connection, not once per call.
#include "server/store/StoreError.h"

#include <SQLiteCpp/Database.h>
#include <SQLiteCpp/Exception.h>
#include <SQLiteCpp/Statement.h>

#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>

namespace tlmhub::server {

class SqliteConnection {
public:
    // Opens `path` (creating it) in WAL mode with a busy timeout, so a writer waits for
    // another instead of failing with SQLITE_BUSY.
    // `syncEveryCommit`: synchronous=FULL rather than NORMAL (see StorageConfig).
    SqliteConnection(const std::string& path, bool syncEveryCommit);

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

private:
    SQLite::Database mDb;
    std::unordered_map<std::string_view, std::unique_ptr<SQLite::Statement>> mStatements;
};

// The StoreError for a failure SQLite reported (disk full, busy, constraint, corrupt, ...).
StoreError toStoreError(const SQLite::Exception& e);
// SQLITE_FULL, or an I/O error (growing the WAL index on a full disk fails as one).
bool isDiskFull(const SQLite::Exception& e);

} // namespace tlmhub::server
