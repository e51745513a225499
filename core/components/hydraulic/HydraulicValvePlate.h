#pragma once
#include "core/Component.h"
#include "core/numerics/Integrator.h"
#include "core/numerics/TurbulentFlowFunction.h"

#include <vector>

namespace tlmhub {

// Q-type valve plate of an axial piston machine: each piston chamber (one
// connection of multiport P1) sees a shaft-angle dependent groove area towards the
// A kidney and, half a turn later, towards the B kidney.
class HydraulicValvePlate : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double groove(double x, double start, double phi, double r, double R, double g1, double th11,
                  double th21, double g2, double th12, double th22) const;

    Port *mpP1 = nullptr, *mpPA = nullptr, *mpPB = nullptr;
    double *mpPhiP = nullptr, *mpPhi1 = nullptr, *mpPhi2 = nullptr, *mpDAlpha = nullptr;
    double *mpAlphaF = nullptr, *mpRf = nullptr, *mpTh1 = nullptr, *mpTh2 = nullptr;
    double *mpRho = nullptr, *mpMovement = nullptr;
    double *mpDebug1 = nullptr, *mpDebug2 = nullptr, *mpDebug3 = nullptr;

    std::size_t mN = 0;
    std::vector<double*> mvpP1_p, mvpP1_q, mvpP1_c, mvpP1_Zc;
    std::vector<double> mP1, mQ1, mC1, mZc1, mXva, mXvb;
    double *mpPA_p = nullptr, *mpPA_q = nullptr, *mpPA_c = nullptr, *mpPA_Zc = nullptr;
    double *mpPB_p = nullptr, *mpPB_q = nullptr, *mpPB_c = nullptr, *mpPB_Zc = nullptr;

    double mRf = 0.0;
    Integrator mIntegrator;
    TurbulentFlowFunction mTurb;
};

} // namespace tlmhub
