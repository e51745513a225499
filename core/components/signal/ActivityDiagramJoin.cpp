#include "core/components/signal/ActivityDiagramJoin.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramJoin::configure()
{
    addInputVariable("event", "Enable", "", 1.0, &mpEvent);
    addInputVariable("diffEvent", "Edge trigger flag (no effect)", "", 0.0, &mpDiffEvent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
    mpPpn3 = addPowerPort("Ppn3", NodeType::PetriNet);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"diffEvent"}, false);
}

void ActivityDiagramJoin::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    mpS3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::State);
    mpQ3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::Flow);
    mOldEvent = 0.0;
    simulateOneTimestep();
}

void ActivityDiagramJoin::simulateOneTimestep()
{
    const double event = *mpEvent;
    const double q3 = onPositive(event) * onPositive(-0.5 + *mpS1 * *mpS2 - *mpS3);
    *mpQ1 = -q3;
    *mpQ2 = -q3;
    *mpQ3 = q3;
    mOldEvent = event;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramJoin, "Other")

} // namespace tlmhub
