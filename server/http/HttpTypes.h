#pragma once
// The request and response types every HTTP handler uses (whole bodies as strings).
#include <boost/beast/http.hpp>

#include <chrono>
#include <string>

namespace tlmhub::server {

namespace http = boost::beast::http;
using Request = http::request<http::string_body>;
using Response = http::response<http::string_body>;

// What the transport hands to the application for each request.
struct Incoming {
    const Request& request;
    std::string clientAddress;   // for the login rate limit
    // When the request had been read whole: what a hand-in's time is, however long it waits.
    std::chrono::system_clock::time_point receivedAt = std::chrono::system_clock::now();
};

} // namespace tlmhub::server
