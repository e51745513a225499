#include "server/http/Router.h"

#include <cctype>

namespace tlmhub::server {

std::string percentDecode(const std::string& text, bool plusIsSpace)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '+' && plusIsSpace) {
            out += ' ';
        } else if (c == '%' && i + 2 < text.size() &&
                   std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
                   std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
            out += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += c;
        }
    }
    return out;
}

RouteParams parseRequestTarget(const std::string& target)
{
    RouteParams params;
    const auto q = target.find('?');
    params.pathOnly = target.substr(0, q);
    if (q == std::string::npos) return params;
    std::string query = target.substr(q + 1);
    std::size_t pos = 0;
    while (pos <= query.size()) {
        const auto amp = query.find('&', pos);
        const std::string pair = query.substr(pos, amp == std::string::npos ? amp : amp - pos);
        if (!pair.empty()) {
            const auto eq = pair.find('=');
            const std::string key = percentDecode(pair.substr(0, eq), true);
            params.query[key] = eq == std::string::npos ? "" : percentDecode(pair.substr(eq + 1), true);
        }
        if (amp == std::string::npos) break;
        pos = amp + 1;
    }
    return params;
}

std::vector<std::string> splitPath(const std::string& path)
{
    std::vector<std::string> segments;
    std::size_t pos = 0;
    while (pos < path.size()) {
        const auto slash = path.find('/', pos);
        const std::string s = path.substr(pos, slash == std::string::npos ? slash : slash - pos);
        if (!s.empty()) segments.push_back(percentDecode(s, false));
        if (slash == std::string::npos) break;
        pos = slash + 1;
    }
    return segments;
}

} // namespace tlmhub::server
