#include "core/components/signal/ActivityDiagramEdge.h"

#include "core/ComponentFactory.h"
#include "core/components/signal/ActivityDiagramActionN.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramEdge::configure()
{
    addInputVariable("event", "Firing event", "", 1.0, &mpEvent);
    addInputVariable("diffEvent", "0 = level trigger, 1 = edge trigger", "", 0.0, &mpDiffEvent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
}

void ActivityDiagramEdge::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    ActivityDiagramActionN::collectAttached(mpPpn1, mLock1);
    ActivityDiagramActionN::collectAttached(mpPpn2, mLock2);
    mOldEvent = *mpEvent;
    simulateOneTimestep();
}

void ActivityDiagramEdge::simulateOneTimestep()
{
    const double event = *mpEvent;
    const double s1 = *mpS1, s2 = *mpS2;
    double q1 = 0.0, q2 = 0.0;
    const double dE = onPositive(-0.5 + event - *mpDiffEvent * mOldEvent);
    const double drop = onPositive(-0.5 + s1 - s2);
    if (dE > 0.0 && drop > 0.0) {
        const bool okU = ActivityDiagramActionN::tryLockAll(mLock1);
        const bool okD = ActivityDiagramActionN::tryLockAll(mLock2);
        if (okU && okD) {
            q2 = dE * onPositive(-0.5 + s1 - s2);
            q1 = -q2;
            mOldEvent = event;
        }
    }
    *mpQ1 = q1;
    *mpQ2 = q2;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramEdge, "Other")

} // namespace tlmhub
