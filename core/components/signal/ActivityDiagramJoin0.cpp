#include "core/components/signal/ActivityDiagramJoin0.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

// NodePetriNet slots: State (place marking) and Flow (token transfer this step).
constexpr int kState = 0;
constexpr int kFlow = 1;

void ActivityDiagramJoin0::configure()
{

    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
    mpPpn3 = addPowerPort("Ppn3", NodeType::PetriNet);
}

void ActivityDiagramJoin0::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, kState);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, kFlow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, kState);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, kFlow);
    mpS3 = getSafeNodeDataPtr(mpPpn3, kState);
    mpQ3 = getSafeNodeDataPtr(mpPpn3, kFlow);
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
