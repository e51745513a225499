#include "core/components/pneumatic/PneumaticQsrc.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void PneumaticQsrc::configure()
{
    mpPp1 = addPowerPort("Pp1", NodeType::Pneumatic);
    addInputVariable("qminput", "Mass flow", "kg/s", 0.0, &mpQminput);
    addInputVariable("Tinput", "Source temperature", "K", 273.0, &mpTinput);
    addInputVariable("cv", "Heat coefficient at constant volume", "J/(kg K)", 718.0, &mpCv);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"cv"}, false);
}

void PneumaticQsrc::initialize()
{
    mpPp1_p = getSafeNodeDataPtr(mpPp1, NodePneumatic::Pressure);
    mpPp1_qm = getSafeNodeDataPtr(mpPp1, NodePneumatic::MassFlow);
    mpPp1_T = getSafeNodeDataPtr(mpPp1, NodePneumatic::Temperature);
    mpPp1_dE = getSafeNodeDataPtr(mpPp1, NodePneumatic::EnergyFlow);
    mpPp1_c = getSafeNodeDataPtr(mpPp1, NodePneumatic::WaveVariable);
    mpPp1_Zc = getSafeNodeDataPtr(mpPp1, NodePneumatic::CharImpedance);
    // Hopsan quirk: cv is sampled only here.
    mCv = *mpCv;
}

void PneumaticQsrc::simulateOneTimestep()
{
    const double T = *mpPp1_T, c = *mpPp1_c, Zc = *mpPp1_Zc;
    const double qm = *mpQminput;
    const double Tinput = *mpTinput;
    const double cv = mCv;

    // Outflow carries the node temperature, inflow the source temperature.
    const double dE = cv * qm * T * onNegative(qm) + cv * qm * Tinput * onPositive(qm);
    const double p = c + dE * Zc;

    *mpPp1_p = p;
    *mpPp1_qm = qm;
    *mpPp1_dE = dE;
}

TLMHUB_REGISTER_COMPONENT(PneumaticQsrc, "Pneumatic")

} // namespace tlmhub
