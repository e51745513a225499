#pragma once
// Small server-wide key/value facts (table meta), e.g. which example files were seeded.
#include "server/store/Database.h"

#include <optional>
#include <string>

namespace tlmhub::server {

class MetaStore {
public:
    explicit MetaStore(Database& db);

    std::optional<std::string> get(const std::string& key);
    void set(const std::string& key, const std::string& value);

private:
    Database& mDb;
};

} // namespace tlmhub::server
