#include "core/components/signal/SignalNoiseGenerator.h"

#include "core/ComponentFactory.h"
#include "core/numerics/WhiteGaussianNoise.h"

namespace tlmhub {

void SignalNoiseGenerator::configure()
{
    addInputVariable("std_dev", "Standard deviation", "", 1.0, &mpStdDev);
    addOutputVariable("out", "Noise output", "", 0.0, &mpOut);
}

void SignalNoiseGenerator::initialize()
{
    mpRandom = &randomStream();
    simulateOneTimestep();
}

void SignalNoiseGenerator::simulateOneTimestep()
{
    *mpOut = *mpStdDev * WhiteGaussianNoise::getValue(*mpRandom);
}

TLMHUB_REGISTER_COMPONENT(SignalNoiseGenerator, "Signal")

} // namespace tlmhub
