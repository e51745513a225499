#include "core/components/signal/SignalFirstOrderFilter.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalFirstOrderFilter::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
    addConstant("k", "Gain", "", 1.0, mK);
    addConstant("omega_num", "Numerator break frequency", "rad/s", 10000000000.0, mOmega_num);
    addConstant("omega_den", "Denominator break frequency", "rad/s", 1000.0, mOmega_den);
    addConstant("y_min", "Lower output limit", "", -1.5e+300, mY_min);
    addConstant("y_max", "Upper output limit", "", 1.5e+300, mY_max);
}

void SignalFirstOrderFilter::initialize()
{
    const double num[2] = {mK, mK / mOmega_num};
    const double den[2] = {1.0, 1.0 / mOmega_den};
    // The filter state starts from whatever is in the nodes now (out = start value).
    mTF.initialize(mTimestep, num, den, *mpIn, *mpOut, mY_min, mY_max);
}

void SignalFirstOrderFilter::simulateOneTimestep()
{
    *mpOut = mTF.update(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalFirstOrderFilter, "Signal")

} // namespace tlmhub
