#include "core/components/signal/SignalHP2Filter.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalHP2Filter::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
    addConstant("omega", "Break frequency", "rad/s", 1000.0, mOmega);
    addConstant("delta", "Relative damping", "", 1.0, mDelta);
    addConstant("y_min", "Lower output limit", "", -1.5e+300, mY_min);
    addConstant("y_max", "Upper output limit", "", 1.5e+300, mY_max);
}

void SignalHP2Filter::initialize()
{
    const double num[3] = {0.0, 0.0, 1.0 / (mOmega * mOmega)};
    const double den[3] = {1.0, 2.0 * mDelta / mOmega, 1.0 / (mOmega * mOmega)};
    mTF.initialize(mTimestep, num, den, *mpIn, *mpOut, mY_min, mY_max);
}

void SignalHP2Filter::simulateOneTimestep()
{
    *mpOut = mTF.update(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalHP2Filter, "Signal")

} // namespace tlmhub
