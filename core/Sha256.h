#pragma once
// SHA-256 (FIPS 180-4) of a byte stream fed in pieces: fingerprints of run results, so a
// test can tell that a change to the engine left every model's output byte for byte as it was.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace tlmhub {

class Sha256 {
public:
    Sha256();
    void update(std::string_view bytes);
    // The digest as 64 lower-case hex digits; the object is spent afterwards.
    std::string hexDigest();

private:
    void compressBlock(const unsigned char* block);

    std::array<std::uint32_t, 8> mState;
    std::array<unsigned char, 64> mBuffer{};
    std::size_t mBuffered = 0;
    std::uint64_t mTotalBytes = 0;
};

} // namespace tlmhub
