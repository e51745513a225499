#include "core/components/signal/SignalSecondOrderTransferFunction.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalSecondOrderTransferFunction::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
    addConstant("a_2", "Numerator coefficient of s^2", "", 1.0, mA_2);
    addConstant("a_1", "Numerator coefficient of s^1", "", 1.0, mA_1);
    addConstant("a_0", "Numerator coefficient of s^0", "", 1.0, mA_0);
    addConstant("b_2", "Denominator coefficient of s^2", "", 1.0, mB_2);
    addConstant("b_1", "Denominator coefficient of s^1", "", 1.0, mB_1);
    addConstant("b_0", "Denominator coefficient of s^0", "", 1.0, mB_0);
}

void SignalSecondOrderTransferFunction::initialize()
{
    const double num[3] = {mA_0, mA_1, mA_2};
    const double den[3] = {mB_0, mB_1, mB_2};
    mTF.initialize(mTimestep, num, den, *mpIn, *mpOut);
}

void SignalSecondOrderTransferFunction::simulateOneTimestep()
{
    *mpOut = mTF.update(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalSecondOrderTransferFunction, "Signal")

} // namespace tlmhub
