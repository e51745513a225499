#include "core/components/signal/SignalDxSegare.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalDxSegare::configure()
{
    addInputVariable("x", "Opening (segment height)", "m", 0.0, &mpX);
    addInputVariable("diameter", "Hole diameter", "m", 0.0, &mpDiameter);
    addOutputVariable("width", "Chord width", "m", &mpWidth);
}

void SignalDxSegare::initialize()
{
    simulateOneTimestep();
}

void SignalDxSegare::simulateOneTimestep()
{
    *mpWidth = dxSegare(*mpX, *mpDiameter);
}

TLMHUB_REGISTER_COMPONENT(SignalDxSegare, "Signal")

} // namespace tlmhub
