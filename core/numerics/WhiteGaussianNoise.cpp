#include "core/numerics/WhiteGaussianNoise.h"

#include <cmath>

#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

double WhiteGaussianNoise::getValue(RandomStream& random)
{
    double r1 = 0.0;
    while (r1 == 0.0) { // log(0) must be avoided
        r1 = static_cast<double>(random.next()) / static_cast<double>(RandomStream::kMax);
    }
    const double r2 = static_cast<double>(random.next()) / static_cast<double>(RandomStream::kMax);
    return std::sqrt((-2.0) * std::log(r1)) * std::cos(2.0 * pi * r2);
}

} // namespace tlmhub
