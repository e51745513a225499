#pragma once
// The server's one SQLite database (embedded, WAL journal). One connection is shared by all
// threads; every store takes mutex() around its statements, so SQLite never sees two
// statements at once and a reader never waits on the file lock of another thread.
//
// Beside the file the database keeps a reserve: a file of a few MiB that is given back to
// the file system when the disk is full, so logging in and deleting (the way to free space)
// still work; it is made again once there is room.
#include <SQLiteCpp/Database.h>
#include <SQLiteCpp/Exception.h>

#include <cstddef>
#include <mutex>
#include <string>

namespace tlmhub::server {

class Database {
public:
    // Opens (creating if needed) the file at `path`; ":memory:" for tests (no reserve).
    explicit Database(const std::string& path, std::size_t reserveBytes = kDefaultReserveBytes);

    SQLite::Database& sql() { return mSql; }
    std::mutex& mutex() { return mMutex; }

    // Runs `write` (under mutex(), taken by the caller); if the disk is full, gives the
    // reserve back and runs it once more. For writes that free space or let a user in.
    template <typename Write>
    auto freeingSpace(Write&& write) -> decltype(write())
    {
        try {
            return write();
        } catch (const SQLite::Exception& e) {
            if (!isDiskFull(e) || !releaseReserve()) throw;
        }
        return write();
    }
    // Makes the reserve again when the disk has room for it and more; call after deleting.
    void restoreReserve();

    static bool isDiskFull(const SQLite::Exception& e);
    static constexpr std::size_t kDefaultReserveBytes = 8u << 20;

private:
    bool releaseReserve();

    SQLite::Database mSql;
    std::mutex mMutex;
    std::string mReservePath;   // empty: no reserve
    std::size_t mReserveBytes;
};

// Current time as unix seconds, the unit of every timestamp column.
long long unixNow();

} // namespace tlmhub::server
