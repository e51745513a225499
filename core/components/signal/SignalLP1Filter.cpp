#include "core/components/signal/SignalLP1Filter.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalLP1Filter::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
    addConstant("omega", "Break frequency", "rad/s", 1000.0, mOmega);
    addConstant("y_min", "Lower output limit", "", -1.5e+300, mY_min);
    addConstant("y_max", "Upper output limit", "", 1.5e+300, mY_max);
}

void SignalLP1Filter::initialize()
{
    const double num[2] = {1.0, 0.0};
    const double den[2] = {1.0, 1.0 / mOmega};
    mTF.initialize(mTimestep, num, den, *mpIn, *mpOut, mY_min, mY_max);
}

void SignalLP1Filter::simulateOneTimestep()
{
    *mpOut = mTF.update(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalLP1Filter, "Signal")

} // namespace tlmhub
