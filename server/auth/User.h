#pragma once
// A server account as every layer above the store sees it (never the password hash).
#include <cstdint>
#include <string>

namespace tlmhub::server {

struct User {
    std::int64_t id = 0;
    std::string username;
    std::string role;   // "admin" | "teacher" | "user"
    bool disabled = false;   // by an administrator: cannot log in, sessions end
};

inline constexpr const char* kRoleAdmin = "admin";
inline constexpr const char* kRoleTeacher = "teacher";
inline constexpr const char* kRoleUser = "user";

inline bool isValidRole(const std::string& role)
{
    return role == kRoleAdmin || role == kRoleTeacher || role == kRoleUser;
}

// admin above teacher above user: when several mapped groups give roles, the highest counts.
inline int roleRank(const std::string& role)
{
    return role == kRoleAdmin ? 2 : role == kRoleTeacher ? 1 : 0;
}

} // namespace tlmhub::server
