#include "fmu/runtime/ResourceLocation.h"

#include <cctype>

namespace tlmhub::fmu {
namespace {

int hexValue(char ch)
{
    if (ch >= '0' && ch <= '9') return ch - '0';
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
    return -1;
}

std::optional<std::string> percentDecoded(const std::string& text)
{
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '%') {
            out += text[i];
            continue;
        }
        if (i + 2 >= text.size()) return std::nullopt;
        const int high = hexValue(text[i + 1]), low = hexValue(text[i + 2]);
        if (high < 0 || low < 0) return std::nullopt;
        out += static_cast<char>(high * 16 + low);
        i += 2;
    }
    return out;
}

} // namespace

std::optional<std::string> directoryOfFileUri(const std::string& uri)
{
    const std::string scheme = "file:";
    if (uri.compare(0, scheme.size(), scheme) != 0)
        return std::nullopt;
    std::string rest = uri.substr(scheme.size());
    // file:///dir and file://localhost/dir have an (empty or local) authority; file:/dir none.
    if (rest.compare(0, 2, "//") == 0) {
        const std::size_t slash = rest.find('/', 2);
        if (slash == std::string::npos) return std::nullopt;
        const std::string host = rest.substr(2, slash - 2);
        if (!host.empty() && host != "localhost") return std::nullopt;
        rest = rest.substr(slash);
    }
    std::optional<std::string> path = percentDecoded(rest);
    if (!path || path->empty() || path->front() != '/') return std::nullopt;
    while (path->size() > 1 && path->back() == '/')
        path->pop_back();
    return path;
}

} // namespace tlmhub::fmu
