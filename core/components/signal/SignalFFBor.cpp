#include "core/components/signal/SignalFFBor.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalFFBor::configure()
{
    addInputVariable("in0", "Input branch 0", "", 0.0, &mpIn0);
    addInputVariable("in1", "Input branch 1", "", 0.0, &mpIn1);
    addOutputVariable("state", "Block state", "", 0.0, &mpState);
    addOutputVariable("exiting", "Exit signal", "", 0.0, &mpExiting);
    addOutputVariable("exitingb0", "Exit signal b0 (unused)", "", 0.0, &mpExitingb0);
    addOutputVariable("exitingb1", "Exit signal b1 (unused)", "", 0.0, &mpExitingb1);
}

void SignalFFBor::initialize()
{
    mOldIn0 = *mpIn0;
    mOldIn1 = *mpIn1;
    mOldExiting = *mpExiting;
    // The reference leaves the sub-states uninitialised; start them at 0.
    mOldState0 = 0.0;
    mOldState1 = 0.0;
    mExitingb0 = *mpExitingb0;
    mExitingb1 = *mpExitingb1;
}

void SignalFFBor::simulateOneTimestep()
{
    const double in0 = *mpIn0, in1 = *mpIn1;
    const double X = onPositive(-0.5 + mOldExiting);
    const double state0 = onPositive(-0.5 - X + 2. * onPositive(-0.5 + in0 - mOldIn0) + onPositive(-0.5 + mOldState0));
    const double state1 = onPositive(-0.5 - X + 2. * onPositive(-0.5 + in1 - mOldIn1) + onPositive(-0.5 + mOldState1));
    const double exiting = onPositive(-0.5 + mOldState0 + mOldState1);
    const double state = onPositive(-0.5 + onPositive(-0.5 + state0) + onPositive(-0.5 + state1));
    mOldState0 = state0;
    mOldState1 = state1;
    mOldIn0 = in0;
    mOldIn1 = in1;
    mOldExiting = exiting;
    *mpState = state;
    *mpExiting = exiting;

    *mpExitingb0 = mExitingb0;
    *mpExitingb1 = mExitingb1;
}

TLMHUB_REGISTER_COMPONENT(SignalFFBor, "Signal")

} // namespace tlmhub
