#include "core/components/signal/ActivityDiagramFork.h"

#include "core/ComponentFactory.h"
#include "core/components/signal/ActivityDiagramActionN.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ActivityDiagramFork::configure()
{
    addInputVariable("event", "Firing event", "", 1.0, &mpEvent);
    addInputVariable("diffEvent", "0 = level trigger, 1 = edge trigger", "", 0.0, &mpDiffEvent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
    mpPpn3 = addPowerPort("Ppn3", NodeType::PetriNet);
}

void ActivityDiagramFork::initialize()
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
    // The reference evaluates the first step before oldEvent is set; use 0.
    mOldEvent = 0.0;
    simulateOneTimestep();
}

void ActivityDiagramFork::simulateOneTimestep()
{
    const double event = *mpEvent;
    const double s1 = *mpS1, s2 = *mpS2, s3 = *mpS3;
    const double dE = onPositive(-0.5 + event - *mpDiffEvent * mOldEvent);
    double q1 = 0.0, q2 = 0.0, q3 = 0.0;
    const double q10 = -dE * onPositive(-0.5 + s1 - s2 - s3);
    if (q10 < 0.0) {
        const bool okU = ActivityDiagramActionN::tryLockAll(mLock1);
        bool okD = ActivityDiagramActionN::tryLockAll(mLock2);
        // Third port: every ActionN must agree; stop asking once one refuses.
        for (ActivityDiagramActionN* a : mLock3) { okD = okD && a->tryAndLockToken(); }
        if (okU && okD) {
            q2 = -q10;
            q3 = -q10;
            q1 = q10;
        }
    }
    mOldEvent = event;
    *mpQ1 = q1;
    *mpQ2 = q2;
    *mpQ3 = q3;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramFork, "Other")

} // namespace tlmhub
