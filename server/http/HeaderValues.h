#pragma once
// Values that go into response headers, and a cookie read from a request. Anything a user chose
// (a model's name in a download) is encoded here, so no header can carry a line break or a quote
// that ends it early.
#include "server/http/HttpTypes.h"

#include <string>
#include <string_view>

namespace tlmhub::server {

// `Content-Disposition: attachment` for a download named `filename` (UTF-8), per RFC 6266:
// an ASCII fallback `filename="..."` and the exact name as `filename*=UTF-8''...` (RFC 8187).
std::string attachmentDisposition(const std::string& filename);

// The value of cookie `name` in the request's Cookie header; "" without one.
std::string requestCookie(const Request& request, std::string_view name);

// No CR, LF, NUL or other control character but tab: the value cannot split the header.
bool isSafeHeaderValue(std::string_view value);
// Whether every header of `response` is safe (the transport refuses to send one that is not).
bool hasSafeHeaders(const Response& response);

} // namespace tlmhub::server
