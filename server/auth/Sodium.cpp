#include "server/auth/Sodium.h"

#include <sodium.h>

#include <mutex>
#include <stdexcept>
#include <vector>

namespace tlmhub::server {

void ensureSodium()
{
    static std::once_flag once;
    std::call_once(once, [] {
        if (sodium_init() < 0) throw std::runtime_error("libsodium could not be initialised");
    });
}

std::string randomHex(std::size_t byteCount)
{
    ensureSodium();
    std::vector<unsigned char> bytes(byteCount);
    randombytes_buf(bytes.data(), bytes.size());
    std::string hex(byteCount * 2 + 1, '\0');
    sodium_bin2hex(hex.data(), hex.size(), bytes.data(), bytes.size());
    hex.pop_back();   // sodium_bin2hex writes a terminating NUL
    return hex;
}

} // namespace tlmhub::server
