#pragma once
// Secrets the administrator gives the server in files (the nodes' shared secret, an LDAP
// service account's password): readable by the server's own user only, read once at start.
#include <filesystem>
#include <string>

namespace tlmhub::server {

// The file's text without one trailing newline (editors and `echo` end files with one).
// Throws std::runtime_error naming `what` and the file when it cannot be read, or when its
// group or others may read it (with the chmod that fixes it).
std::string readSecretFile(const std::filesystem::path& path, const std::string& what);

} // namespace tlmhub::server
