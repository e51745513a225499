#include "core/components/aero/AeroAtmosphere.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void AeroAtmosphere::configure()
{
    addInputVariable("ha", "Altitude", "m", 0.0, &mpHa);
    addInputVariable("g0", "Gravitational acceleration", "m/s2", 9.81, &mpG0);
    addInputVariable("rhos", "Density at sea level", "kg/m3", 1.225, &mpRhos);
    addInputVariable("a", "Lapse rate", "K/m", -0.0065, &mpA);
    addInputVariable("R", "Gas constant", "J/(kg K)", 287.0, &mpR);
    addInputVariable("gamma", "Ratio of specific heats", "", 1.4, &mpGamma);
    addInputVariable("Ts", "Temperature at sea level", "K", 288.16, &mpTs);
    addInputVariable("p0s", "Pressure at sea level", "Pa", 101300.0, &mpP0s);
    addInputVariable("htp", "Tropopause altitude", "m", 11000.0, &mpHtp);
    addInputVariable("Ttp", "Tropopause temperature", "K", 216.66, &mpTtp);
    addInputVariable("ptp", "Tropopause pressure", "Pa", 22610.0, &mpPtp);
    addInputVariable("rhotp", "Tropopause density", "kg/m3", 0.363649, &mpRhotp);
    addInputVariable("e", "Base of natural logarithm", "", 2.71828, &mpE);
    addOutputVariable("rhoa", "Air density", "kg/m3", 1.25, &mpRhoa);
    addOutputVariable("Ta", "Air temperature", "K", 273.0, &mpTa);
    addOutputVariable("p0", "Air pressure", "Pa", 100000.0, &mpP0);
    addOutputVariable("Vsound", "Speed of sound", "m/s", 340.0, &mpVsound);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"g0", "rhos", "a", "R", "gamma", "Ts", "p0s", "htp", "Ttp", "ptp", "rhotp", "e"}, false);
}

void AeroAtmosphere::initialize()
{
    // Hopsan quirk: everything except the altitude is sampled only here.
    mG0 = *mpG0;
    mRhos = *mpRhos;
    mA = *mpA;
    mR = *mpR;
    mGamma = *mpGamma;
    mTs = *mpTs;
    mP0s = *mpP0s;
    mHtp = *mpHtp;
    mTtp = *mpTtp;
    mPtp = *mpPtp;
    mRhotp = *mpRhotp;
    mE = *mpE;
    // No initial step: outputs keep their start values until the first step.
}

void AeroAtmosphere::simulateOneTimestep()
{
    const double ha = *mpHa;
    const double g0 = mG0, rhos = mRhos, a = mA, R = mR, gamma = mGamma, Ts = mTs, p0s = mP0s, htp = mHtp,
                 Ttp = mTtp, ptp = mPtp, rhotp = mRhotp, e = mE;
    // Switch functions as in utilities.md (onNegative(0) = 1).
    const double below = onNegative(ha - htp);
    const double above = onPositive(ha - htp);

    const double Ta = (a * ha + Ts) * below + (a * htp + Ts) * above;
    const double rhoa = rhos * std::pow(Ta / Ts, -1.0 - g0 / (a * R)) * below
                        + rhotp / std::pow(e, g0 * (ha - htp) / (R * Ttp)) * above;
    const double p0 = p0s / std::pow(Ta / Ts, g0 / (a * R)) * below
                      + ptp / std::pow(e, g0 * (ha - htp) / (R * Ttp)) * above;
    const double Vsound = std::sqrt(gamma * R * Ta);

    *mpRhoa = rhoa;
    *mpTa = Ta;
    *mpP0 = p0;
    *mpVsound = Vsound;
}

TLMHUB_REGISTER_COMPONENT(AeroAtmosphere, "Aero")

} // namespace tlmhub
