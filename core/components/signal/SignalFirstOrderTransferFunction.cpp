#include "core/components/signal/SignalFirstOrderTransferFunction.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalFirstOrderTransferFunction::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", 0.0, &mpOut);
    addConstant("a_1", "Numerator coefficient of s^1", "", 1.0, mA_1);
    addConstant("a_0", "Numerator coefficient of s^0", "", 1.0, mA_0);
    addConstant("b_1", "Denominator coefficient of s^1", "", 1.0, mB_1);
    addConstant("b_0", "Denominator coefficient of s^0", "", 1.0, mB_0);
}

void SignalFirstOrderTransferFunction::initialize()
{
    const double num[2] = {mA_0, mA_1};
    const double den[2] = {mB_0, mB_1};
    mTF.initialize(mTimestep, num, den, *mpIn, *mpOut);
}

void SignalFirstOrderTransferFunction::simulateOneTimestep()
{
    *mpOut = mTF.update(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalFirstOrderTransferFunction, "Signal")

} // namespace tlmhub
