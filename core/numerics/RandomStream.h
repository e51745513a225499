#pragma once
// The random numbers of one simulation: the sequence of the C library's rand() on glibc
// (its additive feedback generator, r[i] = r[i-3] + r[i-31] mod 2^32, each output r[i] >> 1,
// started from a seed by a Lehmer generator and 310 discarded values), which is what
// Hopsan's noise sources draw from. Each simulation owns one and seeds it at every start,
// so a run gives the same noise whether it is the first in its process or not.
#include <array>
#include <cstdint>

namespace tlmhub {

class RandomStream {
public:
    static constexpr int kMax = 2147483647;   // RAND_MAX of glibc

    explicit RandomStream(std::uint32_t seed = 1) { reseed(seed); }
    void reseed(std::uint32_t seed);
    // The next number in [0, kMax].
    int next();

private:
    std::array<std::uint32_t, 31> mState{};   // the last 31 values
    int mFront = 0;                            // index of r[i-3]
    int mBack = 0;                             // index of r[i-31]
};

} // namespace tlmhub
