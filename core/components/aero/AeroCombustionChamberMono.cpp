#include "core/components/aero/AeroCombustionChamberMono.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void AeroCombustionChamberMono::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    addInputVariable("pa", "Free-stream pressure", "Pa", 100000.0, &mpPa);
    addInputVariable("Vc", "Chamber volume", "m3", 0.02, &mpVc);
    addInputVariable("R", "Gas constant", "J/(kg K)", 396.0, &mpR);
    addInputVariable("cv", "Heat capacity at constant volume", "J/(kg K)", 1800.0, &mpCv);
    addInputVariable("vfuel", "Exhaust speed for the energy input", "m/s", 1571.0, &mpVfuel);
    addInputVariable("ethap", "Efficiency", "", 0.9, &mpEthap);
    addInputVariable("rhofuel", "Fuel density", "kg/m3", 1200.0, &mpRhofuel);
    addInputVariable("As", "Throat area", "m2", 0.00196, &mpAs);
    addInputVariable("Med", "Design exit Mach number", "", 2.5, &mpMed);
    addInputVariable("alpha", "Damping factor", "", 0.3, &mpAlpha);
    addOutputVariable("thrust", "Thrust", "N", 0.0, &mpThrust);
    addOutputVariable("Tc", "Chamber temperature", "K", 273.0, &mpTc);
    addOutputVariable("rhogas", "Gas density", "kg/m3", 0.0, &mpRhogas);
    addOutputVariable("mdot", "Mass flow", "kg/s", 0.0, &mpMdot);
    addOutputVariable("Ae", "Exit area", "m2", 0.0, &mpAe);
    addOutputVariable("pe", "Exit pressure", "Pa", 0.0, &mpPe);
    addOutputVariable("pc", "Chamber pressure", "Pa", 0.0, &mpPc);
    addOutputVariable("Te", "Exit temperature", "K", 273.0, &mpTe);
    addOutputVariable("ve", "Exit velocity", "m/s", 0.0, &mpVe);
    addOutputVariable("Pin", "Input power", "W", 0.0, &mpPin);
    addOutputVariable("Pout", "Output power", "W", 0.0, &mpPout);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Vc", "R", "cv", "vfuel", "ethap", "rhofuel", "As", "Med", "alpha"}, false);
}

void AeroCombustionChamberMono::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_T = getSafeNodeDataPtr(mpP1, NodeHydraulic::Temperature);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);

    const double p1 = *mpP1_p, q1 = *mpP1_q;
    mT1 = *mpP1_T;
    mZc1 = *mpP1_Zc;
    // Hopsan quirk: everything except pa is sampled only here.
    mVc = *mpVc;
    mR = *mpR;
    mCv = *mpCv;
    mVfuel = *mpVfuel;
    mEthap = *mpEthap;
    mRhofuel = *mpRhofuel;
    mAs = *mpAs;
    mMed = *mpMed;
    mAlpha = *mpAlpha;
    mThrust = *mpThrust;
    mMdot = *mpMdot;
    mAe = *mpAe;
    mPe = *mpPe;
    mTe = *mpTe;
    mVe = *mpVe;
    mPin = *mpPin;
    mPout = *mpPout;

    mC1 = p1;
    mC2 = p1;
    mPc = p1;
    mTc = mT1;
    mRhogas = mPc / (mR * (1.0 + mTc));
    mDelayed1 = (mMdot * mTimestep - mTimestep * q1 * mRhofuel - 2.0 * mRhogas * mVc) / (2.0 * mVc);
}

void AeroCombustionChamberMono::simulateOneTimestep()
{
    const double q1 = *mpP1_q;
    const double pa = *mpPa;
    const double dt = mTimestep, Vc = mVc, R = mR, cv = mCv, vfuel = mVfuel, ethap = mEthap, rhofuel = mRhofuel,
                 As = mAs, Med = mMed, alpha = mAlpha;

    const double gam = (cv + R) / cv;
    const double c10 = mC2 - 2.0 * mMdot * dt * (cv + R) * mTc / (gam * Vc);
    const double c20 = mC1 + ethap * dt * q1 * rhofuel * (vfuel * vfuel) / (gam * Vc);
    const double e = (1.0 + gam) / (2.0 * (gam - 1.0));
    const double K = std::pow(2.0, e) * As * std::pow(1.0 + gam, (1.0 + gam) / (2.0 - 2.0 * gam));

    mX[0] = mRhogas;
    mX[1] = mTc;
    mX[2] = mMdot;
    for (int iter = 1; iter <= 2; ++iter) {
        const double rhogas = mRhogas, Tc = mTc, mdot = mMdot, pc = mPc;
        const double RT = R + R * std::fabs(Tc);
        const double sq = std::sqrt(gam / RT);
        const double flowArg = K * pc * sq;

        mF[0] = rhogas + dt * (mdot - q1 * rhofuel) / (2.0 * Vc) + mDelayed1;
        mF[1] = Tc - pc / (R * rhogas);
        mF[2] = mdot - limit(flowArg, 0.0, 1.0e9);

        mJ[0][0] = 1.0;
        mJ[0][1] = 0.0;
        mJ[0][2] = dt / (2.0 * Vc);
        mJ[1][0] = pc / (R * (rhogas * rhogas));
        mJ[1][1] = 1.0;
        mJ[1][2] = 0.0;
        mJ[2][0] = 0.0;
        // d/dTc of -limit(K pc sqrt(gam/(R + R|Tc|))).
        mJ[2][1] = K * gam * pc * R * dxAbs(Tc) * dxLimit(flowArg, 0.0, 1.0e9) / (2.0 * sq * (RT * RT));
        mJ[2][2] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) { stopSimulation("AeroCombustionChamberMono: singular Jacobian"); }
        mRhogas = mX[0];
        mTc = mX[1];
        mMdot = mX[2];

        // Hopsan quirk: the filter is applied once per iteration (twice per step).
        mC1 = alpha * mC1 + (1.0 - alpha) * c10;
        mC2 = alpha * mC2 + (1.0 - alpha) * c20;
        mZc1 = ethap * dt * rhofuel * (vfuel * vfuel) / (2.0 * gam * Vc);
        mPc = mC2 - mMdot * dt * (cv + R) * mTc / (gam * Vc);
        const double M = 1.0 + (gam - 1.0) * (Med * Med) / 2.0;
        mAe = std::pow(2.0, e) * As * std::pow(M, e) / (std::pow(1.0 + gam, e) * Med);
        mPe = mPc / std::pow(M, gam / (gam - 1.0));
        mTe = mTc / M;
        mVe = Med * std::sqrt(gam * R * mTe);
        mThrust = lowLimit(mAe * (mPe - pa) + mMdot * mVe, 0.0);
        mPin = ethap * q1 * rhofuel * (vfuel * vfuel) / 2.0;
        mPout = mMdot * (mVe * mVe) / 2.0;
    }

    mDelayed1 = (mMdot * dt - dt * q1 * rhofuel - 2.0 * mRhogas * Vc) / (2.0 * Vc);

    *mpP1_T = mT1;
    *mpP1_c = mC1;
    *mpP1_Zc = mZc1;
    *mpThrust = mThrust;
    *mpTc = mTc;
    *mpRhogas = mRhogas;
    *mpMdot = mMdot;
    *mpAe = mAe;
    *mpPe = mPe;
    *mpPc = mPc;
    *mpTe = mTe;
    *mpVe = mVe;
    *mpPin = mPin;
    *mpPout = mPout;
}

TLMHUB_REGISTER_COMPONENT(AeroCombustionChamberMono, "Aero")

} // namespace tlmhub
