#include "core/components/signal/ActivityDiagramActionN.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

bool ActivityDiagramActionN::tryAndLockToken()
{
    if (mLocked) { return false; }
    mLocked = true;
    return true;
}

void ActivityDiagramActionN::collectAttached(Port* port, std::vector<ActivityDiagramActionN*>& out)
{
    out.clear();
    for (Port* other : port->connectedPorts) {
        Component* c = other->component();
        if (c != nullptr && c->typeName() == "ActivityDiagramActionN") {
            if (auto* a = dynamic_cast<ActivityDiagramActionN*>(c)) { out.push_back(a); }
        }
    }
}

bool ActivityDiagramActionN::tryLockAll(const std::vector<ActivityDiagramActionN*>& places)
{
    bool ok = true;
    for (ActivityDiagramActionN* a : places) { ok = a->tryAndLockToken(); }
    return ok;
}

void ActivityDiagramActionN::configure()
{
    addOutputVariable("state", "Place marking", "", 0.0, &mpState);
    mpPpn1 = addPowerMultiPort("Ppn1", NodeType::PetriNet);
}

void ActivityDiagramActionN::initialize()
{
    const std::size_t n = getNumPorts(mpPpn1);
    mpS.assign(n, nullptr);
    mpQ.assign(n, nullptr);
    const double s0 = getDefaultStartValue(mpPpn1, NodePetriNet::State);
    const double q0 = getDefaultStartValue(mpPpn1, NodePetriNet::Flow);
    for (std::size_t i = 0; i < n; ++i) {
        mpS[i] = getSafeMultiPortNodeDataPtr(mpPpn1, i, NodePetriNet::State);
        mpQ[i] = getSafeMultiPortNodeDataPtr(mpPpn1, i, NodePetriNet::Flow);
        *mpS[i] = s0;
        // The start flow is shared out over the connections.
        *mpQ[i] = q0 / static_cast<double>(n);
    }
    mLocked = false;
}

void ActivityDiagramActionN::simulateOneTimestep()
{
    const std::size_t n = mpS.size();
    const double dn = static_cast<double>(n);
    double sTot = 0.0;
    for (std::size_t i = 0; i < n; ++i) { sTot = sTot + (onPositive(*mpS[i] - 0.5) + 2. * dn * (*mpQ[i])); }
    sTot = onPositive(sTot - 0.5);
    for (std::size_t i = 0; i < n; ++i) { *mpS[i] = onPositive(sTot - 0.5); }
    *mpState = onPositive(-0.5 + sTot);
    mLocked = false;
}

TLMHUB_REGISTER_COMPONENT(ActivityDiagramActionN, "Other")

} // namespace tlmhub
