#include "server/auth/AccessPolicy.h"

namespace tlmhub::server {

bool canRead(const User& who, std::int64_t ownerId, const std::string& ownerRole, bool isExample)
{
    if (who.role == kRoleAdmin) return true;
    if (who.id == ownerId) return true;
    if (isExample) return true;
    return who.role == kRoleTeacher && ownerRole == kRoleUser;
}

bool canWrite(const User& who, std::int64_t ownerId, bool isExample)
{
    if (who.role == kRoleAdmin) return true;
    if (isExample) return false;   // users duplicate an example to change it
    return who.id == ownerId;
}

} // namespace tlmhub::server
