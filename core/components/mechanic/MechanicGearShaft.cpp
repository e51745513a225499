#include "core/components/mechanic/MechanicGearShaft.h"

#include "core/ComponentFactory.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void MechanicGearShaft::configure()
{
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    mpPmr2 = addPowerPort("Pmr2", NodeType::MechanicRotational);
    addInputVariable("gearRatio", "Gear ratio wmr1/wmr2", "", 1.0, &mpGearRatio);
    addInputVariable("Ks", "Spring constant (referred to port 2)", "Nm/rad", 1000.0, &mpKs);
    addInputVariable("alpha", "Damping factor", "", 0.9, &mpAlpha);
    addConstant("alpha", "Numerical damping (unused, see alpha#Value)", "", 0.3, mAlpha);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Ks", "alpha"}, false);
}

void MechanicGearShaft::initialize()
{
    double* pT1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    double* pT2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Torque);
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpPmr2_w = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::AngularVelocity);
    mpPmr2_c = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::WaveVariable);
    mpPmr2_Zc = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::CharImpedance);

    // Stiffness and damping are frozen at their initial values.
    mKs = *mpKs;
    mAlpha = *mpAlpha;

    const double n = *mpGearRatio;
    const double T1 = *pT1, T2 = *pT2;
    const double w1 = *mpPmr1_w, w2 = *mpPmr2_w;
    const double Z1 = (mKs * mTimestep) / ((1.0 - mAlpha) * Power(n, 2.0));
    const double Z2 = (mKs * mTimestep) / (1.0 - mAlpha);
    mCmr1 = n * T1 - w1 * Z1;
    mCmr2 = T2 - w2 * Z2;
    mCmr1f = T1 / n;
    mCmr2f = T2;
    // Nothing is written to the nodes here.
}

void MechanicGearShaft::simulateOneTimestep()
{
    const double w1 = *mpPmr1_w;
    const double w2 = *mpPmr2_w;
    const double n = *mpGearRatio;

    const double Z1 = (mKs * mTimestep) / ((1.0 - mAlpha) * Power(n, 2.0));
    const double Z2 = (mKs * mTimestep) / (1.0 - mAlpha);
    const double c10 = mCmr2 + 2.0 * w2 * Z2;
    const double c20 = mCmr1 * n + (2.0 * mKs * mTimestep * w1) / ((1.0 - mAlpha) * n);

    // The written waves are the filter values of the previous step.
    mCmr1 = mCmr1f / n;
    mCmr2 = mCmr2f;
    mCmr1f = (1.0 - mAlpha) * c10 + mAlpha * mCmr1f;
    mCmr2f = (1.0 - mAlpha) * c20 + mAlpha * mCmr2f;

    *mpPmr1_c = mCmr1;
    *mpPmr1_Zc = Z1;
    *mpPmr2_c = mCmr2;
    *mpPmr2_Zc = Z2;
}

TLMHUB_REGISTER_COMPONENT(MechanicGearShaft, "Mechanic")

} // namespace tlmhub
