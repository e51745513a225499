// Standard normal random numbers (utilities.md §13): Box-Muller (cosine
// branch only) on the simulation's RandomStream, which gives the numbers of glibc's
// rand() from seed 1, as the reference draws them.
#pragma once
#include "core/numerics/RandomStream.h"

namespace tlmhub {

class WhiteGaussianNoise
{
public:
    static double getValue(RandomStream& random);
};

} // namespace tlmhub
