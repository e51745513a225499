#include "core/components/signal/SignalStopSimulation.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <string>

namespace tlmhub {

void SignalStopSimulation::configure()
{
    addInputVariable("in", "Stop when true", "", 0.0, &mpIn);
    addConstant("message", "Message shown when the simulation is stopped", "", mMessage);
}

void SignalStopSimulation::initialize()
{
    // The input is not tested at t0; the text is prepared so the step builds no strings.
    mStopText = mMessage.empty() ? ("Simulation stopped by " + name()) : mMessage;
}

void SignalStopSimulation::simulateOneTimestep()
{
    if (doubleToBool(*mpIn)) {
        endSimulation(mStopText);
    }
}

TLMHUB_REGISTER_COMPONENT(SignalStopSimulation, "Signal")

} // namespace tlmhub
