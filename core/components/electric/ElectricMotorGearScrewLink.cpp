#include "core/components/electric/ElectricMotorGearScrewLink.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void ElectricMotorGearScrewLink::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    mpPel2 = addPowerPort("Pel2", NodeType::Electric);
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
    addInputVariable("gearRatio", "Gear ratio w_motor/w_screw", "", 1.0, &mpGearRatio);
    addInputVariable("Ke", "Voltage constant", "V/rpm", 0.13, &mpKe);
    addInputVariable("Ra", "Armature resistance", "ohm", 0.04, &mpRa);
    addInputVariable("Tm0", "Break away torque of the motor", "Nm", 0.0, &mpTm0);
    addInputVariable("wc", "Friction smoothing speed", "rad/s", 1.0, &mpWc);
    addInputVariable("Bm", "Motor viscous friction", "Nms/rad", 0.0012, &mpBm);
    addInputVariable("Jm", "Motor inertia", "kg m^2", 1.0, &mpJm);
    addInputVariable("myg", "Gear friction coefficient (at the output)", "", 0.01, &mpMyg);
    addInputVariable("mys", "Screw friction coefficient", "", 0.001, &mpMys);
    addInputVariable("BL", "Load viscous friction (not used by the equations)", "Nms/rad", 0.0, &mpBL);
    addInputVariable("JL", "Load inertia", "kg m^2", 1.0, &mpJL);
    addInputVariable("pitch", "Screw lead per radian", "m/rad", 0.0008, &mpPitch);
    addInputVariable("thetamin", "Minimum link angle", "rad", -0.5, &mpThetaMin);
    addInputVariable("thetamax", "Maximum link angle", "rad", 0.5, &mpThetaMax);
    addInputVariable("la", "Link length", "m", 0.08, &mpLa);
    addOutputVariable("wm", "Motor speed", "rad/s", 0.0, &mpWm);
    addOutputVariable("tormg", "Generated motor torque", "Nm", 0.0, &mpTormg);
    addOutputVariable("Pin", "Electric input power", "W", 0.0, &mpPin);
    addOutputVariable("Pout", "Link shaft power", "W", 0.0, &mpPout);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Ke", "Ra", "Tm0", "wc", "Bm", "Jm", "myg", "mys", "BL", "JL", "pitch", "thetamin",
                      "thetamax", "la"}, false);
}

ElectricMotorGearScrewLink::Load ElectricMotorGearScrewLink::load(double g) const
{
    const double p2 = mPitch * mPitch, la2 = mLa * mLa;
    const double s = limit(mW / mWc, -1.0, 1.0);
    // Friction magnitude: motor break-away torque plus gear and screw friction, both
    // proportional to the port torque.
    const double frictionGain = g * p2 * mTm0 + la2 * (g * g * mMyg + mMys) * std::fabs(mT);
    const double bt = g * g * (la2 + mBm * p2);

    Load l{};
    l.drive = p2 * (mT - g * mI2 * mKe);
    l.fr = frictionGain * s;
    l.a = l.drive + bt * mW + l.fr;
    l.dFrdw = (frictionGain * dxLimit(mW / mWc, -1.0, 1.0)) / mWc;
    l.dAdw = bt + l.dFrdw;
    l.dAdi = -(g * mKe * p2);
    l.dAdT = p2 + la2 * (g * g * mMyg + mMys) * dxAbs(mT) * s;
    return l;
}

// Bilinear (trapezoidal) forms of Jt d2theta/dt2 = -A and Jt dw/dt = -A, Jt = (JL + g Jm) p^2:
//   theta[n] = -dt^2 A[n] / (4 Jt) - Dtheta1[n-1] - Dtheta2[n-2],
//   w[n]     = -dt (A[n] - Bt w[n]) / (2 Jt + Bt dt) - Dw[n-1]  (the viscous part implicit).
double ElectricMotorGearScrewLink::computeDelayedParts(double g, const Load& l)
{
    const double dt = mTimestep;
    const double p2 = mPitch * mPitch;
    const double jt = (mJL + g * mJm) * p2;
    const double bt = g * g * (mLa * mLa + mBm * p2);
    mDTheta1 = (2.0 * dt * dt * l.a - 8.0 * jt * mTheta) / (4.0 * jt);
    mDW = (dt * (l.drive + l.fr) + (bt * dt - 2.0 * jt) * mW) / (2.0 * jt + bt * dt);
    return (dt * dt * l.a + 4.0 * jt * mTheta) / (4.0 * jt);
}

void ElectricMotorGearScrewLink::initialize()
{
    mpU1 = getSafeNodeDataPtr(mpPel1, NodeElectric::Voltage);
    mpI1 = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpC1 = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpZc1 = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
    mpU2 = getSafeNodeDataPtr(mpPel2, NodeElectric::Voltage);
    mpI2 = getSafeNodeDataPtr(mpPel2, NodeElectric::Current);
    mpC2 = getSafeNodeDataPtr(mpPel2, NodeElectric::WaveVariable);
    mpZc2 = getSafeNodeDataPtr(mpPel2, NodeElectric::CharImpedance);
    mpT = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    mpTheta = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Angle);
    mpW = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpCm = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpZcm = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);
    mpJe = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::EquivalentInertia);

    mU1 = *mpU1;
    mI1 = *mpI1;
    mU2 = *mpU2;
    mI2 = *mpI2;
    mT = *mpT;
    mTheta = *mpTheta;
    mW = *mpW;
    // The equivalent inertia is never computed: Pmr1 keeps its start value.
    mJe = *mpJe;

    mKe = *mpKe;
    mRa = *mpRa;
    mTm0 = *mpTm0;
    mWc = *mpWc;
    mBm = *mpBm;
    mJm = *mpJm;
    mMyg = *mpMyg;
    mMys = *mpMys;
    mJL = *mpJL;
    mPitch = *mpPitch;
    mThetaMin = *mpThetaMin;
    mThetaMax = *mpThetaMax;
    mLa = *mpLa;

    mJac.create(6, 6);
    mEq.create(6);
    mState.create(6);
    mSingularReported = false;

    const double g = *mpGearRatio;
    const double dTheta2 = computeDelayedParts(g, load(g));
    mDelayTheta2.initialize(9, dTheta2);
    mDTheta2 = mDelayTheta2.getIdx(1);
}

void ElectricMotorGearScrewLink::simulateOneTimestep()
{
    // Read the node values and the gear ratio.
    const double c1 = *mpC1, Zc1 = *mpZc1;
    const double c2 = *mpC2, Zc2 = *mpZc2;
    const double cm = *mpCm, Zcm = *mpZcm;
    const double g = *mpGearRatio;
    const double dt = mTimestep, p = mPitch, p2 = mPitch * mPitch;
    const double Ke = mKe, Ra = mRa, la = mLa;
    const double jt = (mJL + g * mJm) * p2;
    const double kw = 2.0 * jt + g * g * (la * la + mBm * p2) * dt;

    mState[0] = mTheta;
    mState[1] = mW;
    mState[2] = mI2;
    mState[3] = mU1;
    mState[4] = mU2;
    mState[5] = mT;

    // Equations: link angle and speed (held at the angle limits), armature circuit with
    // back-EMF g Ke (la/p) w, and the TLM relations of the three ports.
    for (int iter = 1; iter <= 2; ++iter) {
        const Load l = load(g);
        const double thetaRaw = -(dt * dt * l.a) / (4.0 * jt) - mDTheta1 - mDTheta2;
        const double thetaLim = limit(thetaRaw, mThetaMin, mThetaMax);
        const double gate = dxLimit(thetaLim, mThetaMin, mThetaMax);
        const double gateRaw = dxLimit(thetaRaw, mThetaMin, mThetaMax);

        mEq[0] = mTheta - thetaLim;
        mEq[1] = mW - gate * (-(dt * (l.drive + l.fr)) / kw - mDW);
        mEq[2] = mI2 + (p * (mU2 - mU1) + g * Ke * la * mW) / (p * Ra);
        mEq[3] = -c1 + mU1 + mI2 * Zc1;
        mEq[4] = -c2 + mU2 - mI2 * Zc2;
        mEq[5] = -cm + mT - mW * Zcm;

        for (int r = 0; r < 6; ++r) {
            for (int col = 0; col < 6; ++col) mJac[r][col] = 0.0;
        }
        mJac[0][0] = 1.0;
        mJac[0][1] = (dt * dt * gateRaw * l.dAdw) / (4.0 * jt);
        mJac[0][2] = (dt * dt * gateRaw * l.dAdi) / (4.0 * jt);
        mJac[0][5] = (dt * dt * gateRaw * l.dAdT) / (4.0 * jt);
        mJac[1][1] = 1.0 + (dt * gate * l.dFrdw) / kw;
        mJac[1][2] = (dt * gate * l.dAdi) / kw;
        mJac[1][5] = (dt * gate * l.dAdT) / kw;
        mJac[2][1] = (g * Ke * la) / (p * Ra);
        mJac[2][2] = 1.0;
        mJac[2][3] = -1.0 / Ra;
        mJac[2][4] = 1.0 / Ra;
        mJac[3][2] = Zc1;
        mJac[3][3] = 1.0;
        mJac[4][2] = -Zc2;
        mJac[4][4] = 1.0;
        mJac[5][1] = -Zcm;
        mJac[5][5] = 1.0;

        if (!mSolver.solve(mJac, mEq, mState, iter) && !mSingularReported) {
            mSingularReported = true;
            stopSimulation("ElectricMotorGearScrewLink: singular Jacobian");
        }
        mTheta = mState[0];
        mW = mState[1];
        mI2 = mState[2];
        mU1 = mState[3];
        mU2 = mState[4];
        mT = mState[5];
    }

    const double wm = g * mW;
    mI1 = -mI2;
    const double tormg = mI2 * Ke - mBm * g * mW - mTm0 * limit(mW / mWc, -1.0, 1.0);
    const double pin = mI2 * (mU1 - mU2);
    const double pout = mT * mW;

    const double dTheta2 = computeDelayedParts(g, load(g));
    mDTheta2 = mDelayTheta2.getIdx(0);
    mDelayTheta2.update(dTheta2);

    // Write the node values and outputs.
    *mpU1 = mU1;
    *mpI1 = mI1;
    *mpU2 = mU2;
    *mpI2 = mI2;
    *mpT = mT;
    *mpTheta = mTheta;
    *mpW = mW;
    *mpJe = mJe;
    *mpWm = wm;
    *mpTormg = tormg;
    *mpPin = pin;
    *mpPout = pout;
}

TLMHUB_REGISTER_COMPONENT(ElectricMotorGearScrewLink, "Electric")

} // namespace tlmhub
