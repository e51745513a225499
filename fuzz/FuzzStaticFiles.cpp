// Fuzzes static file serving (StaticFiles::serve) with request targets as the transport
// hands them over (parseRequestTarget, as TlmhubApp does). The web root holds index.html and
// assets/app.js; beside the root lies a sentinel file, and a body with the sentinel's
// content means a file outside the root was served.
#include "fuzz/FuzzServer.h"
#include "server/http/Router.h"
#include "server/http/StaticFiles.h"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
const std::string kSentinel = "SENTINEL-outside-the-web-root";

void write(const fs::path& file, const std::string& text)
{
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
}

struct WebRoot {
    tlmhub::fuzz::TempDir dir;
    tlmhub::server::StaticFiles files{dir.path() / "web"};
    WebRoot()
    {
        write(dir.path() / "web" / "index.html", "<html>index</html>");
        write(dir.path() / "web" / "assets" / "app.js", "console.log('app')");
        write(dir.path() / "secret.txt", kSentinel);
        write(dir.path() / "web-secret" / "index.html", kSentinel);   // a sibling sharing the prefix
    }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    namespace http = tlmhub::server::http;
    static WebRoot root;
    const std::string target(reinterpret_cast<const char*>(data), size);
    const tlmhub::server::Request request{http::verb::get, target, 11};
    const std::string path = tlmhub::server::parseRequestTarget(target).pathOnly;
    const tlmhub::server::Response response = root.files.serve(request, path);
    if (response.body().find(kSentinel) != std::string::npos)
        tlmhub::fuzz::fail("served a file outside the web root for target '" + target + "'");
    return 0;
}
