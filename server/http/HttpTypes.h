#pragma once
// The request and response types every HTTP handler uses (whole bodies as strings).
#include <boost/beast/http.hpp>

#include <string>

namespace tlmhub::server {

namespace http = boost::beast::http;
using Request = http::request<http::string_body>;
using Response = http::response<http::string_body>;

// What the transport hands to the application for each request.
struct Incoming {
    const Request& request;
    std::string clientAddress;   // for the login rate limit
};

} // namespace tlmhub::server
