#pragma once
// How many steps of `timestep` fit in a span of time, rounded as Hopsan rounds step counts.
#include <cstddef>

namespace tlmhub {

// Hopsan's round: truncate(x + 0.5) on a non-negative double; 0 for anything not positive
// (NaN included).
inline std::size_t roundSteps(double x)
{
    if (!(x > 0.0)) return 0;
    return static_cast<std::size_t>(x + 0.5);
}

} // namespace tlmhub
