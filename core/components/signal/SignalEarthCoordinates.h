#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Integrates north/east ground speed into latitude/longitude (degrees, spherical
// earth) with time compression, and integrates effective time. Generated-solver
// type; initialisation already advances the state one step.
class SignalEarthCoordinates : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpTimecomp = nullptr;
    double* mpVxcg = nullptr;
    double* mpVycg = nullptr;
    double* mpR = nullptr;
    double* mpTimeE = nullptr;
    double* mpLongitude = nullptr;
    double* mpLattitude = nullptr;
    // Generated-solver pattern: two damped Newton iterations per step.
    Matrix mJ{3, 3};
    Vec mF{3};
    Vec mX{3};
    EquationSystemSolver mSolver{3};

    double mLat = 0.0, mLon = 0.0, mTE = 0.0;
    double mD1 = 0.0, mD2 = 0.0, mD3 = 0.0;
    void computeDelayedParts(double h, double tc, double vx, double vy, double R);
};

} // namespace tlmhub
