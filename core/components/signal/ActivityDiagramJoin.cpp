#include "core/components/signal/ActivityDiagramJoin.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

// NodePetriNet slots: State (place marking) and Flow (token transfer this step).
constexpr int kState = 0;
constexpr int kFlow = 1;

void ActivityDiagramJoin::configure()
{
    addInputVariable("event", "Enable", "", 1.0, &mpEvent);
    addInputVariable("diffEvent", "Edge trigger flag (no effect)", "", 0.0, &mpDiffEvent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
    mpPpn3 = addPowerPort("Ppn3", NodeType::PetriNet);
}

void ActivityDiagramJoin::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, kState);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, kFlow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, kState);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, kFlow);
    mpS3 = getSafeNodeDataPtr(mpPpn3, kState);
    mpQ3 = getSafeNodeDataPtr(mpPpn3, kFlow);
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
