#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Q-type set of three masses in one dimension (Hopsan folder Special/MechanicB). Mass k
// sits on port Pmk; M2 and M3 are each coupled to M1 by viscous and dry friction, and every
// mass has viscous and dry friction to ground and its own stroke limits. 9 unknowns, two
// damped Newton iterations per step. Documented in
// docs/components/electric-mechanic-other.md, "MechanicM3load1D".
class MechanicM3load1D : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    // Input variable values of one step (all are read every step, as in Hopsan).
    struct Inputs {
        double m[3];                  // masses, kg
        double b[3];                  // viscous friction to ground, Ns/m
        double b12, b13;              // viscous friction M1-M2, M1-M3, Ns/m
        double fc[3];                 // dry friction to ground, N
        double fc12, fc13;            // dry friction M1-M2, M1-M3, N
        double bfc;                   // numerical friction factor
        double xMin[3], xMax[3];      // stroke limits of the port positions, m
        double offset[3], dir[3];     // position offset (m) and direction (+-1) of the outputs
    };
    // Forces on the masses that the trapezoidal step treats as known, and their
    // derivatives with respect to the three port velocities.
    struct Loads {
        double fr[3];                 // dry friction to ground (positive along the port's x)
        double fr12, fr13;            // dry friction between the pairs, acting on M1
        double g[3];                  // everything but each mass's own viscous terms
        double dg[3][3];              // dg[k][j] = d g[k] / d v_j
    };

    Inputs readInputs() const;
    Loads loads(const Inputs& in) const;
    void computeDelayedParts(const Inputs& in, const Loads& l);

    Port* mpPm[3] = {nullptr, nullptr, nullptr};
    double *mpFc[3] = {}, *mpFc12 = nullptr, *mpFc13 = nullptr;
    double *mpMass[3] = {}, *mpB[3] = {}, *mpB12 = nullptr, *mpB13 = nullptr, *mpBfc = nullptr;
    double *mpXMin[3] = {}, *mpXMax[3] = {}, *mpOffset[3] = {}, *mpDir[3] = {};
    double *mpPosOut[3] = {}, *mpVelOut[3] = {}, *mpFricOut[3] = {};
    double *mpFric12Out = nullptr, *mpFric13Out = nullptr;
    // Node slots of port k: force, position, velocity, wave variable, impedance, mass.
    double *mpF[3] = {}, *mpX[3] = {}, *mpV[3] = {}, *mpC[3] = {}, *mpZc[3] = {}, *mpMe[3] = {};

    // Unknowns [v1 v2 v3 x1 x2 x3 f1 f2 f3], kept between steps.
    double mV[3] = {}, mX[3] = {}, mF[3] = {};
    // Delayed parts of the last step: velocity (mDv) and position (mDx) of each mass.
    double mDv[3] = {}, mDx[3] = {};

    Matrix mJac;
    Vec mEq;
    Vec mState;
    EquationSystemSolver mSolver{9};
    bool mSingularReported = false;
};

} // namespace tlmhub
