#pragma once
// Saved models (table models): the .hmf text as the user last saved it, plus who owns it and
// whether it is an example. The text is stored verbatim; loading and validating it is the
// caller's business, so the store works without the core.
#include "server/auth/User.h"

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
    virtual ~ModelStore() = default;

    // Returns the new id; nullopt when `ownerId` names no account. Names need not be unique.
    virtual std::optional<std::int64_t> create(std::int64_t ownerId, const std::string& name,
                                               const std::string& hmf, bool isExample) = 0;
    virtual std::optional<ModelSummary> summary(std::int64_t id) = 0;
    virtual std::optional<std::string> hmf(std::int64_t id) = 0;
    // Changes the given fields and touches updated_at; false when the model does not exist.
    virtual bool update(std::int64_t id, const std::optional<std::string>& name,
                        const std::optional<std::string>& hmf) = 0;
    // Works on a full disk too (deleting is how space is freed).
    virtual bool remove(std::int64_t id) = 0;
    virtual std::vector<ModelSummary> list() = 0;   // by id

    // Every model `who` may read (AccessPolicy::canRead), by id. The rule has one home, the
    // policy, rather than one SQL text per back end.
    std::vector<ModelSummary> listVisibleTo(const User& who);
};

} // namespace tlmhub::server
