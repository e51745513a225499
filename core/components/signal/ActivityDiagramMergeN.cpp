#include "core/components/signal/ActivityDiagramMergeN.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramMergeN::configure()
{

    mpPpn1 = addPowerMultiPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
}

void ActivityDiagramMergeN::initialize()
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

    if (n == 0) { addErrorMessage("ActivityDiagramMergeN needs at least one connection on Ppn1."); }
}

void ActivityDiagramMergeN::simulateOneTimestep()
{
    const std::size_t n = mpS.size();
    if (n == 0) { return; }
    const double s2 = *mpS2;
    double g = onPositive((*mpS[0] - s2) - 0.5);
    *mpQ[0] = -g;
    for (std::size_t i = 1; i < n; ++i) {
        const double qi = -onPositive((1.0 - g) * (*mpS[i] - s2) - 0.5);
        *mpQ[i] = qi;
        g = onPositive(g - qi - 0.5);
    }
    *mpQ2 = g;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramMergeN, "Other")

} // namespace tlmhub
