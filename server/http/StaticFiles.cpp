#include "server/http/StaticFiles.h"

#include "server/http/HttpSession.h"
#include "server/http/Router.h"

#include <fstream>
#include <sstream>

namespace tlmhub::server {

namespace fs = std::filesystem;

StaticFiles::StaticFiles(fs::path root) : mRoot(std::move(root)) {}

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
    fs::path relative;
    for (const std::string& segment : splitPath(path)) {
        if (segment == ".." || segment == "." || segment.find('\0') != std::string::npos)
            return errorResponse(http::status::bad_request, "bad_request", "bad path");
        relative /= segment;
    }
    std::error_code ec;
    fs::path file = mRoot / relative;
    if (relative.empty() || !fs::is_regular_file(file, ec)) file = mRoot / "index.html";
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
            relative.string().rfind("assets/", 0) == 0 ? "public, max-age=31536000, immutable" : "no-cache");
    res.body() = content.str();
    res.prepare_payload();
    return res;
}

} // namespace tlmhub::server
