#include "core/components/signal/ActivityDiagramJoin0.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramJoin0::configure()
{

    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
    mpPpn3 = addPowerPort("Ppn3", NodeType::PetriNet);
}

void ActivityDiagramJoin0::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    mpS3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::State);
    mpQ3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::Flow);
    simulateOneTimestep();
}

void ActivityDiagramJoin0::simulateOneTimestep()
{
    const double q3 = onPositive(-0.5 + *mpS1 * *mpS2 - *mpS3);
    *mpQ1 = -q3;
    *mpQ2 = -q3;
    *mpQ3 = q3;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramJoin0, "Other")

} // namespace tlmhub
