#include "cli/remote/Credentials.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace tlmhub::cli::remote {

namespace {

std::string environment(const char* name)
{
    const char* value = std::getenv(name);
    return value ? value : "";
}

[[noreturn]] void fail(const std::string& what, const std::filesystem::path& path)
{
    throw std::runtime_error(what + " '" + path.string() + "': " + std::strerror(errno));
}

} // namespace

std::filesystem::path credentialsPath()
{
    const std::string config = environment("XDG_CONFIG_HOME");
    if (!config.empty()) return std::filesystem::path(config) / "tlmhub" / "credentials";
    const std::string home = environment("HOME");
    if (home.empty()) throw std::runtime_error("neither XDG_CONFIG_HOME nor HOME is set: nowhere to keep credentials");
    return std::filesystem::path(home) / ".config" / "tlmhub" / "credentials";
}

void saveCredentials(const Credentials& credentials)
{
    const std::filesystem::path path = credentialsPath();
    const std::filesystem::path directory = path.parent_path();
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    if (ec) throw std::runtime_error("cannot create '" + directory.string() + "': " + ec.message());
    if (::chmod(directory.c_str(), 0700) != 0) fail("cannot make private", directory);

    const std::string text = nlohmann::json{{"url", credentials.url}, {"token", credentials.token}}.dump(2) + "\n";
    std::string temporary = (directory / ".credentials.XXXXXX").string();
    const int fd = ::mkstemp(temporary.data());   // mode 0600
    if (fd < 0) fail("cannot create a file in", directory);
    bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    written = ::fsync(fd) == 0 && written;
    written = ::close(fd) == 0 && written;
    if (!written || ::rename(temporary.c_str(), path.c_str()) != 0) {
        const int saved = errno;
        ::unlink(temporary.c_str());
        errno = saved;
        fail("cannot write", path);
    }
}

std::optional<Credentials> loadCredentials(std::string& error)
{
    const std::string url = environment("TLMHUB_URL"), token = environment("TLMHUB_TOKEN");
    if (!url.empty() && !token.empty()) return Credentials{url, token};
    Credentials credentials;
    const std::filesystem::path path = credentialsPath();
    std::ifstream in(path);
    if (in) {
        std::stringstream text;
        text << in.rdbuf();
        const nlohmann::json file = nlohmann::json::parse(text.str(), nullptr, false);
        if (!file.is_object() || !file.value("url", nlohmann::json()).is_string() ||
            !file.value("token", nlohmann::json()).is_string()) {
            error = path.string() + " is not a credentials file ({\"url\", \"token\"}); log in again";
            return std::nullopt;
        }
        credentials.url = file.at("url").get<std::string>();
        credentials.token = file.at("token").get<std::string>();
    }
    if (!url.empty()) credentials.url = url;
    if (!token.empty()) credentials.token = token;
    if (credentials.url.empty() || credentials.token.empty()) {
        error = "not logged in: run 'tlmhub-cli remote login URL' or set TLMHUB_URL and TLMHUB_TOKEN (no " +
                std::string(credentials.url.empty() ? "server URL" : "token") + " in " + path.string() +
                " or the environment)";
        return std::nullopt;
    }
    return credentials;
}

} // namespace tlmhub::cli::remote
