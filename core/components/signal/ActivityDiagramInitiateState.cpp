#include "core/components/signal/ActivityDiagramInitiateState.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

// NodePetriNet slots: State (place marking) and Flow (token transfer this step).
constexpr int kState = 0;
constexpr int kFlow = 1;

void ActivityDiagramInitiateState::configure()
{
    addInputVariable("event", "Firing event", "", 1.0, &mpEvent);
    addInputVariable("diffEvent", "0 = level trigger, 1 = edge trigger", "", 1.0, &mpDiffEvent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
}

void ActivityDiagramInitiateState::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, kState);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, kFlow);
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
