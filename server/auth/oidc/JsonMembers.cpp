#include "server/auth/oidc/JsonMembers.h"

namespace tlmhub::server {

std::string stringMember(const nlohmann::json& object, const char* name)
{
    const auto it = object.find(name);
    return it != object.end() && it->is_string() ? it->get<std::string>() : std::string{};
}

} // namespace tlmhub::server
