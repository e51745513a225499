#pragma once
// libsodium must be initialised once before any of its functions are used; every caller goes
// through here so the order of static construction never matters.
#include <string>

namespace tlmhub::server {

// Initialises libsodium (thread-safe, idempotent). Throws std::runtime_error if it cannot.
void ensureSodium();

// `byteCount` bytes from the system's cryptographic random source, hex encoded.
std::string randomHex(std::size_t byteCount);

} // namespace tlmhub::server
