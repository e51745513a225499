#pragma once
// Newton solution shared by Hopsan's generated multi-port spool valves (HydraulicValve43
// and relatives): N hydraulic ports joined by turbulent edges q = K*signedSquareL(dp, plam).
// Unknowns are the port flows q[0..N) then the port pressures p[0..N); each port obeys
// q_k = +-sum of its edge flows and p_k = lowLimit(c_k + q_k*Zc_k*onPositive(p_k), 0).
// Two Newton iterations per step from the previous step's values, as the generated code.
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

#include <vector>

namespace tlmhub {

class HydraulicEdgeNetwork {
public:
    struct Edge {
        int from; // port index; flow from -> to is positive for p_from > p_to
        int to;
        double K;
        // A sensing edge draws on `from` only: its flow is not booked at `to` (load-sensing
        // ports of the generated valves are modelled so).
        bool sensing = false;
    };

    explicit HydraulicEdgeNetwork(int ports)
        : q(ports, 0.0), p(ports, 0.0), mN(ports), mJ(2 * ports, 2 * ports), mF(2 * ports), mX(2 * ports),
          mSolver(2 * ports)
    {
    }

    std::vector<double> q, p; // solution, also the start point of the next step

    // c, Zc: the ports' wave variables and impedances this step. False on a singular Jacobian.
    bool solve(const std::vector<Edge>& edges, const double* c, const double* Zc, double plam)
    {
        for (int k = 0; k < mN; ++k) { mX[k] = q[k]; mX[mN + k] = p[k]; }
        for (int iter = 1; iter <= 2; ++iter) {
            for (int r = 0; r < 2 * mN; ++r) {
                mF[r] = 0.0;
                for (int col = 0; col < 2 * mN; ++col) mJ[r][col] = 0.0;
            }
            for (int k = 0; k < mN; ++k) {
                // Flow balance rows: q_k plus the edge flows leaving port k.
                mF[k] = q[k];
                mJ[k][k] = 1.0;
                const double a = c[k] + q[k] * Zc[k] * onPositive(p[k]);
                mF[mN + k] = p[k] - lowLimit(a, 0.0);
                mJ[mN + k][k] = -Zc[k] * dxLowLimit(a, 0.0) * onPositive(p[k]);
                mJ[mN + k][mN + k] = 1.0;
            }
            for (const Edge& e : edges) {
                const double dp = p[e.from] - p[e.to];
                const double f = e.K * signedSquareL(dp, plam);
                const double df = e.K * dxSignedSquareL(dp, plam);
                mF[e.from] += f;
                mJ[e.from][mN + e.from] += df;
                mJ[e.from][mN + e.to] -= df;
                if (e.sensing) continue;
                mF[e.to] -= f;
                mJ[e.to][mN + e.from] -= df;
                mJ[e.to][mN + e.to] += df;
            }
            if (!mSolver.solve(mJ, mF, mX, iter)) return false;
            for (int k = 0; k < mN; ++k) { q[k] = mX[k]; p[k] = mX[mN + k]; }
        }
        return true;
    }

private:
    int mN;
    Matrix mJ;
    Vec mF, mX;
    EquationSystemSolver mSolver;
};

} // namespace tlmhub
