#include "core/components/signal/ActivityDiagramForkN.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramForkN::configure()
{
    addInputVariable("event", "Firing event", "", 1.0, &mpEvent);
    addInputVariable("diffevent", "0 = level trigger, 1 = edge trigger", "", 0.0, &mpDiffevent);
    addOutputVariable("state", "Firing flag", "", 0.0, &mpState);
    mpPpn1 = addPowerMultiPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
}

void ActivityDiagramForkN::initialize()
{
    const std::size_t n = getNumPorts(mpPpn1);
    mpS.assign(n, nullptr);
    mpQ.assign(n, nullptr);
    // Hopsan zeroes the incoming sub-port nodes here (their start values do not survive).
    for (std::size_t i = 0; i < n; ++i) {
        mpS[i] = getSafeMultiPortNodeDataPtr(mpPpn1, i, NodePetriNet::State, 0.0);
        mpQ[i] = getSafeMultiPortNodeDataPtr(mpPpn1, i, NodePetriNet::Flow, 0.0);
    }
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    mOldEvent = 0.0;
}

void ActivityDiagramForkN::simulateOneTimestep()
{
    const double event = *mpEvent;
    const double state = onPositive(-0.5 + event - *mpDiffevent * mOldEvent);
    mOldEvent = event;
    const std::size_t n = mpS.size();
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) { sum = sum + *mpS[i]; }
    const double se = (n > 0) ? onPositive(sum - 0.5) : 0.0;
    const double s2 = *mpS2;
    for (std::size_t i = 0; i < n; ++i) { *mpQ[i] = state * onPositive(s2 - se - 0.5); }
    *mpQ2 = -state * onPositive(s2 - se - 0.5);
    *mpState = state;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramForkN, "Other")

} // namespace tlmhub
