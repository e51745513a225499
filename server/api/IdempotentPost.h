#pragma once
// A POST that creates a job or a study, made safe to retry by an Idempotency-Key header
// (protocol/README.md, "Retrying a submit"). The first request with a key creates; a later
// one with the same key and body, within a day, gets what the first one created; the same key
// with another body is refused (422); while the first one is still being handled, a retry is
// told to come back (503 busy, Retry-After). Without the header, `create` just runs.
#include "server/api/ApiSupport.h"

#include <functional>
#include <optional>

namespace tlmhub::server {

// What `create` made: its response, and the id of the object when it made one.
struct Created {
    Response response;
    std::optional<std::int64_t> id;
};

Response idempotentPost(Services& s, Call& call, const std::string& route, const std::function<Created()>& create,
                        const std::function<Response(std::int64_t id)>& replay);

} // namespace tlmhub::server
