#include "server/http/HeaderValues.h"

#include <algorithm>

namespace tlmhub::server {

namespace {

// RFC 8187 attr-char: ALPHA / DIGIT / "!#$&+-.^_`|~"; everything else is percent-encoded.
bool isAttrChar(unsigned char c)
{
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) return true;
    return std::string_view("!#$&+-.^_`|~").find(static_cast<char>(c)) != std::string_view::npos;
}

} // namespace

std::string attachmentDisposition(const std::string& filename)
{
    std::string fallback;
    std::string encoded;
    static constexpr char kHex[] = "0123456789ABCDEF";
    for (const char ch : filename) {
        const auto c = static_cast<unsigned char>(ch);
        const bool plain = c >= 0x20 && c < 0x7f && c != '"' && c != '\\' && c != '%';
        fallback += plain ? ch : '_';
        if (isAttrChar(c)) {
            encoded += ch;
        } else {
            encoded += '%';
            encoded += kHex[c >> 4];
            encoded += kHex[c & 0xf];
        }
    }
    return "attachment; filename=\"" + fallback + "\"; filename*=UTF-8''" + encoded;
}

bool isSafeHeaderValue(std::string_view value)
{
    for (const char ch : value) {
        const auto c = static_cast<unsigned char>(ch);
        if ((c < 0x20 && c != '\t') || c == 0x7f) return false;
    }
    return true;
}

bool hasSafeHeaders(const Response& response)
{
    for (const auto& field : response)
        if (!isSafeHeaderValue(field.value()) || !isSafeHeaderValue(field.name_string())) return false;
    return true;
}

std::string requestCookie(const Request& request, std::string_view name)
{
    const std::string cookies(request[http::field::cookie]);
    const std::string prefix = std::string(name) + "=";
    for (std::size_t at = 0; at < cookies.size();) {
        while (at < cookies.size() && (cookies[at] == ' ' || cookies[at] == ';')) ++at;
        const std::size_t end = std::min(cookies.find(';', at), cookies.size());
        if (cookies.compare(at, prefix.size(), prefix) == 0) return cookies.substr(at + prefix.size(), end - at - prefix.size());
        at = end;
    }
    return {};
}

} // namespace tlmhub::server
