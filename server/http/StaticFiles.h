#pragma once
// Serves the built web app: files under a root directory, index.html for any other path
// (the app routes on the client), never anything outside the root.
#include "server/http/HttpTypes.h"

#include <filesystem>

namespace tlmhub::server {

class StaticFiles {
public:
    explicit StaticFiles(std::filesystem::path root);
    Response serve(const Request& request, const std::string& path) const;

private:
    std::filesystem::path mRoot;
};

std::string mimeTypeFor(const std::filesystem::path& file);

} // namespace tlmhub::server
