#include "server/auth/AccessPolicy.h"

namespace tlmhub::server {

bool canRead(const User& who, std::int64_t ownerId, bool isExample)
{
    if (who.role == kRoleAdmin) return true;
    if (who.id == ownerId) return true;
    return isExample;
}

bool canWrite(const User& who, std::int64_t ownerId, bool isExample)
{
    if (who.role == kRoleAdmin) return true;
    if (isExample) return false;   // users duplicate an example to change it
    return who.id == ownerId;
}

bool canControlJob(const User& who, std::int64_t ownerId)
{
    return who.role == kRoleAdmin || who.id == ownerId;
}

// The new job belongs to whoever submits it: only the owner re-runs their own input.
bool canRerunJob(const User& who, std::int64_t ownerId)
{
    return who.id == ownerId;
}

bool isAdministrator(const User& who)
{
    return who.role == kRoleAdmin;
}

bool administersServer(const User& account)
{
    return account.role == kRoleAdmin && !account.disabled;
}

} // namespace tlmhub::server
