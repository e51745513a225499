// Fuzzes REST requests with bodies (POST, PUT, PATCH under /api/v1) through
// TlmhubApp::handle, authenticated as the admin. An input is
//   <method> <target below /api/v1>\n<content type>\n<body>
// e.g. "POST /models\napplication/json\n{...}". A handler must answer every request with
// a response (no exception), and a JSON response must be JSON.
#include "fuzz/FuzzServer.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    namespace http = tlmhub::server::http;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::string method, target, contentType, body;
    std::getline(in, method, ' ');
    std::getline(in, target);
    std::getline(in, contentType);
    std::getline(in, body, '\0');
    const http::verb verb = http::string_to_verb(method);
    if (verb != http::verb::post && verb != http::verb::put && verb != http::verb::patch) return 0;

    tlmhub::fuzz::FuzzServer& server = tlmhub::fuzz::FuzzServer::instance();
    tlmhub::server::Request request{verb, "/api/v1" + target, 11};
    try {
        request.set(http::field::authorization, "Bearer " + server.token());
        request.set(http::field::content_type, contentType);
    } catch (const std::exception&) {
        return 0;   // a header over Beast's 64 KiB field limit: the transport refuses it
    }
    request.body() = body;
    request.prepare_payload();

    const tlmhub::server::Response response = server.handle(request);
    if (std::string(response[http::field::content_type]).rfind("application/json", 0) == 0 &&
        nlohmann::json::parse(response.body(), nullptr, false).is_discarded())
        tlmhub::fuzz::fail("JSON response that is not JSON: " + response.body());
    return 0;
}
