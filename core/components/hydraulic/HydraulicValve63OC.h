#pragma once
#include "core/Component.h"
#include "core/components/hydraulic/HydraulicEdgeNetwork.h"

namespace tlmhub {

// Q-type generated 6/3 open-centre spool valve: P, T, A, B as the generated 4/3 valve
// plus an open-centre gallery Pocp -> Poct that is open at the centre and closes as the
// spool moves either way. Spool position given by the input xv.
class HydraulicValve63OC : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    std::vector<HydraulicEdgeNetwork::Edge> edges(double xv) const;

    enum { P, T, A, B, OCP, OCT };
    Port* mpPort[6] = {};
    double *mp_p[6] = {}, *mp_q[6] = {}, *mp_c[6] = {}, *mp_Zc[6] = {};
    double *mp_xv = nullptr, *mp_rho = nullptr, *mp_Cq = nullptr, *mp_Sd = nullptr;
    double *mp_Frap = nullptr, *mp_Frat = nullptr, *mp_Frbp = nullptr, *mp_Frbt = nullptr, *mp_Froc = nullptr;
    double *mp_Xap0 = nullptr, *mp_Xat0 = nullptr, *mp_Xbp0 = nullptr, *mp_Xbt0 = nullptr, *mp_Xoc0 = nullptr;
    double *mp_Xvmax = nullptr, *mp_plam = nullptr;

    // Parameters are read once at initialisation (generated-component convention).
    double rho = 0, Cq = 0, Sd = 0, Frap = 0, Frat = 0, Frbp = 0, Frbt = 0, Froc = 0;
    double Xap0 = 0, Xat0 = 0, Xbp0 = 0, Xbt0 = 0, Xoc0 = 0, Xvmax = 0, plam = 0;
    HydraulicEdgeNetwork mNet{6};
};

} // namespace tlmhub
