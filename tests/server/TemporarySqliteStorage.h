#pragma once
// Test support: SQLite storage in a fresh temporary directory (removed afterwards), with a
// second, raw connection to the same file for what a test sets up or checks behind the
// stores' backs (rows aged, schema rules).
#include "server/store/Storage.h"

#include <SQLiteCpp/Database.h>

#include <filesystem>
#include <memory>

namespace tlmhub::test {

class TemporarySqliteStorage {
public:
    TemporarySqliteStorage();
    ~TemporarySqliteStorage();
    TemporarySqliteStorage(const TemporarySqliteStorage&) = delete;
    TemporarySqliteStorage& operator=(const TemporarySqliteStorage&) = delete;

    server::Storage& operator*() { return *mStorage; }
    server::Storage* operator->() { return mStorage.get(); }
    const std::filesystem::path& file() const { return mFile; }
    // A connection of its own to the file; writes wait for the stores' writers.
    SQLite::Database& raw();

private:
    std::filesystem::path mDir, mFile;
    std::unique_ptr<server::Storage> mStorage;
    std::unique_ptr<SQLite::Database> mRaw;
};

} // namespace tlmhub::test
