#include "core/components/signal/ActivityDiagramFinal.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramFinal::configure()
{
    addInputVariable("event", "Firing event", "", 1.0, &mpEvent);
    addInputVariable("diffEvent", "0 = level trigger, 1 = edge trigger", "", 0.0, &mpDiffEvent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
}

void ActivityDiagramFinal::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mOldEvent = *mpEvent;
    simulateOneTimestep();
}

void ActivityDiagramFinal::simulateOneTimestep()
{
    const double event = *mpEvent;
    const double dE = onPositive(-0.5 + event - *mpDiffEvent * mOldEvent);
    *mpQ1 = -(dE * onPositive(-0.5 + *mpS1));
    mOldEvent = event;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramFinal, "Other")

} // namespace tlmhub
