#pragma once
// The SQLite back end's access to its file: a pool of connections (one per thread that is
// using the database at the moment), each store call run on one of them with SQLite's
// exceptions turned into StoreError.
//
// Beside the file the database keeps a reserve: a file of a few MiB that is given back to
// the file system when the disk is full, so logging in and deleting (the way to free space)
// still work; it is made again once there is room.
#include "server/store/ConnectionPool.h"
#include "server/store/Storage.h"
#include "server/store/sqlite/SqliteConnection.h"

#include <cstddef>
#include <string>

namespace tlmhub::server {

class SqliteDatabase {
public:
    // ":memory:" is one private database, so it gets one connection (a second would be a
    // second, empty database) and no reserve.
    explicit SqliteDatabase(const StorageConfig& config);

    const std::string& path() const { return mPath; }

    // Runs `work(SqliteConnection&)` on a leased connection.
    template <typename Work>
    auto run(Work&& work) -> decltype(work(std::declval<SqliteConnection&>()))
    {
        auto lease = acquire();
        try {
            return work(*lease);
        } catch (const SQLite::Exception& e) {
            throw toStoreError(e);
        }
    }
    // The same, for writes that free space or let a user in: if the disk is full, gives the
    // reserve back and runs `work` once more.
    template <typename Work>
    auto runFreeingSpace(Work&& work) -> decltype(work(std::declval<SqliteConnection&>()))
    {
        auto lease = acquire();
        try {
            try {
                return work(*lease);
            } catch (const SQLite::Exception& e) {
                if (!isDiskFull(e) || !releaseReserve()) throw;
            }
            return work(*lease);
        } catch (const SQLite::Exception& e) {
            throw toStoreError(e);
        }
    }

    // Makes the reserve again when the disk has room for it and more; call after deleting.
    void restoreReserve();

private:
    ConnectionPool<SqliteConnection>::Lease acquire();
    bool releaseReserve();

    std::string mPath;
    ConnectionPool<SqliteConnection> mPool;
    std::string mReservePath;   // empty: no reserve
    std::size_t mReserveBytes;
};

} // namespace tlmhub::server
