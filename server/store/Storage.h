#pragma once
// The server's storage: one object per back end that hands out the stores of every aggregate
// (users, sessions, models, jobs and their leases, results, meta facts, API tokens, studies, teaching labs,
// sign-ins through a provider, the learning platforms tlmhub is an LTI tool of).
// Opening it applies the schema migrations the database lacks, so every store finds the
// current schema.
// No SQLite or PostgreSQL type appears in this header or in any store interface; the back
// ends live in server/store/sqlite/ and server/store/postgres/.
//
// Every store method may be called from any thread at the same time.
#include "server/store/ApiTokenStore.h"
#include "server/store/JobLeaseStore.h"
#include "server/store/IdempotencyKeyStore.h"
#include "server/store/JobStore.h"
#include "server/store/LabStore.h"
#include "server/store/LtiStore.h"
#include "server/store/MetaStore.h"
#include "server/store/ModelStore.h"
#include "server/store/ResultStore.h"
#include "server/store/SessionStore.h"
#include "server/store/SignInStore.h"
#include "server/store/StoreError.h"
#include "server/store/StudyStore.h"
#include "server/store/UserStore.h"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

namespace tlmhub::server {

struct StorageConfig {
    // "postgresql://user@host:port/db" (or "postgres://..."): PostgreSQL. Anything else is the
    // path of an SQLite file; ":memory:" is a private in-memory database (tests).
    std::string database;
    // Connections the back end opens at most (SQLite: about one per thread that uses it).
    unsigned maxConnections = 16;
    // SQLite: bytes kept in a reserve file beside the database, given back when the disk is
    // full so logging in and deleting still work. 0: none.
    std::size_t reserveBytes = 8u << 20;
    // SQLite: flush the WAL to disk at every commit (synchronous=FULL). Off, it is flushed at
    // checkpoints: a power cut may lose the last commits, never corrupt the file. PostgreSQL
    // flushes every commit in any case (its server's fsync settings decide).
    bool syncEveryCommit = false;
};

class Storage {
public:
    virtual ~Storage() = default;

    virtual UserStore& users() = 0;
    virtual SessionStore& sessions() = 0;
    virtual ModelStore& models() = 0;
    virtual JobStore& jobs() = 0;
    virtual JobLeaseStore& jobLeases() = 0;
    virtual ResultStore& results() = 0;
    virtual MetaStore& meta() = 0;
    virtual IdempotencyKeyStore& idempotencyKeys() = 0;
    virtual ApiTokenStore& apiTokens() = 0;
    virtual StudyStore& studies() = 0;
    virtual LabStore& labs() = 0;
    virtual SignInStore& signIns() = 0;
    virtual LtiStore& lti() = 0;

    // The schema version the database is at (the newest migration applied).
    virtual int schemaVersion() = 0;
    // "SQLite /path/tlmhub.sqlite" or "PostgreSQL tlmhub@host:port/db", for logs.
    virtual std::string describe() const = 0;
    // Writes a consistent snapshot of the whole database to `file` (a new file) while the
    // server keeps running. Throws StoreError when the back end cannot (PostgreSQL: use
    // pg_dump, see docs/storage.md).
    virtual void backup(const std::filesystem::path& file) = 0;
};

// The newest schema version this build knows. Both back ends keep their migrations in an
// array of this size, so a migration added to one and not the other does not compile.
inline constexpr int kSchemaVersion = 12;

// Opens the back end `config.database` names and migrates its schema. Throws StoreError
// (Unavailable when it cannot be reached or opened, Corrupt when its schema is newer than
// this build's).
std::unique_ptr<Storage> openStorage(const StorageConfig& config);

bool isPostgresUri(const std::string& database);

// The error for a database at schema `version`, newer than kSchemaVersion: this build does not
// know that schema, so it must not write it.
StoreError schemaNewerThanThisServer(int version);

} // namespace tlmhub::server
