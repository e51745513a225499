#include "core/components/signal/ActivityDiagramDecision.h"

#include "core/ComponentFactory.h"
#include "core/components/signal/ActivityDiagramActionN.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramDecision::configure()
{
    addInputVariable("event2", "Event for Ppn2", "", 0.0, &mpEvent2);
    addInputVariable("event3", "Event for Ppn3", "", 0.0, &mpEvent3);
    addInputVariable("diffevent", "0 = level trigger, 1 = edge trigger", "", 0.0, &mpDiffevent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
    mpPpn3 = addPowerPort("Ppn3", NodeType::PetriNet);
}

void ActivityDiagramDecision::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::State);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, NodePetriNet::Flow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::State);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, NodePetriNet::Flow);
    mpS3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::State);
    mpQ3 = getSafeNodeDataPtr(mpPpn3, NodePetriNet::Flow);
    ActivityDiagramActionN::collectAttached(mpPpn1, mLock1);
    ActivityDiagramActionN::collectAttached(mpPpn2, mLock2);
    ActivityDiagramActionN::collectAttached(mpPpn3, mLock3);
    mOldEvent2 = *mpEvent2;
    mOldEvent3 = *mpEvent3;
    simulateOneTimestep();
}

void ActivityDiagramDecision::simulateOneTimestep()
{
    const double event2 = *mpEvent2, event3 = *mpEvent3, diffevent = *mpDiffevent;
    const double s1 = *mpS1, s2 = *mpS2, s3 = *mpS3;
    const double dE2 = onPositive(-0.5 + event2 - diffevent * mOldEvent2);
    const double dE3 = onPositive(-0.5 + event3 - diffevent * mOldEvent3);
    const double q20 = dE2 * onPositive(s1 - s2);
    const double q30 = dE3 * onPositive(s1 - s3);
    double q2 = 0.0, q3 = 0.0;
    bool ok1 = false, ok2 = false, ok3 = false;
    if (q20 > 0.0 || q30 > 0.0) { ok1 = ActivityDiagramActionN::tryLockAll(mLock1); }
    if (q20 > 0.0) { ok2 = ActivityDiagramActionN::tryLockAll(mLock2); }
    if (q30 > 0.0) { ok3 = ActivityDiagramActionN::tryLockAll(mLock3); }
    if (q20 > 0.0 || q30 > 0.0) {
        if (ok1 && ok2) { q2 = dE2 * onPositive(s1 - s2); }
        if (ok1 && ok3) { q3 = dE3 * (1.0 - q2) * onPositive(s1 - s3); }
    }
    const double q1 = -onPositive(-0.5 + q2 + q3);
    mOldEvent2 = event2;
    mOldEvent3 = event3;
    *mpQ1 = q1;
    *mpQ2 = q2;
    *mpQ3 = q3;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramDecision, "Other")

} // namespace tlmhub
