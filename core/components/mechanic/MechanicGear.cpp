#include "core/components/mechanic/MechanicGear.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void MechanicGear::configure()
{
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    mpPmr2 = addPowerPort("Pmr2", NodeType::MechanicRotational);
    addInputVariable("gearRatio", "Gear ratio wmr1/wmr2", "", 1.0, &mpGearRatio);
    addInputVariable("Jg", "Equivalent inertia at port 2", "kg m^2", 1.0, &mpJg);
    addInputVariable("Bg", "Viscous friction coefficient at port 2", "Nms/rad", 0.0, &mpBg);
    addInputVariable("myfric", "Friction coefficient of the gear (at the output)", "", 0.01, &mpMyfric);
    addInputVariable("wc", "Friction smoothing speed", "rad/s", 1.0, &mpWc);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Jg", "Bg", "myfric", "wc"}, false);
}

// Hopsan's friction term uses the slip wmr1 + gearRatio * wmr2, which the kinematic relation
// makes zero after the first Newton step; kept so that results match.
double MechanicGear::frictionSign() const
{
    return limit((mW1 + *mpGearRatio * mW2) / mWc, -1.0, 1.0);
}

void MechanicGear::computeDelayedParts(double g)
{
    const double h = mTimestep;
    mDelayed1 = (-g * h * mT1 + h * mT2 - 2.0 * mJg * mW2 + mBg * h * mW2 + h * mMyfric * mT1 * frictionSign())
                / (2.0 * mJg + mBg * h);
    mDelayed2 = (-2.0 * mTheta2 - h * mW2) / 2.0;
    mDelayed3 = (-2.0 * mTheta1 + g * h * mW2) / 2.0;
}

void MechanicGear::initialize()
{
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_T = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    mpPmr1_a = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Angle);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpPmr1_Je = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::EquivalentInertia);
    mpPmr2_w = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::AngularVelocity);
    mpPmr2_T = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Torque);
    mpPmr2_a = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::Angle);
    mpPmr2_c = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::WaveVariable);
    mpPmr2_Zc = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::CharImpedance);
    mpPmr2_Je = getSafeNodeDataPtr(mpPmr2, NodeMechanicRotational::EquivalentInertia);

    mW1 = *mpPmr1_w;
    mT1 = *mpPmr1_T;
    mTheta1 = *mpPmr1_a;
    mJeq1 = *mpPmr1_Je;
    mW2 = *mpPmr2_w;
    mT2 = *mpPmr2_T;
    mTheta2 = *mpPmr2_a;
    mJeq2 = *mpPmr2_Je;
    // Hopsan quirk: all inputs but gearRatio are sampled only here.
    mJg = *mpJg;
    mBg = *mpBg;
    mMyfric = *mpMyfric;
    mWc = *mpWc;
    computeDelayedParts(*mpGearRatio);
}

void MechanicGear::simulateOneTimestep()
{
    const double c1 = *mpPmr1_c, Zc1 = *mpPmr1_Zc;
    const double c2 = *mpPmr2_c, Zc2 = *mpPmr2_Zc;
    const double g = *mpGearRatio;
    const double h = mTimestep;
    const double K = 2.0 * mJg + mBg * h;

    mX[0] = mW2;
    mX[1] = mTheta2;
    mX[2] = mTheta1;
    mX[3] = mT1;
    mX[4] = mT2;
    for (int iter = 1; iter <= 2; ++iter) {
        const double s = frictionSign();
        const double ds = dxLimit((mW1 + g * mW2) / mWc, -1.0, 1.0);

        mF[0] = mW2 + h * (-g * mT1 + mT2 + mMyfric * mT1 * s) / K + mDelayed1;
        mF[1] = mTheta2 - h * mW2 / 2.0 + mDelayed2;
        mF[2] = mTheta1 + g * h * mW2 / 2.0 + mDelayed3;
        mF[3] = mT1 - c1 + g * mW2 * Zc1;
        mF[4] = mT2 - c2 - mW2 * Zc2;

        for (int r = 0; r < 5; ++r) {
            for (int c = 0; c < 5; ++c) mJ[r][c] = 0.0;
        }
        mJ[0][0] = 1.0 + g * h * mMyfric * mT1 * ds / (K * mWc);
        mJ[0][3] = h * (-g + mMyfric * s) / K;
        mJ[0][4] = h / K;
        mJ[1][0] = -h / 2.0;
        mJ[1][1] = 1.0;
        mJ[2][0] = g * h / 2.0;
        mJ[2][2] = 1.0;
        mJ[3][0] = g * Zc1;
        mJ[3][3] = 1.0;
        mJ[4][0] = -Zc2;
        mJ[4][4] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) stopSimulation("MechanicGear: singular Jacobian");
        mW2 = mX[0];
        mTheta2 = mX[1];
        mTheta1 = mX[2];
        mT1 = mX[3];
        mT2 = mX[4];
        mW1 = -g * mW2;
        mJeq1 = mJg / (g * g);
        mJeq2 = mJg;
    }

    computeDelayedParts(g);

    *mpPmr1_T = mT1;
    *mpPmr1_a = mTheta1;
    *mpPmr1_w = mW1;
    *mpPmr1_Je = mJeq1;
    *mpPmr2_T = mT2;
    *mpPmr2_a = mTheta2;
    *mpPmr2_w = mW2;
    *mpPmr2_Je = mJeq2;
}

TLMHUB_REGISTER_COMPONENT(MechanicGear, "Mechanic")

} // namespace tlmhub
