#include "core/components/aero/AeroJetEngine.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void AeroJetEngine::configure()
{
    addInputVariable("uin", "Throttle 0..1", "", 1.0, &mpUin);
    addInputVariable("rho", "Air density", "kg/m3", 1.25, &mpRho);
    addInputVariable("T", "Air temperature", "K", 273.0, &mpT);
    addInputVariable("p0", "Air pressure", "Pa", 100000.0, &mpP0);
    addInputVariable("Vsound", "Speed of sound", "m/s", 340.0, &mpVsound);
    addInputVariable("speed", "Air speed", "m/s", 100.0, &mpSpeed);
    addInputVariable("thrustmax", "Max thrust", "N", 77000.0, &mpThrustmax);
    addInputVariable("SFC0", "Specific fuel consumption", "kg/(N s)", 2.66e-5, &mpSFC0);
    addInputVariable("thau", "Engine time constant", "s", 5.0, &mpThau);
    addInputVariable("Ctm", "Thrust Mach coefficient", "", 0.1304, &mpCtm);
    addInputVariable("Csfct", "SFC coefficient", "", 0.1304, &mpCsfct);
    addInputVariable("Csfcm", "SFC Mach coefficient", "", 0.13045134663401256, &mpCsfcm);
    addInputVariable("e", "Base of natural logarithm", "", 2.71828, &mpE);
    addOutputVariable("thrust", "Thrust", "N", 5000.0, &mpThrust);
    addOutputVariable("Shspeed", "Normalised shaft speed", "", 1.0, &mpShspeed);
    addOutputVariable("qmfuel", "Fuel mass flow", "kg/s", 1.0, &mpQmfuel);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"T", "p0", "thrustmax", "SFC0", "thau", "Ctm", "Csfct", "Csfcm", "e"}, false);
}

// Thrust, reference shaft speed and SFC from the previous shaft speed.
void AeroJetEngine::explicitPart()
{
    const double rho = *mpRho, Vsound = *mpVsound, speed = *mpSpeed, uin = *mpUin, e = mE;
    const double mach = speed / Vsound;
    mThrust = 0.8207 * std::pow(e, 0.1304 * mach) * std::pow(rho, 0.8853) * std::pow(mShspeed, 3.104) * mThrustmax;
    mShspeedref = std::pow(limit(uin, 0.0, 1.0), 0.323);
    mSFC = 0.000017638 * std::pow(e, 0.4453 * mach) * std::pow(mShspeed, 0.00459) / std::pow(rho, 0.126478);
}

void AeroJetEngine::initialize()
{
    // Hopsan quirk: these are sampled only here (the coefficient inputs are unused).
    mThrustmax = *mpThrustmax;
    mThau = *mpThau;
    mE = *mpE;
    mThrust = *mpThrust;
    mShspeed = *mpShspeed;
    mQmfuel = *mpQmfuel;
    explicitPart();
    const double dt = mTimestep;
    mDelayed1 = (dt * mShspeed - dt * mShspeedref - 2.0 * mShspeed * mThau) / (dt + 2.0 * mThau);
}

void AeroJetEngine::simulateOneTimestep()
{
    const double dt = mTimestep, thau = mThau;
    explicitPart();

    double S = mShspeed;
    for (int iter = 1; iter <= 2; ++iter) {
        const double F0 = S - dt * mShspeedref / (dt + 2.0 * thau) + mDelayed1;
        S = S - (iter == 1 ? 1.0 : 0.67) * F0;
        mQmfuel = mSFC * mThrust;
    }
    mShspeed = S;
    mDelayed1 = (dt * mShspeed - dt * mShspeedref - 2.0 * mShspeed * thau) / (dt + 2.0 * thau);

    *mpThrust = mThrust;
    *mpShspeed = mShspeed;
    *mpQmfuel = mQmfuel;
}

TLMHUB_REGISTER_COMPONENT(AeroJetEngine, "Aero")

} // namespace tlmhub
