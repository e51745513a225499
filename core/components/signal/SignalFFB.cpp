#include "core/components/signal/SignalFFB.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalFFB::configure()
{
    addInputVariable("set", "Activation input", "", 0.0, &mpSet);
    addInputVariable("exit", "Exit input", "", 0.0, &mpExit);
    addInputVariable("exitb", "Exit input b (level)", "", 0.0, &mpExitb);
    addInputVariable("leave", "Leave input", "", 0.0, &mpLeave);
    addOutputVariable("state", "Block state", "", 0.0, &mpState);
    addOutputVariable("exiting", "Exit signal", "", 0.0, &mpExiting);
    addOutputVariable("exitingb", "Exit signal b", "", 0.0, &mpExitingb);
}

void SignalFFB::initialize()
{
    mOldState = *mpState;
    mOldSet = *mpSet;
    mOldExit = *mpExit;
    mOldLeave = *mpLeave;
}

void SignalFFB::simulateOneTimestep()
{
    const double set = *mpSet, exit = *mpExit, exitb = *mpExitb, leave = *mpLeave;
    const double E = onPositive(-0.5 + exit + exitb - mOldExit);
    const double L = onPositive(-0.5 + leave - mOldLeave);
    const double S = onPositive(-0.5 + mOldState);
    const double R = onPositive(-0.5 - mOldSet + set);
    const double state = onPositive(-0.5 - E - L + S + 2. * R);
    // Multiplies by the raw previous state, as the reference does.
    const double exiting = mOldState * onPositive(-0.5 + exit - mOldExit);
    mOldState = state;
    mOldSet = set;
    mOldExit = exit;
    mOldLeave = leave;
    *mpState = state;
    *mpExiting = exiting;
    *mpExitingb = exiting;
}

TLMHUB_REGISTER_COMPONENT(SignalFFB, "Signal")

} // namespace tlmhub
