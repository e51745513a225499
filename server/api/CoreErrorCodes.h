#pragma once
// The one place where the core's status codes become the protocol's error codes
// (protocol/messages.schema.json, ErrorCode).
#include "core/Status.h"

namespace tlmhub::server {

const char* protocolErrorCode(StatusCode code);

} // namespace tlmhub::server
