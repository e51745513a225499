#pragma once
// Serves the built web app: files under a root directory, index.html for any other path
// (the app routes on the client), never anything outside the root.
#include "server/http/HttpTypes.h"

#include <filesystem>
#include <optional>

namespace tlmhub::server {

class StaticFiles {
public:
    explicit StaticFiles(std::filesystem::path root);
    // `path` is the request target without its query, still percent-encoded.
    Response serve(const Request& request, const std::string& path) const;

private:
    std::filesystem::path mRoot;   // absolute, without links
};

// The file a request path names inside `root` (absolute, without links), or nullopt when
// the path is refused: a segment that decodes to "." or "..", or that holds a slash, a
// backslash, NUL or another control character, or that starts with '.', or a result that
// resolves (through symbolic links too) outside the root. An empty path gives `root`.
std::optional<std::filesystem::path> resolveStaticPath(const std::filesystem::path& root,
                                                       const std::string& path);

std::string mimeTypeFor(const std::filesystem::path& file);

} // namespace tlmhub::server
