#include "core/components/electric/ElectricCapacitance2.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricCapacitance2::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    mpPel2 = addPowerPort("Pel2", NodeType::Electric);
    addInputVariable("Cc", "Capacitance", "(A s)/V", 1.0e-4, &mpCc);
    addInputVariable("alpha", "numerical damping", "", 0.1, &mpAlpha);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Cc", "alpha"}, false);
}

void ElectricCapacitance2::initialize()
{
    mpPel1_i = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
    mpPel2_i = getSafeNodeDataPtr(mpPel2, NodeElectric::Current);
    mpPel2_c = getSafeNodeDataPtr(mpPel2, NodeElectric::WaveVariable);
    mpPel2_Zc = getSafeNodeDataPtr(mpPel2, NodeElectric::CharImpedance);

    // States start from the node start values; nothing is written at t0.
    mC1 = *mpPel1_c;
    mZc1 = *mpPel1_Zc;
    mC2 = *mpPel2_c;
    mZc2 = *mpPel2_Zc;
    // Hopsan quirk: Cc and alpha are sampled only here.
    mCc = *mpCc;
    mAlpha = *mpAlpha;
}

void ElectricCapacitance2::simulateOneTimestep()
{
    const double i1 = *mpPel1_i;
    const double i2 = *mpPel2_i;
    const double alpha = mAlpha;

    // Uses the previous step's impedances (the start values at step 1).
    const double c2r = mC2 + 2.0 * mZc2 * i2;
    const double c1r = mC1 + 2.0 * mZc1 * i1;
    const double c1rf = (1.0 - alpha) * c1r + alpha * mC2;
    const double c2rf = alpha * mC1 + (1.0 - alpha) * c2r;
    mZc1 = mTimestep / ((1.0 - alpha) * mCc);
    mZc2 = mZc1;
    mC1 = c2rf;
    mC2 = c1rf;

    *mpPel1_c = mC1;
    *mpPel1_Zc = mZc1;
    *mpPel2_c = mC2;
    *mpPel2_Zc = mZc2;
}

TLMHUB_REGISTER_COMPONENT(ElectricCapacitance2, "Electric")

} // namespace tlmhub
