#include "core/components/hydraulic/HydraulicQPsrc.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void HydraulicQPsrc::configure()
{
    mpP1 = addPowerPort("P1", NodeType::Hydraulic);
    // Old-style optional signal ports that fall back to a plain parameter.
    mpPqinput = addReadPort("Pqinput", NodeType::Signal, false);
    mpPpinput = addReadPort("Ppinput", NodeType::Signal, false);
    addConstant("qinput", "Flow", "m3/s", 0.0, mQinput);
    addConstant("pinput", "Pressure (not used)", "Pa", 1.0e5, mPinput);
    addOutputVariable("Pcout", "Wave variable at P1", "Pa", 0.0, &mpPcout);
    addOutputVariable("PZcout", "Characteristic impedance at P1", "Pa s/m^3", 0.0, &mpPZcout);
}

void HydraulicQPsrc::initialize()
{
    mpP1_p = getSafeNodeDataPtr(mpP1, NodeHydraulic::Pressure);
    mpP1_q = getSafeNodeDataPtr(mpP1, NodeHydraulic::Flow);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeHydraulic::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeHydraulic::CharImpedance);
    mpQ = mpPqinput->isConnected() ? getSafeNodeDataPtr(mpPqinput, NodeSignal::Value) : &mQinput;
}

void HydraulicQPsrc::simulateOneTimestep()
{
    const double c = *mpP1_c, Zc = *mpP1_Zc;
    const double q = *mpQ;
    const double p = c + Zc * q;
    *mpP1_q = q;
    *mpP1_p = p;
    *mpPcout = c;
    *mpPZcout = Zc;
}

TLMHUB_REGISTER_COMPONENT(HydraulicQPsrc, "Hydraulic")

} // namespace tlmhub
