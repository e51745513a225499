// Backing up and restoring the SQLite database (docs/storage.md).
//
// backup() uses VACUUM INTO rather than the online backup API (sqlite3_backup_*): it reads
// the whole database in one read transaction, so the copy is a consistent snapshot while
// writers go on (WAL); it never restarts when another connection writes during the copy,
// as an incremental sqlite3_backup_step does; and it writes a compact file in rollback
// journal mode, one self-contained file without free pages or a -wal beside it. The page
// copy of the backup API would be faster for a database of many gigabytes, but keeps every
// free page a deleted result left.
#include "server/store/sqlite/SqliteStorage.h"

#include <SQLiteCpp/Database.h>
#include <SQLiteCpp/Statement.h>
#include <sqlite3.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <string>
#include <unistd.h>

namespace tlmhub::server {

namespace fs = std::filesystem;

namespace {

const char* const kTlmhubTables[] = {"users", "sessions", "models", "jobs", "job_results", "meta"};

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

StoreError ioError(const std::string& what, const fs::path& file, int err)
{
    return StoreError(err == ENOSPC || err == EDQUOT ? StoreErrc::DiskFull : StoreErrc::Unavailable,
                      what + " " + quoted(file) + ": " + std::strerror(err));
}

// Flushes a file (or a directory, after a rename in it) to the disk, so what a rename makes
// visible is also there after a power cut.
void syncPath(const fs::path& p)
{
    const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw ioError("cannot open", p, errno);
    const int rc = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0) throw ioError("cannot flush", p, err);
}

fs::path directoryOf(const fs::path& file)
{
    return file.has_parent_path() ? file.parent_path() : fs::path(".");
}

void removeQuietly(const fs::path& p)
{
    std::error_code ignored;
    fs::remove(p, ignored);
}

// Checks that `file` is a tlmhub database this build can migrate (an older schema version
// is migrated at the next start).
void checkRestorable(const fs::path& file, const fs::path& shownAs)
{
    try {
        SQLite::Database db(file.string(), SQLite::OPEN_READWRITE);
        SQLite::Statement check(db, "PRAGMA quick_check");
        check.executeStep();
        if (check.getColumn(0).getString() != "ok")
            throw StoreError(StoreErrc::Corrupt, quoted(shownAs) + " is a damaged SQLite database: " +
                                                     check.getColumn(0).getString());
        for (const char* table : kTlmhubTables)
            if (!db.tableExists(table))
                throw StoreError(StoreErrc::Corrupt, quoted(shownAs) + " is an SQLite database but not a "
                                                     "tlmhub one (it has no table " + table + ")");
        // A database from before migrations existed has no schema_migrations: version 0.
        const int version = db.tableExists("schema_migrations")
                                ? db.execAndGet("SELECT COALESCE(MAX(version), 0) FROM schema_migrations").getInt()
                                : 0;
        if (version > kSchemaVersion)
            throw StoreError(StoreErrc::Corrupt, quoted(shownAs) + " is at schema version " +
                                                     std::to_string(version) + ", newer than this server's " +
                                                     std::to_string(kSchemaVersion) + "; restore it with a newer tlmhub-server");
    } catch (const SQLite::Exception& e) {
        throw StoreError(StoreErrc::Corrupt, quoted(shownAs) + " is not a readable SQLite database: " + e.what());
    }
}

// Refuses when a server (or any connection) has `database` open. In WAL mode every open
// connection holds a shared lock on the file, which BEGIN EXCLUSIVE alone does not test
// (in WAL mode it only excludes other writers); in exclusive locking mode the first read
// takes the file's exclusive lock, which fails at once while anyone else holds it. Holding
// the lock, the WAL is checkpointed into the file, so the file kept as .before-restore is
// complete without it. A file SQLite cannot read is no server's database: it is replaced.
void checkpointUnlessInUse(const fs::path& database)
{
    try {
        SQLite::Database db(database.string(), SQLite::OPEN_READWRITE);
        db.setBusyTimeout(0);
        db.exec("PRAGMA locking_mode=EXCLUSIVE");
        db.exec("BEGIN EXCLUSIVE");
        db.exec("COMMIT");
        db.exec("PRAGMA wal_checkpoint(TRUNCATE)");
    } catch (const SQLite::Exception& e) {
        switch (e.getErrorCode() & 0xff) {
        case SQLITE_NOTADB:
        case SQLITE_CORRUPT: return;
        case SQLITE_BUSY:
        case SQLITE_LOCKED:
            throw StoreError(StoreErrc::Busy, "the database " + quoted(database) +
                                                  " is in use (is a tlmhub-server running on it?); "
                                                  "stop the server before restoring");
        default:
            throw StoreError(StoreErrc::Unavailable, "cannot open the current database " + quoted(database) +
                                                         " to replace it: " + e.what());
        }
    }
}

} // namespace

void SqliteStorage::backup(const fs::path& file)
{
    if (fs::exists(file))
        throw StoreError(StoreErrc::Unavailable, "the backup file " + quoted(file) +
                                                     " already exists; choose a new name");
    // Written beside the target and renamed when complete, so the target name never holds a
    // partial file; the process id keeps two backups to one name apart.
    const fs::path partial = file.string() + "." + std::to_string(::getpid()) + ".partial";
    removeQuietly(partial);
    try {
        mDb.run([&](SqliteConnection& c) {
            SQLite::Statement vacuum(c.db(), "VACUUM INTO ?");
            vacuum.bind(1, partial.string());
            vacuum.exec();
        });
        syncPath(partial);
        // RENAME_NOREPLACE: a file made under the target name meanwhile is not replaced.
        if (::renameat2(AT_FDCWD, partial.c_str(), AT_FDCWD, file.c_str(), RENAME_NOREPLACE) != 0)
            throw ioError("cannot rename the backup to", file, errno);
        syncPath(directoryOf(file));
    } catch (const StoreError& e) {
        removeQuietly(partial);
        throw StoreError(e.code(), "backup to " + quoted(file) + " failed: " + e.what());
    }
}

void restoreSqliteBackup(const fs::path& backupFile, const fs::path& databasePath)
{
    std::ifstream in(backupFile, std::ios::binary);
    if (!in || !fs::is_regular_file(backupFile))
        throw StoreError(StoreErrc::Unavailable, "cannot read the backup " + quoted(backupFile));
    char header[16] = {};
    in.read(header, sizeof header);
    if (!in || std::memcmp(header, "SQLite format 3", sizeof header) != 0)
        throw StoreError(StoreErrc::Corrupt, quoted(backupFile) + " is not an SQLite database");
    in.close();

    const fs::path kept = databasePath.string() + ".before-restore";
    if (fs::exists(kept))
        throw StoreError(StoreErrc::Unavailable, quoted(kept) + " (kept by an earlier restore) exists; "
                                                     "move it away first");

    // The snapshot is copied beside the database and checked there: the check opens it (a
    // backup in WAL mode gets a -wal beside it), and the backup itself stays as it was.
    const fs::path incoming = databasePath.string() + ".restoring";
    const auto removeIncoming = [&] {
        for (const char* suffix : {"", "-wal", "-shm", "-journal"}) removeQuietly(incoming.string() + suffix);
    };
    removeIncoming();
    try {
        std::error_code ec;
        if (!fs::copy_file(backupFile, incoming, ec))
            throw ioError("cannot copy the backup to", incoming, ec.value());
        checkRestorable(incoming, backupFile);
        syncPath(incoming);

        const bool hadDatabase = fs::exists(databasePath);
        if (hadDatabase) {
            checkpointUnlessInUse(databasePath);
            // A hard link keeps the old file under its new name, and the rename below swaps
            // the database in one step: at no moment is there no database at the path.
            if (::link(databasePath.c_str(), kept.c_str()) != 0)
                throw ioError("cannot keep the current database as", kept, errno);
        }
        // A -wal or -shm left by the old file would be read as the new one's.
        for (const char* suffix : {"-wal", "-shm"}) removeQuietly(databasePath.string() + suffix);
        if (::rename(incoming.c_str(), databasePath.c_str()) != 0) {
            const int err = errno;
            if (hadDatabase) removeQuietly(kept);   // the old file is still in place
            throw ioError("cannot move the restored database to", databasePath, err);
        }
        syncPath(directoryOf(databasePath));
    } catch (...) {
        removeIncoming();
        throw;
    }
}

} // namespace tlmhub::server
