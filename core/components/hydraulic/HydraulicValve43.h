#pragma once
#include "core/Component.h"
#include "core/components/hydraulic/HydraulicEdgeNetwork.h"

namespace tlmhub {

// Q-type generated 4/3 spool valve (P, T, A, B); spool position given by the input xv
// (no spool dynamics); flows solved by two Newton iterations per step.
class HydraulicValve43 : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    std::vector<HydraulicEdgeNetwork::Edge> edges(double xv) const;

    enum { P, T, A, B };
    Port* mpPort[4] = {};
    double *mp_p[4] = {}, *mp_q[4] = {}, *mp_c[4] = {}, *mp_Zc[4] = {};
    double *mp_xv = nullptr, *mp_rho = nullptr, *mp_Cq = nullptr, *mp_Sd = nullptr;
    double *mp_Frap = nullptr, *mp_Frat = nullptr, *mp_Frbp = nullptr, *mp_Frbt = nullptr;
    double *mp_Xap0 = nullptr, *mp_Xat0 = nullptr, *mp_Xbp0 = nullptr, *mp_Xbt0 = nullptr;
    double *mp_Xvmax = nullptr, *mp_plam = nullptr;

    // Parameters are read once at initialisation (generated-component convention).
    double rho = 0, Cq = 0, Sd = 0, Frap = 0, Frat = 0, Frbp = 0, Frbt = 0;
    double Xap0 = 0, Xat0 = 0, Xbp0 = 0, Xbt0 = 0, Xvmax = 0, plam = 0;
    HydraulicEdgeNetwork mNet{4};
};

} // namespace tlmhub
