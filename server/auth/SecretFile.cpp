#include "server/auth/SecretFile.h"

#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tlmhub::server {

std::string readSecretFile(const std::filesystem::path& path, const std::string& what)
{
    const std::string where = what + " " + path.string();
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) throw std::runtime_error(where + ": cannot be read");
    if ((info.st_mode & (S_IRGRP | S_IROTH)) != 0) {
        std::ostringstream mode;
        mode << std::oct << (info.st_mode & 0777);
        throw std::runtime_error(where + " can be read by group or others (mode 0" + mode.str() +
                                 "); make it private: chmod 600 " + path.string());
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(where + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    std::string secret = text.str();
    if (!secret.empty() && secret.back() == '\n') secret.pop_back();
    if (!secret.empty() && secret.back() == '\r') secret.pop_back();
    return secret;
}

} // namespace tlmhub::server
