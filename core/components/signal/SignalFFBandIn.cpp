#include "core/components/signal/SignalFFBandIn.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalFFBandIn::configure()
{
    addInputVariable("in0", "Input", "", 0.0, &mpIn0);
    addOutputVariable("state", "Block state", "", 0.0, &mpState);
    addOutputVariable("out0", "Output branch 0", "", 0.0, &mpOut0);
    addOutputVariable("out1", "Output branch 1", "", 0.0, &mpOut1);
}

void SignalFFBandIn::initialize()
{
    mOldState = *mpState;
    mOldIn0 = *mpIn0;
    mOldOut0 = *mpOut0;
}

void SignalFFBandIn::simulateOneTimestep()
{
    const double in0 = *mpIn0;
    const double state = onPositive(-0.5 + 2. * onPositive(-0.5 + in0 - mOldIn0) - onPositive(-0.5 + mOldOut0)
                                    + onPositive(-0.5 + mOldState));
    mOldState = state;
    mOldIn0 = in0;
    mOldOut0 = state;
    *mpState = state;
    *mpOut0 = state;
    *mpOut1 = state;
}

TLMHUB_REGISTER_COMPONENT(SignalFFBandIn, "Signal")

} // namespace tlmhub
