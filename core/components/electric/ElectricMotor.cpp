#include "core/components/electric/ElectricMotor.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ElectricMotor::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    mpPel2 = addPowerPort("Pel2", NodeType::Electric);
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    addInputVariable("Ke", "Voltage constant", "V s/rad", 0.13, &mpKe);
    addInputVariable("Ra", "Armature resistance", "ohm", 0.04, &mpRa);
    addInputVariable("Tm0", "Break away torque", "Nm", 0.0, &mpTm0);
    addInputVariable("wc", "Friction smoothing speed", "rad/s", 1.0, &mpWc);
    addInputVariable("Bm", "Viscous friction", "Nms/rad", 0.0012, &mpBm);
    addInputVariable("Jm", "Rotor inertia", "kg m^2", 1.0, &mpJm);
    addOutputVariable("tormg", "Generated torque", "Nm", 0.0, &mpTormg);
    addOutputVariable("Pin", "Electric input power", "W", 0.0, &mpPin);
    addOutputVariable("Pout", "Shaft power", "W", 0.0, &mpPout);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Ke", "Ra", "Tm0", "wc", "Bm", "Jm"}, false);
}

void ElectricMotor::computeDelayedParts()
{
    const double dt = mTimestep, Ke = mKe, Tm0 = mTm0, wc = mWc, Bm = mBm, Jm = mJm;
    const double K = 2.0 * Jm + Bm * dt;
    const double Fw = Tm0 * limit(mW / wc, -1.0, 1.0);
    mDelayed1 = (-mI2 * Ke * dt + dt * mT - 2.0 * Jm * mW + Bm * dt * mW + dt * Fw) / K;
    mDelayed2 = (-2.0 * mTheta - dt * mW) / 2.0;
}

void ElectricMotor::initialize()
{
    mpPel1_u = getSafeNodeDataPtr(mpPel1, NodeElectric::Voltage);
    mpPel1_i = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
    mpPel2_u = getSafeNodeDataPtr(mpPel2, NodeElectric::Voltage);
    mpPel2_i = getSafeNodeDataPtr(mpPel2, NodeElectric::Current);
    mpPel2_c = getSafeNodeDataPtr(mpPel2, NodeElectric::WaveVariable);
    mpPel2_Zc = getSafeNodeDataPtr(mpPel2, NodeElectric::CharImpedance);
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_T = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    mpPmr1_a = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Angle);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpPmr1_Je = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::EquivalentInertia);

    mU1 = *mpPel1_u;
    mI1 = *mpPel1_i;
    mU2 = *mpPel2_u;
    mI2 = *mpPel2_i;
    mW = *mpPmr1_w;
    mT = *mpPmr1_T;
    mTheta = *mpPmr1_a;
    mJeq = *mpPmr1_Je;
    mTormg = *mpTormg;
    mPin = *mpPin;
    mPout = *mpPout;
    // Hopsan quirk: all inputs are sampled only here.
    mKe = *mpKe;
    mRa = *mpRa;
    mTm0 = *mpTm0;
    mWc = *mpWc;
    mBm = *mpBm;
    mJm = *mpJm;
    computeDelayedParts();
}

void ElectricMotor::simulateOneTimestep()
{
    const double c1 = *mpPel1_c, Zc1 = *mpPel1_Zc;
    const double c2 = *mpPel2_c, Zc2 = *mpPel2_Zc;
    const double cm = *mpPmr1_c, Zcm = *mpPmr1_Zc;
    const double dt = mTimestep, Ke = mKe, Ra = mRa, Tm0 = mTm0, wc = mWc, Bm = mBm, Jm = mJm;
    const double K = 2.0 * Jm + Bm * dt;

    mX[0] = mW;
    mX[1] = mTheta;
    mX[2] = mI2;
    mX[3] = mU1;
    mX[4] = mU2;
    mX[5] = mT;
    for (int iter = 1; iter <= 2; ++iter) {
        const double w = mW, theta = mTheta, i2 = mI2, u1 = mU1, u2 = mU2, T = mT;
        const double Fw = Tm0 * limit(w / wc, -1.0, 1.0);

        mF[0] = w + dt * (-i2 * Ke + T + Fw) / K + mDelayed1;
        mF[1] = theta - dt * w / 2.0 + mDelayed2;
        mF[2] = i2 + (u2 - u1 + Ke * w) / Ra;
        mF[3] = u1 - c1 + Zc1 * i2;
        mF[4] = u2 - c2 - Zc2 * i2;
        mF[5] = T - cm - Zcm * w;

        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 6; ++c) { mJ[r][c] = 0.0; }
        }
        mJ[0][0] = 1.0 + dt * Tm0 * dxLimit(w / wc, -1.0, 1.0) / (K * wc);
        mJ[0][2] = -Ke * dt / K;
        mJ[0][5] = dt / K;
        mJ[1][0] = -dt / 2.0;
        mJ[1][1] = 1.0;
        mJ[2][0] = Ke / Ra;
        mJ[2][2] = 1.0;
        mJ[2][3] = -1.0 / Ra;
        mJ[2][4] = 1.0 / Ra;
        mJ[3][2] = Zc1;
        mJ[3][3] = 1.0;
        mJ[4][2] = -Zc2;
        mJ[4][4] = 1.0;
        mJ[5][0] = -Zcm;
        mJ[5][5] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) { stopSimulation("ElectricMotor: singular Jacobian"); }
        mW = mX[0];
        mTheta = mX[1];
        mI2 = mX[2];
        mU1 = mX[3];
        mU2 = mX[4];
        mT = mX[5];

        mI1 = -mI2;
        mTormg = mI2 * Ke - Bm * mW - Tm0 * limit(mW / wc, -1.0, 1.0);
        mPin = mI2 * (mU1 - mU2);
        mPout = mT * mW;
    }

    computeDelayedParts();

    *mpPel1_u = mU1;
    *mpPel1_i = mI1;
    *mpPel2_u = mU2;
    *mpPel2_i = mI2;
    *mpPmr1_T = mT;
    *mpPmr1_a = mTheta;
    *mpPmr1_w = mW;
    *mpPmr1_Je = mJeq;
    *mpTormg = mTormg;
    *mpPin = mPin;
    *mpPout = mPout;
}

TLMHUB_REGISTER_COMPONENT(ElectricMotor, "Electric")

} // namespace tlmhub
