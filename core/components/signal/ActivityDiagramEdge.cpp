#include "core/components/signal/ActivityDiagramEdge.h"

#include "core/ComponentFactory.h"
#include "core/components/signal/ActivityDiagramActionN.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

// NodePetriNet slots: State (place marking) and Flow (token transfer this step).
constexpr int kState = 0;
constexpr int kFlow = 1;

namespace {
// Collects the ActionN places attached to a port (they own a token lock).
void collectActionN(Port* port, std::vector<ActivityDiagramActionN*>& out)
{
    out.clear();
    for (Port* other : port->connectedPorts) {
        Component* c = other->component();
        if (c != nullptr && c->typeName() == "ActivityDiagramActionN") {
            if (auto* a = dynamic_cast<ActivityDiagramActionN*>(c)) { out.push_back(a); }
        }
    }
}

// Places of other types count as success; with several ActionN the last attempt decides.
bool tryLockAll(const std::vector<ActivityDiagramActionN*>& places)
{
    bool ok = true;
    for (ActivityDiagramActionN* a : places) { ok = a->tryAndLockToken(); }
    return ok;
}
} // namespace

void ActivityDiagramEdge::configure()
{
    addInputVariable("event", "Firing event", "", 1.0, &mpEvent);
    addInputVariable("diffEvent", "0 = level trigger, 1 = edge trigger", "", 0.0, &mpDiffEvent);
    mpPpn1 = addPowerPort("Ppn1", NodeType::PetriNet);
    mpPpn2 = addPowerPort("Ppn2", NodeType::PetriNet);
}

void ActivityDiagramEdge::initialize()
{
    mpS1 = getSafeNodeDataPtr(mpPpn1, kState);
    mpQ1 = getSafeNodeDataPtr(mpPpn1, kFlow);
    mpS2 = getSafeNodeDataPtr(mpPpn2, kState);
    mpQ2 = getSafeNodeDataPtr(mpPpn2, kFlow);
    collectActionN(mpPpn1, mLock1);
    collectActionN(mpPpn2, mLock2);
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
        const bool okU = tryLockAll(mLock1);
        const bool okD = tryLockAll(mLock2);
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
