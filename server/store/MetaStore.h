#pragma once
// Small server-wide key/value facts (table meta), e.g. which example files were seeded.
#include <optional>
#include <string>

namespace tlmhub::server {

class MetaStore {
public:
    virtual ~MetaStore() = default;

    virtual std::optional<std::string> get(const std::string& key) = 0;
    virtual void set(const std::string& key, const std::string& value) = 0;
    // Adds the key unless it is there: true when this call added it. Of nodes starting at
    // once on one database, exactly one gets true.
    virtual bool insertIfAbsent(const std::string& key, const std::string& value) = 0;
};

} // namespace tlmhub::server
