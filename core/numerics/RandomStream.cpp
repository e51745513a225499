#include "core/numerics/RandomStream.h"

namespace tlmhub {

namespace {
constexpr int kDegree = 31;       // r[i] depends on r[i-31] ...
constexpr int kSeparation = 3;    // ... and r[i-3]
constexpr int kDiscarded = 310;   // values thrown away after seeding
} // namespace

void RandomStream::reseed(std::uint32_t seed)
{
    if (seed == 0) seed = 1;
    // r[0] = seed, r[i] = 16807 * r[i-1] mod (2^31 - 1), signed as glibc computes it.
    std::int32_t word = static_cast<std::int32_t>(seed);
    mState[0] = seed;
    for (int i = 1; i < kDegree; ++i) {
        const std::int32_t hi = word / 127773, lo = word % 127773;
        word = 16807 * lo - 2836 * hi;
        if (word < 0) word += 2147483647;
        mState[i] = static_cast<std::uint32_t>(word);
    }
    mFront = 0;
    mBack = kSeparation;
    for (int i = 0; i < kDiscarded; ++i) next();
}

int RandomStream::next()
{
    // A ring of the last 31 values: mBack holds r[i-31], which r[i] replaces; mFront r[i-3].
    const std::uint32_t value = mState[mFront] + mState[mBack];
    mState[mBack] = value;
    mFront = mFront + 1 == kDegree ? 0 : mFront + 1;
    mBack = mBack + 1 == kDegree ? 0 : mBack + 1;
    return static_cast<int>(value >> 1);
}

} // namespace tlmhub
