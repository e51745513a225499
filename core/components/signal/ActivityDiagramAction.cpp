#include "core/components/signal/ActivityDiagramAction.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramAction::configure()
{
    addOutputVariable("state", "Place marking", "", 0.0, &mpState);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
}

void ActivityDiagramAction::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    mStated = *mpState;
    simulateOneTimestep();
}

void ActivityDiagramAction::simulateOneTimestep()
{
    const double state = onPositive(-0.5 + *mpQ1 + *mpQ2 + mStated);
    *mpS1 = state;
    *mpS2 = state;
    *mpState = state;
    mStated = state;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramAction, "Other")

} // namespace tlmhub
