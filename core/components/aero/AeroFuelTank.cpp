#include "core/components/aero/AeroFuelTank.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void AeroFuelTank::configure()
{
    addInputVariable("massflow", "Fuel mass flow", "kg/s", 0.0, &mpMassflow);
    addInputVariable("massfuel0", "Initial fuel mass", "kg", 0.0, &mpMassfuel0);
    addOutputVariable("massfuel", "Fuel mass", "kg", 0.0, &mpMassfuel);
    addOutputVariable("consfuel", "Consumed fuel", "kg", 0.0, &mpConsfuel);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"massfuel0"}, false);
}

void AeroFuelTank::initialize()
{
    mMassfuel0 = *mpMassfuel0;
    mMassfuel = *mpMassfuel;
    mConsfuel = *mpConsfuel;
    mDelayed1 = (-2.0 * mConsfuel - *mpMassflow * mTimestep) / 2.0;
}

void AeroFuelTank::simulateOneTimestep()
{
    const double massflow = *mpMassflow;
    const double dt = mTimestep;
    // One unknown with unit Jacobian: damped Newton iterations done inline.
    double consfuel = mConsfuel;
    for (int iter = 1; iter <= 2; ++iter) {
        const double F0 = consfuel - limit(massflow * dt / 2.0 - mDelayed1, 0.0, mMassfuel0);
        consfuel = consfuel - (iter == 1 ? 1.0 : 0.67) * F0;
        mMassfuel = limit(mMassfuel0 - consfuel, 0.0, mMassfuel0);
    }
    mConsfuel = consfuel;
    mDelayed1 = (-2.0 * mConsfuel - massflow * dt) / 2.0;

    *mpMassfuel = mMassfuel;
    *mpConsfuel = mConsfuel;
}

TLMHUB_REGISTER_COMPONENT(AeroFuelTank, "Aero")

} // namespace tlmhub
