#include "core/components/signal/ActivityDiagramMerge0.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramMerge0::configure()
{

    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
    mpPpn3 = addPowerPort("Ppn3", NodeType::PetriNet);
}

void ActivityDiagramMerge0::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    mpS3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::State);
    mpQ3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::Flow);
    simulateOneTimestep();
}

void ActivityDiagramMerge0::simulateOneTimestep()
{
    const double s1 = *mpS1, s2 = *mpS2, s3 = *mpS3;
    // No 0.5 offset in the first gate (reference behaviour).
    const double q3 = onPositive(s1 + s2 - s3);
    const double q1 = -(q3 * onPositive(-0.5 + s1));
    const double q2 = -(q3 * onPositive(0.5 + q1) * onPositive(-0.5 + s2));
    *mpQ1 = q1;
    *mpQ2 = q2;
    *mpQ3 = q3;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramMerge0, "Other")

} // namespace tlmhub
