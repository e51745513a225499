#include "core/components/hydraulic/HydraulicFuelTankG.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void HydraulicFuelTankG::configure()
{
    mpPT = addPowerPort("PT", NodeType::Hydraulic);

    addInputVariable("gx", "acceleration", "m/s^2", 9.82, &mp_gx);
    addInputVariable("rhofuel", "Fuel density", "kg/m^3", 700.0, &mp_rhofuel);
    addInputVariable("p0", "tank pressure", "Pa", 1.0e5, &mp_p0);
    addInputVariable("hf", "fuel in tank height", "m", 5.0, &mp_hf);
    addInputVariable("massfuel0", "The initial fuel mass", "kg", 1000.0, &mp_massfuel0);
    addInputVariable("massfuelmax", "fuelmass at full tank", "kg", 1000.0, &mp_massfuelmax);
    addOutputVariable("massfuel", "Fuel mass", "kg", 0.0, &mp_massfuel);
    addOutputVariable("consfuel", "Consumed fuel mass", "kg", 0.0, &mp_consfuel);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"rhofuel", "p0", "hf", "massfuel0", "massfuelmax"}, false);
}

void HydraulicFuelTankG::initialize()
{
    mpPT_q = getSafeNodeDataPtr(mpPT, NodeHydraulic::Flow);
    mpPT_c = getSafeNodeDataPtr(mpPT, NodeHydraulic::WaveVariable);
    mpPT_Zc = getSafeNodeDataPtr(mpPT, NodeHydraulic::CharImpedance);

    rhofuel = *mp_rhofuel; p0 = *mp_p0; hf = *mp_hf;
    massfuel0 = *mp_massfuel0; massfuelmax = *mp_massfuelmax;
    // As Hopsan, nothing is written here: the first step sets c and Zc.
    mConsfuel = *mp_consfuel;
    mPrevQ = *mpPT_q;
}

void HydraulicFuelTankG::simulateOneTimestep()
{
    // Flow out of the tank (q < 0 at PT) is consumed fuel; trapezoidal rule, the
    // consumed mass kept within [0, massfuel0 + 1e-4].
    const double q = *mpPT_q;
    mConsfuel = limit(mConsfuel - mTimestep * rhofuel * (q + mPrevQ) / 2.0, 0.0, 0.0001 + massfuel0);
    mPrevQ = q;

    const double massfuel = massfuel0 - mConsfuel;
    const double level = hf * massfuel / massfuelmax;
    *mpPT_c = (p0 + *mp_gx * level * rhofuel) * onPositive(massfuel);
    *mpPT_Zc = 0.0;
    *mp_massfuel = massfuel;
    *mp_consfuel = mConsfuel;
}

TLMHUB_REGISTER_COMPONENT(HydraulicFuelTankG, "Hydraulic")

} // namespace tlmhub
