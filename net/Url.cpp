#include "net/Url.h"

#include <cctype>
#include <cstdio>

namespace tlmhub::net {

namespace {

bool defaultPort(const Url& url) { return url.port == (url.secure ? "443" : "80"); }

// An IPv6 address in brackets, as URLs and Host headers write it.
std::string hostText(const std::string& host)
{
    return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

bool validPort(const std::string& port)
{
    if (port.empty() || port.size() > 5) return false;
    for (char c : port)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    const int value = std::stoi(port);
    return value >= 1 && value <= 65535;
}

} // namespace

std::string Url::authority() const
{
    return hostText(host) + ":" + port;
}

std::string Url::text() const
{
    return (secure ? "https://" : "http://") + hostText(host) + (defaultPort(*this) ? "" : ":" + port) + prefix;
}

std::optional<Url> parseUrl(const std::string& text, std::string& error)
{
    Url url;
    std::string rest;
    if (text.rfind("https://", 0) == 0) {
        url.secure = true;
        rest = text.substr(8);
    } else if (text.rfind("http://", 0) == 0) {
        rest = text.substr(7);
    } else {
        error = "the server URL must start with http:// or https://, got '" + text + "'";
        return std::nullopt;
    }
    const std::size_t slash = rest.find('/');
    std::string authority = rest.substr(0, slash);
    url.prefix = slash == std::string::npos ? "" : rest.substr(slash);
    if (url.prefix.find_first_of("?#") != std::string::npos) {
        error = "the server URL cannot have a query or fragment: '" + text + "'";
        return std::nullopt;
    }
    while (!url.prefix.empty() && url.prefix.back() == '/') url.prefix.pop_back();
    const std::string api = "/api/v1";
    if (url.prefix.size() >= api.size() && url.prefix.compare(url.prefix.size() - api.size(), api.size(), api) == 0)
        url.prefix.erase(url.prefix.size() - api.size());

    std::string port;
    if (!authority.empty() && authority.front() == '[') {
        const std::size_t close = authority.find(']');
        if (close == std::string::npos) {
            error = "unbalanced '[' in the server URL '" + text + "'";
            return std::nullopt;
        }
        url.host = authority.substr(1, close - 1);
        if (close + 1 < authority.size()) {
            if (authority[close + 1] != ':') {
                error = "unexpected text after ']' in the server URL '" + text + "'";
                return std::nullopt;
            }
            port = authority.substr(close + 2);
        }
    } else {
        const std::size_t colon = authority.find(':');
        url.host = authority.substr(0, colon);
        if (colon != std::string::npos) port = authority.substr(colon + 1);
    }
    if (url.host.empty() || authority.find('@') != std::string::npos) {
        error = "the server URL needs a host (and no user name): '" + text + "'";
        return std::nullopt;
    }
    url.port = port.empty() ? (url.secure ? "443" : "80") : port;
    if (!validPort(url.port)) {
        error = "bad port '" + port + "' in the server URL '" + text + "'";
        return std::nullopt;
    }
    return url;
}

std::string percentEncode(const std::string& text)
{
    std::string out;
    for (unsigned char c : text) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
            out += static_cast<char>(c);
        } else {
            char hex[4];
            std::snprintf(hex, sizeof hex, "%%%02X", c);
            out += hex;
        }
    }
    return out;
}

} // namespace tlmhub::net
