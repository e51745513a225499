#include "core/components/signal/SignalSegare.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalSegare::configure()
{
    addInputVariable("x", "Opening (segment height)", "m", 0.0, &mpX);
    addInputVariable("diameter", "Hole diameter", "m", 0.0, &mpDiameter);
    addOutputVariable("area", "Segment area", "m^2", &mpArea);
}

void SignalSegare::initialize()
{
    simulateOneTimestep();
}

void SignalSegare::simulateOneTimestep()
{
    *mpArea = segare(*mpX, *mpDiameter);
}

TLMHUB_REGISTER_COMPONENT(SignalSegare, "Signal")

} // namespace tlmhub
