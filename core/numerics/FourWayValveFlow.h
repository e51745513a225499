// The flows of a four-port valve (P, T, A, B) through its turbulent metering edges P-A, P-B,
// A-T, B-T and, in some types, P-T, with the cavitation rule Hopsan's valves share: a port
// whose pressure would fall below zero is taken as a zero-pressure source (c = Zc = 0) and
// all flows are solved once more, without clamping afterwards.
#pragma once

#include "core/numerics/TurbulentFlowFunction.h"

namespace tlmhub {

// A port's characteristic: its wave variable and impedance.
struct TlmWave {
    double c = 0.0;
    double Zc = 0.0;

    double pressure(double q) const { return c + q * Zc; }
};

struct FourWayValveEdges {
    const TurbulentFlowFunction& pa;
    const TurbulentFlowFunction& pb;
    const TurbulentFlowFunction& at;
    const TurbulentFlowFunction& bt;
    const TurbulentFlowFunction* pt = nullptr; // only in valves with a P-T edge
};

// Flows into the valve at each port; after solveFourWayValve the ports hold the
// characteristics the flows were solved with, so port.pressure(q) is the port's pressure.
struct FourWayValveFlows {
    double p = 0.0, t = 0.0, a = 0.0, b = 0.0;
};

inline FourWayValveFlows fourWayValveFlows(const FourWayValveEdges& edges, const TlmWave& P, const TlmWave& T,
                                           const TlmWave& A, const TlmWave& B)
{
    const double qpa = edges.pa.getFlow(P.c, A.c, P.Zc, A.Zc);
    const double qpb = edges.pb.getFlow(P.c, B.c, P.Zc, B.Zc);
    const double qat = edges.at.getFlow(A.c, T.c, A.Zc, T.Zc);
    const double qbt = edges.bt.getFlow(B.c, T.c, B.Zc, T.Zc);
    FourWayValveFlows q;
    q.a = qpa - qat;
    q.b = qpb - qbt;
    if (edges.pt) {
        const double qpt = edges.pt->getFlow(P.c, T.c, P.Zc, T.Zc);
        q.p = -qpa - qpb - qpt;
        q.t = qat + qbt + qpt;
    } else {
        q.p = -qpa - qpb;
        q.t = qat + qbt;
    }
    return q;
}

// Replaces a port that would cavitate at flow q by a zero-pressure source; true if it did.
inline bool cavitates(TlmWave& port, double q)
{
    if (port.pressure(q) >= 0.0) return false;
    port = TlmWave{};
    return true;
}

inline FourWayValveFlows solveFourWayValve(const FourWayValveEdges& edges, TlmWave& P, TlmWave& T, TlmWave& A,
                                           TlmWave& B)
{
    const FourWayValveFlows q = fourWayValveFlows(edges, P, T, A, B);
    // Every port is checked, then one more solve if any cavitated.
    bool cavitation = cavitates(A, q.a);
    cavitation = cavitates(B, q.b) || cavitation;
    cavitation = cavitates(P, q.p) || cavitation;
    cavitation = cavitates(T, q.t) || cavitation;
    return cavitation ? fourWayValveFlows(edges, P, T, A, B) : q;
}

} // namespace tlmhub
