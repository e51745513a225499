#include "core/components/signal/SignalAdditiveNoise.h"

#include "core/ComponentFactory.h"
#include "core/numerics/WhiteGaussianNoise.h"

namespace tlmhub {

void SignalAdditiveNoise::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addInputVariable("std_dev", "Standard deviation", "", 1.0, &mpStd_dev);
    addOutputVariable("out", "Output signal", "", &mpOut);
}

void SignalAdditiveNoise::initialize()
{
    mpRandom = &randomStream();
    simulateOneTimestep();
}

void SignalAdditiveNoise::simulateOneTimestep()
{
    *mpOut = *mpIn + (*mpStd_dev) * WhiteGaussianNoise::getValue(*mpRandom);
}

TLMHUB_REGISTER_COMPONENT(SignalAdditiveNoise, "Signal")

} // namespace tlmhub
