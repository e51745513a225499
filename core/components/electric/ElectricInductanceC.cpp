#include "core/components/electric/ElectricInductanceC.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricInductanceC::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    mpPel2 = addPowerPort("Pel2", NodeType::Electric);
    addInputVariable("Induct", "Inductance", "A/(Vs)", 0.1, &mpInduct);
    addInputVariable("alpha", "numerical damping", "", 0.1, &mpAlpha);
    addOutputVariable("Cp", "parasitic capacitance", "(A s)/V", 0.0, &mpCp);
}

void ElectricInductanceC::initialize()
{
    mpPel1_i = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
    mpPel2_i = getSafeNodeDataPtr(mpPel2, NodeElectric::Current);
    mpPel2_c = getSafeNodeDataPtr(mpPel2, NodeElectric::WaveVariable);
    mpPel2_Zc = getSafeNodeDataPtr(mpPel2, NodeElectric::CharImpedance);

    mC1 = *mpPel1_c;
    mZc1 = *mpPel1_Zc;
    mC2 = *mpPel2_c;
    mZc2 = *mpPel2_Zc;
    // Hopsan quirk: one full step is taken already at initialisation.
    simulateOneTimestep();
}

void ElectricInductanceC::simulateOneTimestep()
{
    const double i1 = *mpPel1_i;
    const double i2 = *mpPel2_i;
    const double Induct = *mpInduct;
    const double alpha = *mpAlpha;

    const double c2r = mC2 + 2.0 * mZc2 * i2;
    const double c1r = mC1 + 2.0 * mZc1 * i1;
    const double c1rf = (1.0 - alpha) * c1r + alpha * mC2;
    const double c2rf = alpha * mC1 + (1.0 - alpha) * c2r;
    mZc1 = (1.0 - alpha) * Induct / mTimestep;
    mZc2 = mZc1;
    mC1 = c2rf;
    mC2 = c1rf;
    const double Cp = mTimestep * mTimestep / Induct;

    *mpPel1_c = mC1;
    *mpPel1_Zc = mZc1;
    *mpPel2_c = mC2;
    *mpPel2_Zc = mZc2;
    *mpCp = Cp;
}

TLMHUB_REGISTER_COMPONENT(ElectricInductanceC, "Electric")

} // namespace tlmhub
