#include "core/components/pneumatic/PneumaticVolume2.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void PneumaticVolume2::configure()
{
    mpPp1 = addPowerPort("Pp1", NodeType::Pneumatic);
    mpPp2 = addPowerPort("Pp2", NodeType::Pneumatic);
    addInputVariable("V", "Volume", "m3", 0.001, &mpV);
    addInputVariable("R", "Gas constant", "J/Kg K", 287.0, &mpR);
    addInputVariable("cv", "heatcoeff", "J/Kg K", 718.0, &mpCv);
    addInputVariable("ka", "heat conductance", "J/Ks", 0.0, &mpKa);
    addInputVariable("T0", "Outside temperature", "K", 300.0, &mpT0);
    addInputVariable("alpha", "numerical damping", "", 0.1, &mpAlpha);
    addInputVariable("pmin", "numerical min pressure", "", 1.0, &mpPmin);
    addOutputVariable("mass", "Mass in volume", "kg", 0.001, &mpMass);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"V", "R", "cv", "ka", "T0", "alpha", "pmin"}, false);
}

void PneumaticVolume2::initialize()
{
    mPp1.bind(mpPp1);
    mPp2.bind(mpPp2);

    const double p1 = *mPp1.p, qm1 = *mPp1.qm, T1 = *mPp1.T;
    const double p2 = *mPp2.p, qm2 = *mPp2.qm, T2 = *mPp2.T;
    mC1 = *mPp1.c;
    mC2 = *mPp2.c;
    // Hopsan quirk: all inputs are sampled only here.
    mV = *mpV;
    mR = *mpR;
    mCv = *mpCv;
    mKa = *mpKa;
    mT0 = *mpT0;
    mPmin = *mpPmin;
    mFak = 1.0 / (1.0 - *mpAlpha);

    // Initial mass from the mean start state (start temperatures must be non-zero).
    const double Tav = (T1 + T2) / 2.0;
    const double pav = (p1 + p2) / 2.0;
    mMass = pav * mV / (mR * Tav);
    mDelayed1 = (-2.0 * mMass - mTimestep * qm1 - mTimestep * qm2) / 2.0;
    // Nothing is written to the nodes here.
}

void PneumaticVolume2::simulateOneTimestep()
{
    const double p1 = *mPp1.p, qm1 = *mPp1.qm, dE1 = *mPp1.dE;
    const double p2 = *mPp2.p, qm2 = *mPp2.qm, dE2 = *mPp2.dE;
    const double dt = mTimestep, V = mV, R = mR, cv = mCv, ka = mKa, T0 = mT0, pmin = mPmin;

    const double pav = pmin / 2.0 + (p1 + p2 - pmin) * onPositive(p1 + p2 - pmin) / 2.0;
    // Uses the mass of the previous step: the temperature lags one step.
    const double Tav = pav * V / (mMass * R);
    const double ZcEP = mFak * dt * R / ((cv + R) * V);
    const double cd1 = mC2 + 2.0 * (dE2 + ka * (T0 - Tav) / 2.0) * ZcEP;
    const double cd2 = mC1 + 2.0 * (dE1 + ka * (T0 - Tav) / 2.0) * ZcEP;

    // The one-unknown Newton system is linear with unit Jacobian: the first
    // iteration is exact and the second (weight 0.67) adds a zero correction.
    double mass = mMass;
    for (int iter = 1; iter <= 2; ++iter) {
        const double F0 = mass - dt * (qm1 + qm2) / 2.0 + mDelayed1;
        mass = mass - (iter == 1 ? 1.0 : 0.67) * F0;
    }
    mMass = mass;
    mC1 = cd1 + ka * (T0 - Tav) * ZcEP / 2.0;
    mC2 = cd2 + ka * (T0 - Tav) * ZcEP / 2.0;

    mDelayed1 = (-2.0 * mMass - dt * qm1 - dt * qm2) / 2.0;

    *mPp1.T = Tav;
    *mPp1.c = mC1;
    *mPp1.Zc = ZcEP;
    *mPp2.T = Tav;
    *mPp2.c = mC2;
    *mPp2.Zc = ZcEP;
    *mpMass = mMass;
}

TLMHUB_REGISTER_COMPONENT(PneumaticVolume2, "Pneumatic")

} // namespace tlmhub
