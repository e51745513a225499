#include "core/components/mechanic/MechanicRotShaft.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicRotShaft::configure()
{
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    mpPmr2 = addPowerPort("Pmr2", NodeType::MechanicRotational);
    addInputVariable("Ks", "Torsional stiffness", "Nm/rad", 1000.0, &mpKs);
    addInputVariable("alpha", "Numerical damping (filter factor)", "", 0.1, &mpAlpha);
}

void MechanicRotShaft::initialize()
{
    double* pT1 = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    double* pT2 = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Torque);
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpPmr2_w = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::AngularVelocity);
    mpPmr2_c = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::WaveVariable);
    mpPmr2_Zc = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::CharImpedance);

    const double Ks = *mpKs, alpha = *mpAlpha;
    const double T1 = *pT1, T2 = *pT2;
    const double w1 = *mpPmr1_w, w2 = *mpPmr2_w;

    mCmr1 = T1 - (Ks * mTimestep * w1) / (1.0 - alpha);
    mCmr2 = T2 - (Ks * mTimestep * w2) / (1.0 - alpha);
    mCmr1f = T1;
    mCmr2f = T2;

    // One step here so c and Zc are in the nodes before the Q components start.
    simulateOneTimestep();
}

void MechanicRotShaft::simulateOneTimestep()
{
    const double w1 = *mpPmr1_w;
    const double w2 = *mpPmr2_w;
    const double Ks = *mpKs, alpha = *mpAlpha;

    // Grouping as in the generated original: (2*Ks*dt*w)/(1 - alpha).
    const double c10 = mCmr2 + (2.0 * Ks * mTimestep * w2) / (1.0 - alpha);
    const double c20 = mCmr1 + (2.0 * Ks * mTimestep * w1) / (1.0 - alpha);
    const double Z = (Ks * mTimestep) / (1.0 - alpha);
    mCmr1f = (1.0 - alpha) * c10 + alpha * mCmr1f;
    mCmr2f = (1.0 - alpha) * c20 + alpha * mCmr2f;
    mCmr1 = mCmr1f;
    mCmr2 = mCmr2f;

    *mpPmr1_c = mCmr1;
    *mpPmr1_Zc = Z;
    *mpPmr2_c = mCmr2;
    *mpPmr2_Zc = Z;
}

TLMHUB_REGISTER_COMPONENT(MechanicRotShaft, "Mechanic")

} // namespace tlmhub
