#pragma once
#include "core/Component.h"
#include "core/components/hydraulic/HydraulicEdgeNetwork.h"

namespace tlmhub {

// Q-type generated 4/3 load-sensing spool valve: P, T, A, B as HydraulicValve43 (with
// overlaps) plus a load-sensing port Pls that senses A or B through small edges and is
// drained to T around the centre. Spool position given by the input xv.
class HydraulicValve43LS : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    std::vector<HydraulicEdgeNetwork::Edge> edges(double xv) const;

    enum { P, T, A, B, LS };
    Port* mpPort[5] = {};
    double *mp_p[5] = {}, *mp_q[5] = {}, *mp_c[5] = {}, *mp_Zc[5] = {};
    double *mp_xv = nullptr, *mp_rho = nullptr, *mp_Cq = nullptr, *mp_Sd = nullptr;
    double *mp_Frap = nullptr, *mp_Frat = nullptr, *mp_Frbp = nullptr, *mp_Frbt = nullptr, *mp_wls = nullptr;
    double *mp_Xap0 = nullptr, *mp_Xat0 = nullptr, *mp_Xbp0 = nullptr, *mp_Xbt0 = nullptr;
    double *mp_Xlsa0 = nullptr, *mp_Xlsb0 = nullptr, *mp_Xls0 = nullptr;
    double *mp_Xvmax = nullptr, *mp_Xvlsmax = nullptr, *mp_plam = nullptr;

    // Parameters are read once at initialisation (generated-component convention).
    double rho = 0, Cq = 0, Sd = 0, Frap = 0, Frat = 0, Frbp = 0, Frbt = 0, wls = 0;
    double Xap0 = 0, Xat0 = 0, Xbp0 = 0, Xbt0 = 0, Xlsa0 = 0, Xlsb0 = 0, Xls0 = 0;
    double Xvmax = 0, Xvlsmax = 0, plam = 0;
    HydraulicEdgeNetwork mNet{5};
};

} // namespace tlmhub
