#pragma once
// Idempotency keys (table idempotency_keys): a script that retries a POST /jobs or POST
// /studies after a lost reply sends the same Idempotency-Key header, and gets the job or
// study its first attempt made instead of a second one. A key is its owner's for a day.
//
// A request reserves its key before it creates anything and completes the reservation with
// what it made; a second request with the key finds the reservation (still pending, or done
// with the object's id), so two attempts racing on any nodes make one object.
#include <cstdint>
#include <optional>
#include <string>

namespace tlmhub::server {

struct IdempotencyKey {
    std::string route;        // "POST /jobs", "POST /studies"
    std::string requestHash;  // SHA-256 of the request body, hex: a reused key with another body is an error
    std::int64_t objectId = 0; // 0 while its request is still being handled
};

class IdempotencyKeyStore {
public:
    virtual ~IdempotencyKeyStore() = default;

    // Reserves `key` for `ownerId` (pending) unless the owner used it after `notBeforeUnix`:
    // nullopt when this call reserved it, else that use (an older one is replaced). Also forgets
    // the owner's keys from before `notBeforeUnix`, so the table keeps a day of keys per user.
    virtual std::optional<IdempotencyKey> reserve(std::int64_t ownerId, const std::string& key,
                                                  const IdempotencyKey& use, std::int64_t nowUnix,
                                                  std::int64_t notBeforeUnix) = 0;
    // The reserved key made `objectId`.
    virtual void complete(std::int64_t ownerId, const std::string& key, std::int64_t objectId) = 0;
    // The reserved key's request made nothing (refused, failed): a later attempt may try again.
    virtual void release(std::int64_t ownerId, const std::string& key) = 0;
};

} // namespace tlmhub::server
