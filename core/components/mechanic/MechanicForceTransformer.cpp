#include "core/components/mechanic/MechanicForceTransformer.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicForceTransformer::configure()
{
    addInputVariable("F", "Generated force", "N", 0.0, &mpF);
    mpP1 = addPowerPort("P1", NodeType::Mechanic);
    // The force is given by the input and the impedance is always zero, so these two
    // start values are not user settable.
    disableStartValue(mpP1, NodeMechanic::Force);
    setDefaultStartValue(mpP1, NodeMechanic::CharImpedance, 0.0);
    disableStartValue(mpP1, NodeMechanic::CharImpedance);
}

void MechanicForceTransformer::initialize()
{
    mpP1_f = getSafeNodeDataPtr(mpP1, NodeMechanic::Force);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanic::WaveVariable);

    const double F = *mpF;
    *mpP1_f = F;
    // Keep an explicitly given wave start value; otherwise start from the force.
    if (*mpP1_c == 0.0) {
        *mpP1_c = F;
    }
}

void MechanicForceTransformer::simulateOneTimestep()
{
    *mpP1_c = *mpF;
}

TLMHUB_REGISTER_COMPONENT(MechanicForceTransformer, "Mechanic")

} // namespace tlmhub
