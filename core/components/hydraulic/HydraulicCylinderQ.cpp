#include "core/components/hydraulic/HydraulicCylinderQ.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicCylinderQ::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Mechanic);
    addInputVariable("A_1", "Piston area 1", "m^2", 0.0001, &mpA1);
    addInputVariable("A_2", "Piston area 2", "m^2", 0.0001, &mpA2);
    addInputVariable("B_p", "Viscous friction of piston", "N s/m", 0.0, &mpBp);
    addInputVariable("B_l", "Viscous friction of load", "N s/m", 0.0, &mpBl);
    addInputVariable("k_l", "Stiffness of load", "N/m", 100.0, &mpKl);
    addConstant("m_l", "Inertia of load", "kg", 0.05, mMass);
    addConstant("s_l", "Stroke", "m", 0.01, mSl);
}

void HydraulicCylinderQ::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpP2_p = getSafeNodeDataPtr(mpP2, NodeHydraulic::Pressure);
    mpP2_q = getSafeNodeDataPtr(mpP2, NodeHydraulic::Flow);
    mpP2_c = getSafeNodeDataPtr(mpP2, NodeHydraulic::WaveVariable);
    mpP2_Zc = getSafeNodeDataPtr(mpP2, NodeHydraulic::CharImpedance);
    mpP3_f = getSafeNodeDataPtr(mpP3, NodeMechanic::Force);
    mpP3_x = getSafeNodeDataPtr(mpP3, NodeMechanic::Position);
    mpP3_v = getSafeNodeDataPtr(mpP3, NodeMechanic::Velocity);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeMechanic::WaveVariable);
    mpP3_Zx = getSafeNodeDataPtr(mpP3, NodeMechanic::CharImpedance);

    const double bp = *mpBp;
    const double bl = *mpBl;
    const double kl = *mpKl;
    // Start position/velocity come from the C-type mechanic neighbour's start values.
    const double x3 = *mpP3_x;
    const double v3 = *mpP3_v;

    mPosNum[0] = 1.0;
    mPosNum[1] = 0.0;
    mPosNum[2] = 0.0;
    mPosDen[0] = kl;
    mPosDen[1] = bl + bp;
    mPosDen[2] = mMass;
    mVelNum[0] = 1.0;
    mVelNum[1] = 0.0;
    mVelDen[0] = bl + bp;
    mVelDen[1] = mMass;

    mPositionTF.initialize(mTimestep, mPosNum, mPosDen, 0.0, x3, 0.0, mSl);
    mVelocityTF.initialize(mTimestep, mVelNum, mVelDen, 0.0, v3);
}

void HydraulicCylinderQ::simulateOneTimestep()
{
    double c1 = *mpP1_c, Zc1 = *mpP1_Zc;
    double c2 = *mpP2_c, Zc2 = *mpP2_Zc;
    const double cx3 = *mpP3_c, Zx3 = *mpP3_Zx;

    const double A1 = *mpA1;
    const double A2 = *mpA2;
    const double bp = *mpBp;
    const double bl = *mpBl;
    const double kl = *mpKl;

    bool cavP1 = false;
    bool cavP2 = false;
    double x3 = 0.0, v3 = 0.0, f3 = 0.0, q1 = 0.0, q2 = 0.0, p1 = 0.0, p2 = 0.0;
    bool doRecalc = false;
    do {
        doRecalc = false;
        const double cx1 = A1 * c1 - A2 * c2;
        const double Zx1 = A1 * A1 * Zc1 + A2 * A2 * Zc2;

        mPosDen[1] = bl + bp + Zx1 + Zx3;
        mPositionTF.setDen(mPosDen);
        x3 = mPositionTF.updateWithBackup(cx1 - cx3);   // kl sits in the denominator
        if (mPositionTF.isSaturated()) {
            mVelocityTF.backup();
            mVelocityTF.initializeValues(0.0, 0.0);
            v3 = 0.0;
        } else {
            mVelDen[0] = bl + bp + Zx1 + Zx3;
            mVelocityTF.setDen(mVelDen);
            v3 = mVelocityTF.updateWithBackup(cx1 - cx3 - kl * x3);
        }

        f3 = cx3 + Zx3 * v3;
        q1 = -A1 * v3;
        q2 = A2 * v3;
        p1 = c1 + Zc1 * q1;
        p2 = c2 + Zc2 * q2;

        // Cavitation: clamp the chamber and redo the step once with c = Zc = 0.
        if (p1 < 0.0) {
            p1 = 0.0;
            c1 = 0.0;
            Zc1 = 0.0;
            if (!cavP1) {
                cavP1 = true;
                doRecalc = true;
            }
        }
        if (p2 < 0.0) {
            p2 = 0.0;
            c2 = 0.0;
            Zc2 = 0.0;
            // Hopsan sets the P1 flag here (reference quirk, kept on purpose).
            if (!cavP2) {
                cavP1 = true;
                doRecalc = true;
            }
        }
        if (doRecalc) {
            mPositionTF.restoreBackup();
            mVelocityTF.restoreBackup();
        }
    } while (doRecalc);

    *mpP1_p = p1;
    *mpP1_q = q1;
    *mpP2_p = p2;
    *mpP2_q = q2;
    *mpP3_f = f3;
    *mpP3_x = x3;
    *mpP3_v = v3;
}

TLMHUB_REGISTER_COMPONENT(HydraulicCylinderQ, "Hydraulic")

} // namespace tlmhub
