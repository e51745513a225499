#pragma once
#include "core/Component.h"
#include "core/numerics/EquationSystemSolver.h"
#include "core/numerics/Matrix.h"

namespace tlmhub {

// Common rigid-body 6-DOF core shared by AeroVehicleTVC, AeroAircraft6DOFS and
// AeroAircraft6DOFSS: 13 unknowns (Ub, Vb, Wb, Pb, Qb, Rb, q0..q3, xcg, ycg, zcg),
// trapezoidal discretisation, two damped Newton iterations per step.
struct Aero6DofCore {
    // State (unknowns).
    double Ub = 0, Vb = 0, Wb = 0, Pb = 0, Qb = 0, Rb = 0;
    double q0 = 0, q1 = 0, q2 = 0, q3 = 0;
    double xcg = 0, ycg = 0, zcg = 0;
    // Explicit quantities held constant during the iterations of one step.
    double Fx = 0, Fy = 0, Fz = 0, Lb = 0, Mb = 0, Nb = 0;
    double m = 1, Ix = 0, Iy = 0, Iz = 0, Ixz = 0, g = 0, k = 0;
    // Delayed parts d1..d13 (index 0..12).
    double d[13] = {};

    EquationSystemSolver solver{13};
    Matrix J{13, 13};
    Vec F{13}, X{13};

    // Attitude quaternion from Euler angles (roll Phi, pitch Theta, heading Psi).
    void setQuaternionFromEuler(double Phi, double Theta, double Psi);
    // Direction cosines from the current quaternion.
    void dcm(double& r11, double& r12, double& r13, double& r21, double& r22, double& r23, double& r31,
             double& r32, double& r33) const;
    // One damped Newton iteration (iter 1-based); false if the Jacobian is singular.
    bool iterate(int iter, double dt);
    // Delayed parts from the current state.
    void computeDelayedParts(double dt);
    // Common outputs.
    void velocitiesEarth(double& vx, double& vy, double& vz) const;
    void eulerAngles(double& Phi, double& Theta, double& Psi) const;

private:
    void stateToVec();
    void vecToState();
};

// C-type rigid-body 6-DOF vehicle with two thrust-vector-controlled engines.
class AeroVehicleTVC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    void explicitQuantities();
    void writeOutputs();
    void evalOutputs();

    Port *mpPtvcly = nullptr, *mpPtvclz = nullptr, *mpPtvcry = nullptr, *mpPtvcrz = nullptr;
    double *mpAly = nullptr, *mpAlz = nullptr, *mpAry = nullptr, *mpArz = nullptr;
    double *mpCly = nullptr, *mpZcly = nullptr, *mpClz = nullptr, *mpZclz = nullptr, *mpCry = nullptr,
           *mpZcry = nullptr, *mpCrz = nullptr, *mpZcrz = nullptr;
    double mCly = 0, mZcly = 0, mClz = 0, mZclz = 0, mCry = 0, mZcry = 0, mCrz = 0, mZcrz = 0;

    // Per-step inputs.
    double *mpThrustl = nullptr, *mpThrustr = nullptr, *mpG0 = nullptr, *mpMfuel = nullptr, *mpMcargo = nullptr,
           *mpRho = nullptr, *mpVturbx = nullptr, *mpVturby = nullptr, *mpVturbz = nullptr, *mpWturbx = nullptr,
           *mpWturby = nullptr, *mpWturbz = nullptr;
    // Inputs frozen at initialisation.
    double *mpCd0b = nullptr, *mpCtvc = nullptr, *mpCLalphabh = nullptr, *mpCLalphabv = nullptr,
           *mpHthrust0 = nullptr, *mpIx = nullptr, *mpIxz = nullptr, *mpIy = nullptr, *mpIz = nullptr,
           *mpMe = nullptr, *mpSbh = nullptr, *mpSbv = nullptr, *mpXbach = nullptr, *mpXbacv = nullptr,
           *mpXbcge = nullptr, *mpXcargo = nullptr, *mpXfuel = nullptr, *mpXeng = nullptr, *mpYeng = nullptr,
           *mpKground = nullptr, *mpCground = nullptr;
    double mCd0b = 0, mCLalphabh = 0, mCLalphabv = 0, mMe = 0, mSbh = 0, mSbv = 0, mXbach = 0, mXbacv = 0,
           mXbcge = 0, mXcargo = 0, mXfuel = 0, mXeng = 0, mYeng = 0;

    // Outputs.
    double *mpXcg = nullptr, *mpYcg = nullptr, *mpZcg = nullptr, *mpVx = nullptr, *mpVy = nullptr, *mpVz = nullptr,
           *mpPsi = nullptr, *mpThetao = nullptr, *mpPhi = nullptr, *mpUb = nullptr, *mpVb = nullptr,
           *mpWb = nullptr, *mpPb = nullptr, *mpQb = nullptr, *mpRb = nullptr, *mpQ0 = nullptr, *mpQ1 = nullptr,
           *mpQ2 = nullptr, *mpQ3 = nullptr, *mpAlphaAttack = nullptr, *mpBetaSlip = nullptr,
           *mpAltitude = nullptr, *mpGfx = nullptr, *mpGfy = nullptr, *mpGfz = nullptr, *mpCL1 = nullptr,
           *mpCd1 = nullptr, *mpFax = nullptr, *mpFaz = nullptr;

    Aero6DofCore mCore;
    double mAlpha = 0, mBeta = 0;
    double mVx = 0, mVy = 0, mVz = 0, mPhi = 0, mThetao = 0, mPsi = 0;
};

} // namespace tlmhub
