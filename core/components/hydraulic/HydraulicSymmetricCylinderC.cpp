#include "core/components/hydraulic/HydraulicSymmetricCylinderC.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicSymmetricCylinderC::addAreaInputs()
{
    addInputVariable("A", "Piston area", "m^2", 0.001, &mpA1);
}

void HydraulicSymmetricCylinderC::initialize()
{
    // Both chamber areas read the single input A (pointer rebound every run).
    mpA2 = mpA1;
    HydraulicCylinderC::initialize();
}

TLMHUB_REGISTER_COMPONENT(HydraulicSymmetricCylinderC, "Hydraulic")

} // namespace tlmhub
