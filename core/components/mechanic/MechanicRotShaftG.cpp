#include "core/components/mechanic/MechanicRotShaftG.h"

#include "core/ComponentFactory.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void MechanicRotShaftG::configure()
{
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    mpPmr2 = addPowerPort("Pmr2", NodeType::MechanicRotational);
    addInputVariable("dy", "Outer diameter", "m", 0.02, &mpDy);
    addInputVariable("di", "Inner diameter", "m", 0.0, &mpDi);
    addInputVariable("len", "Length", "m", 0.1, &mpLen);
    addInputVariable("G", "Shear modulus", "Pa", 7.93e10, &mpG);
    addInputVariable("alpha", "Numerical damping (filter factor)", "", 0.1, &mpAlpha);
}

// Zc = Ks*dt/(1 - alpha) with Ks = pi/32*(dy^4 - di^4)*G/len (pi/32 truncated to 0.0981748
// as in the original).
double MechanicRotShaftG::impedance() const
{
    const double dy = *mpDy, di = *mpDi, len = *mpLen, G = *mpG, alpha = *mpAlpha;
    const double Ks = (0.0981748 * (-Power(di, 4.0) + Power(dy, 4.0)) * G) / len;
    const double fak = 1.0 / (1.0 - alpha);
    return fak * Ks * mTimestep;
}

void MechanicRotShaftG::initialize()
{
    double* pT1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    double* pT2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Torque);
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpPmr2_w = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::AngularVelocity);
    mpPmr2_c = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::WaveVariable);
    mpPmr2_Zc = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::CharImpedance);

    const double Zexpr = impedance();
    mCmr1 = (*pT1) - (*mpPmr1_w) * Zexpr;
    mCmr2 = (*pT2) - (*mpPmr2_w) * Zexpr;
    mCmr1f = *pT1;
    mCmr2f = *pT2;

    simulateOneTimestep();
}

void MechanicRotShaftG::simulateOneTimestep()
{
    const double w1 = *mpPmr1_w;
    const double w2 = *mpPmr2_w;
    const double alpha = *mpAlpha;
    const double Zexpr = impedance();

    const double c10 = mCmr2 + 2.0 * w2 * Zexpr;
    const double c20 = mCmr1 + 2.0 * w1 * Zexpr;
    mCmr1f = (1.0 - alpha) * c10 + alpha * mCmr1f;
    mCmr2f = (1.0 - alpha) * c20 + alpha * mCmr2f;
    mCmr1 = mCmr1f;
    mCmr2 = mCmr2f;

    *mpPmr1_c = mCmr1;
    *mpPmr1_Zc = Zexpr;
    *mpPmr2_c = mCmr2;
    *mpPmr2_Zc = Zexpr;
}

TLMHUB_REGISTER_COMPONENT(MechanicRotShaftG, "Mechanic")

} // namespace tlmhub
