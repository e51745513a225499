#include "core/components/signal/SignalFFBloop.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalFFBloop::configure()
{
    addInputVariable("in0", "Input", "", 0.0, &mpIn0);
    addInputVariable("divert", "Route selector (>0.5 selects out1)", "", 0.0, &mpDivert);
    addOutputVariable("state", "Block state", "", 0.0, &mpState);
    addOutputVariable("out0", "Output branch 0", "", 0.0, &mpOut0);
    addOutputVariable("out1", "Output branch 1", "", 0.0, &mpOut1);
}

void SignalFFBloop::initialize()
{
    mOldState = *mpState;
    mOldIn0 = *mpIn0;
    mOldOut0 = *mpOut0;
    mOldOut1 = *mpOut1;
}

void SignalFFBloop::simulateOneTimestep()
{
    const double in0 = *mpIn0, divert = *mpDivert;
    const double state = onPositive(-0.5 + 2. * onPositive(-0.5 + in0 - mOldIn0)
                                    - onPositive(-0.5 + mOldOut0 + mOldOut1) + onPositive(-0.5 + mOldState));
    const double out0 = state * onPositive(0.5 - divert);
    const double out1 = state * onPositive(-0.5 + divert);
    mOldState = state;
    mOldIn0 = in0;
    mOldOut0 = out0;
    mOldOut1 = out1;
    *mpState = state;
    *mpOut0 = out0;
    *mpOut1 = out1;
}

TLMHUB_REGISTER_COMPONENT(SignalFFBloop, "Signal")

} // namespace tlmhub
