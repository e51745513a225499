#include "core/components/hydraulic/HydraulicValve43LS.h"

#include "core/ComponentFactory.h"

#include <cmath>

namespace tlmhub {

void HydraulicValve43LS::configure()
{
    mpPort[P] = addPowerPort("Pp", NodeType::Hydraulic);
    mpPort[T] = addPowerPort("Pt", NodeType::Hydraulic);
    mpPort[A] = addPowerPort("Pa", NodeType::Hydraulic);
    mpPort[B] = addPowerPort("Pb", NodeType::Hydraulic);
    mpPort[LS] = addPowerPort("Pls", NodeType::Hydraulic);

    addInputVariable("xv", "Spool position", "m", 0.0, &mp_xv);
    addInputVariable("rho", "Oil density", "kg/m^3", 860.0, &mp_rho);
    addInputVariable("Cq", "Flow coefficient", "-", 0.67, &mp_Cq);
    addInputVariable("Sd", "Spool diameter", "m", 0.01, &mp_Sd);
    addInputVariable("Frap", "Spool circle fraction (P-A)", "-", 1.0, &mp_Frap);
    addInputVariable("Frat", "Spool circle fraction (A-T)", "-", 1.0, &mp_Frat);
    addInputVariable("Frbp", "Spool circle fraction (P-B)", "-", 1.0, &mp_Frbp);
    addInputVariable("Frbt", "Spool circle fraction (B-T)", "-", 1.0, &mp_Frbt);
    addInputVariable("wls", "Area gradient LS-port", "m", 0.01, &mp_wls);
    addInputVariable("Xap0", "Overlap", "m", 0.0003, &mp_Xap0);
    addInputVariable("Xat0", "Overlap", "m", 0.0003, &mp_Xat0);
    addInputVariable("Xbp0", "Overlap", "m", 0.0003, &mp_Xbp0);
    addInputVariable("Xbt0", "Overlap", "m", 0.0003, &mp_Xbt0);
    addInputVariable("Xlsa0", "Overlap", "m", 0.0003, &mp_Xlsa0);
    addInputVariable("Xlsb0", "Overlap", "m", 0.0003, &mp_Xlsb0);
    addInputVariable("Xls0", "Zero opening LS port", "m", 0.0003, &mp_Xls0);
    addInputVariable("Xvmax", "Max valve opening", "m", 0.01, &mp_Xvmax);
    addInputVariable("Xvlsmax", "Max opening LS port", "m", 0.001, &mp_Xvlsmax);
    addInputVariable("plam", "Turbulence onset pressure", "Pa", 1.0e4, &mp_plam);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"rho", "Cq", "Sd", "Frap", "Frat", "Frbp", "Frbt", "wls", "Xap0", "Xat0", "Xbp0",
                      "Xbt0", "Xlsa0", "Xlsb0", "Xls0", "Xvmax", "Xvlsmax", "plam"}, false);
}

std::vector<HydraulicEdgeNetwork::Edge> HydraulicValve43LS::edges(double xv) const
{
    const double Ks = 1.4142135623730951 * Cq / std::sqrt(rho);
    const double k = 3.14159 * Ks * Sd;
    // As Hopsan: the main openings are all measured from Xap0; the sensing edges draw on
    // Pls only (their flow is not taken from A, B or T).
    return {{P, A, k * Frap * limit(-Xap0 + xv, 0.0, -Xap0 + Xvmax)},
            {T, A, k * Frat * limit(-Xap0 - xv, 0.0, -Xat0 + Xvmax)},
            {P, B, k * Frbp * limit(-Xap0 - xv, 0.0, -Xbp0 + Xvmax)},
            {T, B, k * Frbt * limit(-Xap0 + xv, 0.0, -Xbt0 + Xvmax)},
            {LS, A, Ks * wls * limit(-Xlsa0 + xv, 0.0, -Xlsa0 + Xvlsmax), true},
            {LS, B, Ks * wls * limit(-Xlsb0 - xv, 0.0, -Xlsb0 + Xvlsmax), true},
            {LS, T, Ks * wls * limit(Xls0 - std::fabs(xv), 0.0, Xls0), true}};
}

void HydraulicValve43LS::initialize()
{
    for (int k = 0; k < 5; ++k) {
        mp_p[k] = getSafeNodeDataPtr(mpPort[k], NodeHydraulic::Pressure);
        mp_q[k] = getSafeNodeDataPtr(mpPort[k], NodeHydraulic::Flow);
        mp_c[k] = getSafeNodeDataPtr(mpPort[k], NodeHydraulic::WaveVariable);
        mp_Zc[k] = getSafeNodeDataPtr(mpPort[k], NodeHydraulic::CharImpedance);
        mNet.p[k] = *mp_p[k];
        mNet.q[k] = *mp_q[k];
    }
    rho = *mp_rho; Cq = *mp_Cq; Sd = *mp_Sd;
    Frap = *mp_Frap; Frat = *mp_Frat; Frbp = *mp_Frbp; Frbt = *mp_Frbt; wls = *mp_wls;
    Xap0 = *mp_Xap0; Xat0 = *mp_Xat0; Xbp0 = *mp_Xbp0; Xbt0 = *mp_Xbt0;
    Xlsa0 = *mp_Xlsa0; Xlsb0 = *mp_Xlsb0; Xls0 = *mp_Xls0;
    Xvmax = *mp_Xvmax; Xvlsmax = *mp_Xvlsmax; plam = *mp_plam;
}

void HydraulicValve43LS::simulateOneTimestep()
{
    double c[5], Zc[5];
    for (int k = 0; k < 5; ++k) { c[k] = *mp_c[k]; Zc[k] = *mp_Zc[k]; }
    if (!mNet.solve(edges(*mp_xv), c, Zc, plam)) {
        stopSimulation("HydraulicValve43LS: singular Jacobian");
    }
    for (int k = 0; k < 5; ++k) { *mp_p[k] = mNet.p[k]; *mp_q[k] = mNet.q[k]; }
}

TLMHUB_REGISTER_COMPONENT(HydraulicValve43LS, "Hydraulic")

} // namespace tlmhub
