#include "core/components/signal/ActivityDiagramConnector.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramConnector::configure()
{

    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
}

void ActivityDiagramConnector::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    // The reference starts from an uninitialised state variable; use 0.
    mStated = 0.0;
    simulateOneTimestep();
}

void ActivityDiagramConnector::simulateOneTimestep()
{
    const double state = onPositive(-0.5 + *mpQ1 + *mpQ2 + mStated);
    *mpS1 = state;
    *mpS2 = state;
    mStated = state;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramConnector, "Other")

} // namespace tlmhub
