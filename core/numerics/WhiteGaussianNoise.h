// Standard normal random numbers (utilities.md §13): Box-Muller (cosine
// branch only) on the C library rand(). rand() is used on purpose, because
// bit-exact noise reproduction needs the same generator and sequence as the
// reference (glibc rand(), default seed 1 unless someone calls srand).
#pragma once

namespace tlmhub {

class WhiteGaussianNoise
{
public:
    static double getValue();
};

} // namespace tlmhub
