#include "core/components/signal/SignalAnimationSlider.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalAnimationSlider::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
    addConstant("min", "Output at input 0", "", 0.0, mMin);
    addConstant("max", "Output at input 1", "", 1.0, mMax);
}

void SignalAnimationSlider::initialize()
{
    simulateOneTimestep();
}

void SignalAnimationSlider::simulateOneTimestep()
{
    *mpOut = mMin + (mMax - mMin) * (*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalAnimationSlider, "Signal")

} // namespace tlmhub
