#include "server/http/StaticFiles.h"

#include "server/http/HttpSession.h"
#include "server/http/Router.h"

#include <fstream>
#include <sstream>

namespace tlmhub::server {

namespace fs = std::filesystem;

namespace {

// The root as an absolute path without links, so resolved files can be compared with it
// (it need not exist yet: the app may be built after the server starts).
fs::path canonicalRoot(const fs::path& root)
{
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(fs::absolute(root, ec), ec);
    return ec ? fs::absolute(root) : canonical;
}

bool refusedSegment(const std::string& segment)
{
    if (segment.empty() || segment.front() == '.') return true;   // ".", "..", dot files
    for (const char c : segment) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '/' || c == '\\' || u < 0x20 || u == 0x7f) return true;
    }
    return false;
}

// Whether `inner` is `root` or below it, comparing whole path elements.
bool isWithin(const fs::path& root, const fs::path& inner)
{
    auto r = root.begin();
    auto i = inner.begin();
    for (; r != root.end(); ++r, ++i) {
        if (r->empty()) continue;   // trailing separator of the root
        if (i == inner.end() || *r != *i) return false;
    }
    return true;
}

} // namespace

StaticFiles::StaticFiles(fs::path root) : mRoot(canonicalRoot(root)) {}

std::optional<fs::path> resolveStaticPath(const fs::path& root, const std::string& path)
{
    if (!path.empty() && path.front() != '/') return std::nullopt;
    fs::path file = root;
    std::size_t pos = 0;
    while (pos < path.size()) {
        const auto slash = path.find('/', pos);
        const std::string raw = path.substr(pos, slash == std::string::npos ? slash : slash - pos);
        pos = slash == std::string::npos ? path.size() : slash + 1;
        if (raw.empty()) continue;
        const std::string segment = percentDecode(raw, false);
        if (refusedSegment(segment)) return std::nullopt;
        file /= segment;
    }
    // Symbolic links inside the root must not lead out of it either.
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(file, ec);
    if (ec || !isWithin(root, resolved)) return std::nullopt;
    return resolved;
}

std::string mimeTypeFor(const fs::path& file)
{
    const std::string ext = file.extension().string();
    if (ext == ".html") return "text/html; charset=utf-8";
    if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
    if (ext == ".css") return "text/css; charset=utf-8";
    if (ext == ".json" || ext == ".map") return "application/json";
    if (ext == ".svg") return "image/svg+xml";
    if (ext == ".png") return "image/png";
    if (ext == ".ico") return "image/x-icon";
    if (ext == ".woff2") return "font/woff2";
    if (ext == ".hmf" || ext == ".xml") return "application/xml";
    return "application/octet-stream";
}

Response StaticFiles::serve(const Request& request, const std::string& path) const
{
    if (request.method() != http::verb::get && request.method() != http::verb::head)
        return errorResponse(http::status::method_not_allowed, "bad_request", "only GET serves files");
    const auto resolved = resolveStaticPath(mRoot, path);
    if (!resolved) return errorResponse(http::status::bad_request, "bad_request", "bad path");
    std::error_code ec;
    fs::path file = *resolved;
    if (!fs::is_regular_file(file, ec)) file = mRoot / "index.html";
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        return errorResponse(http::status::not_found, "not_found",
                             "the web app is not built (no " + (mRoot / "index.html").string() +
                                 "); run `npm ci && npm run build` in web/");
    }
    std::ostringstream content;
    content << in.rdbuf();
    Response res{http::status::ok, request.version()};
    res.set(http::field::content_type, mimeTypeFor(file));
    // Vite puts a content hash in asset names, so those may be cached for long.
    res.set(http::field::cache_control,
            file.parent_path() == mRoot / "assets" ? "public, max-age=31536000, immutable" : "no-cache");
    res.body() = content.str();
    res.prepare_payload();
    return res;
}

} // namespace tlmhub::server
