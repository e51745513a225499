#include "core/components/signal/SignalSecondOrderFilter.h"

#include "core/ComponentFactory.h"
#include <cmath>

namespace tlmhub {

void SignalSecondOrderFilter::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
    addConstant("k", "Gain", "", 1.0, mK);
    addConstant("omega_1", "Numerator break frequency", "rad/s", 10000000000.0, mOmega_1);
    addConstant("delta_1", "Numerator damping", "", 1.0, mDelta_1);
    addConstant("omega_2", "Denominator break frequency", "rad/s", 1000.0, mOmega_2);
    addConstant("delta_2", "Denominator damping", "", 1.0, mDelta_2);
    addConstant("y_min", "Lower output limit", "", -1.5e+300, mY_min);
    addConstant("y_max", "Upper output limit", "", 1.5e+300, mY_max);
}

void SignalSecondOrderFilter::initialize()
{
    const double num[3] = {mK, mK * 2.0 * mDelta_1 / mOmega_1, mK / (mOmega_1 * mOmega_1)};
    const double den[3] = {1.0, 2.0 * mDelta_2 / mOmega_2, 1.0 / std::pow(mOmega_2, 2)};
    mTF.initialize(mTimestep, num, den, *mpIn, *mpOut, mY_min, mY_max);
}

void SignalSecondOrderFilter::simulateOneTimestep()
{
    *mpOut = mTF.update(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalSecondOrderFilter, "Signal")

} // namespace tlmhub
