#pragma once
// A tlmhub server's address as the remote commands take it: http[s]://HOST[:PORT][/PREFIX],
// e.g. a server behind a proxy at https://lab.example.org/tlmhub.
#include <optional>
#include <string>

namespace tlmhub::net {

struct Url {
    bool secure = false;        // https
    std::string host;           // name or address, without IPv6 brackets
    std::string port;           // always set: 80 or 443 when the URL names none
    std::string prefix;         // path before /api/v1, "" or "/tlmhub" (no trailing slash)

    // The URL as a user writes it, without a default port.
    std::string text() const;
    // "host:port", IPv6 in brackets: how messages name the server.
    std::string authority() const;
};

// The URL, or nullopt with `error` saying why. A trailing "/" or "/api/v1" is dropped.
std::optional<Url> parseUrl(const std::string& text, std::string& error);

// `text` with everything but unreserved characters percent-encoded (a query value).
std::string percentEncode(const std::string& text);

} // namespace tlmhub::net
