#include "server/api/IdempotentPost.h"

#include "core/Sha256.h"
#include "server/store/UnixTime.h"

#include <algorithm>

namespace tlmhub::server {

namespace {

constexpr std::size_t kMaxKeyLength = 200;
constexpr std::int64_t kKeyLifetimeSeconds = 24 * 60 * 60;

bool validKey(std::string_view key)
{
    return !key.empty() && key.size() <= kMaxKeyLength &&
           std::all_of(key.begin(), key.end(), [](char c) { return c > ' ' && c < 0x7f; });
}

std::string bodyHash(const std::string& body)
{
    Sha256 sha;
    sha.update(body);
    return sha.hexDigest();
}

} // namespace

Response idempotentPost(Services& s, Call& call, const std::string& route, const std::function<Created()>& create,
                        const std::function<Response(std::int64_t id)>& replay)
{
    const auto header = call.request.find("Idempotency-Key");
    if (header == call.request.end()) return create().response;
    const std::string key(header->value());
    if (!validKey(key))
        return apiError(http::status::bad_request, "bad_request",
                        "Idempotency-Key must be 1 to " + std::to_string(kMaxKeyLength) + " visible ASCII characters");
    const IdempotencyKey use{route, bodyHash(call.request.body()), 0};
    const std::int64_t now = unixNow();
    const auto earlier = s.idempotencyKeys.reserve(call.who().id, key, use, now, now - kKeyLifetimeSeconds);
    if (earlier) {
        if (earlier->route != use.route || earlier->requestHash != use.requestHash)
            return apiError(http::status::unprocessable_entity, "conflict",
                            "this Idempotency-Key was used with another request in the last 24 hours; "
                            "use a new key for a new request");
        if (earlier->objectId == 0) {
            Response busy = apiError(http::status::service_unavailable, "busy",
                                     "the first request with this Idempotency-Key is still being handled");
            busy.set(http::field::retry_after, "1");
            return busy;
        }
        Response again = replay(earlier->objectId);
        again.set("Idempotent-Replayed", "true");
        return again;
    }
    Created created;
    try {
        created = create();
    } catch (...) {
        s.idempotencyKeys.release(call.who().id, key);
        throw;
    }
    if (created.id) s.idempotencyKeys.complete(call.who().id, key, *created.id);
    else s.idempotencyKeys.release(call.who().id, key);
    return created.response;
}

} // namespace tlmhub::server
