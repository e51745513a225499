#pragma once
// One WebSocket message as it goes on the wire: text (JSON) or binary (a stream frame a client
// asked to get as float64 columns).
#include <string>

namespace tlmhub::server {

struct OutgoingMessage {
    std::string data;
    bool binary = false;
};

} // namespace tlmhub::server
