#pragma once
// Headers every HTTP response carries (SECURITY.md): the page may load its own scripts,
// styles, images and connections only, no page of another site may frame it (but the LTI
// launch page, by the registered platforms), a browser
// never guesses a content type, and no Referer leaves the site.
#include "server/http/HttpTypes.h"

namespace tlmhub::server {

// The policy the app runs under; what it allows beyond 'self' is what the app needs.
extern const char* const kContentSecurityPolicy;
// The same without its frame-ancestors directive, for the LTI launch page, which the
// registered learning platforms may frame.
extern const char* const kContentSecurityPolicyWithoutFrameAncestors;

// Sets the security headers a response does not set itself.
void addSecurityHeaders(Response& response);

} // namespace tlmhub::server
