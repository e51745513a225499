#pragma once
// Reading the members of the JSON documents providers send, where a missing member and one of
// the wrong type mean the same: not given.
#include <nlohmann/json.hpp>

#include <string>

namespace tlmhub::server {

// The member's text; "" when it is missing or not a string.
std::string stringMember(const nlohmann::json& object, const char* name);

} // namespace tlmhub::server
