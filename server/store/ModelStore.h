#pragma once
// Saved models (table models): the .hmf text as the user last saved it, plus who owns it and
// whether it is an example. The text is stored verbatim; loading and validating it is the
// caller's business, so the store works without the core.
#include "server/auth/User.h"
#include "server/store/Database.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

struct ModelSummary {
    std::int64_t id = 0;
    std::string name;
    std::int64_t ownerId = 0;
    std::string ownerName, ownerRole;
    bool isExample = false;
    std::int64_t createdAt = 0, updatedAt = 0;   // unix seconds
};

class ModelStore {
public:
    // Needs the users table (owners), so construct after UserStore.
    explicit ModelStore(Database& db);

    // Returns the new id. Names need not be unique.
    std::int64_t create(std::int64_t ownerId, const std::string& name, const std::string& hmf,
                        bool isExample);
    std::optional<ModelSummary> summary(std::int64_t id);
    std::optional<std::string> hmf(std::int64_t id);
    // Changes the given fields and touches updated_at; false when the model does not exist.
    bool update(std::int64_t id, const std::optional<std::string>& name,
                const std::optional<std::string>& hmf);
    bool remove(std::int64_t id);
    // Every model `who` may read (AccessPolicy::canRead), by id.
    std::vector<ModelSummary> listVisibleTo(const User& who);

    Database& database() { return mDb; }

private:
    Database& mDb;
};

} // namespace tlmhub::server
