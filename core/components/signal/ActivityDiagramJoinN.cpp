#include "core/components/signal/ActivityDiagramJoinN.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramJoinN::configure()
{

    mpPpn1 = addPowerMultiPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
}

void ActivityDiagramJoinN::initialize()
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
}

void ActivityDiagramJoinN::simulateOneTimestep()
{
    const std::size_t n = mpS.size();
    const double s2 = *mpS2;
    double g = 1.0;
    for (std::size_t i = 0; i < n; ++i) { g = g * onPositive(onPositive(*mpS[i] - 0.5) - s2 - 0.5); }
    for (std::size_t i = 0; i < n; ++i) { *mpQ[i] = -g; }
    *mpQ2 = g;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramJoinN, "Other")

} // namespace tlmhub
