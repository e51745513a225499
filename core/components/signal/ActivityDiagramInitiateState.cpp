#include "core/components/signal/ActivityDiagramInitiateState.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramInitiateState::configure()
{
    addInputVariable("event", "Firing event", "", 1.0, &mpEvent);
    addInputVariable("diffEvent", "0 = level trigger, 1 = edge trigger", "", 1.0, &mpDiffEvent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
}

void ActivityDiagramInitiateState::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mOldEvent = 0.0;
    simulateOneTimestep();
}

void ActivityDiagramInitiateState::simulateOneTimestep()
{
    const double event = *mpEvent;
    *mpQ1 = onPositive(-0.5 + event - *mpDiffEvent * mOldEvent - *mpS1);
    mOldEvent = event;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramInitiateState, "Other")

} // namespace tlmhub
