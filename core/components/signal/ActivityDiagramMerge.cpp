#include "core/components/signal/ActivityDiagramMerge.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramMerge::configure()
{
    addInputVariable("event1", "Event for Ppn1", "", 1.0, &mpEvent1);
    addInputVariable("event2", "Event for Ppn2", "", 1.0, &mpEvent2);
    addInputVariable("diffevent", "0 = level trigger, 1 = edge trigger", "", 0.0, &mpDiffevent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
    mpPpn3 = addPowerPort("Ppn3", NodeType::PetriNet);
}

void ActivityDiagramMerge::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    mpS3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::State);
    mpQ3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::Flow);
    mOldEvent1 = *mpEvent1;
    mOldEvent2 = *mpEvent2;
    simulateOneTimestep();
}

void ActivityDiagramMerge::simulateOneTimestep()
{
    const double event1 = *mpEvent1, event2 = *mpEvent2, diffevent = *mpDiffevent;
    const double s1 = *mpS1, s2 = *mpS2, s3 = *mpS3;
    const double dE1 = onPositive(-0.5 + event1 - diffevent * mOldEvent1);
    const double dE2 = onPositive(-0.5 + event2 - diffevent * mOldEvent2);
    const double q1 = -(dE1 * onPositive(-0.5 + s1 - s3));
    const double q2 = -(dE2 * onPositive(0.5 + q1) * onPositive(-0.5 + s2 - s3));
    const double q3 = onPositive(-0.5 + onPositive(-0.5 - q1) + onPositive(-0.5 - q2));
    mOldEvent1 = event1;
    mOldEvent2 = event2;
    *mpQ1 = q1;
    *mpQ2 = q2;
    *mpQ3 = q3;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramMerge, "Other")

} // namespace tlmhub
