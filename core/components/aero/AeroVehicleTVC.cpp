#include "core/components/aero/AeroVehicleTVC.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

// ------------------------------------------------------------------ common 6-DOF core

void Aero6DofCore::setQuaternionFromEuler(double Phi, double Theta, double Psi)
{
    const double cphi = std::cos(Phi / 2.0), sphi = std::sin(Phi / 2.0);
    const double cth = std::cos(Theta / 2.0), sth = std::sin(Theta / 2.0);
    const double cpsi = std::cos(Psi / 2.0), spsi = std::sin(Psi / 2.0);
    q0 = cphi * cpsi * cth + sphi * spsi * sth;
    q1 = cpsi * cth * sphi - cphi * spsi * sth;
    q2 = cth * sphi * spsi + cphi * cpsi * sth;
    q3 = cphi * cth * spsi - cpsi * sphi * sth;
}

void Aero6DofCore::dcm(double& r11, double& r12, double& r13, double& r21, double& r22, double& r23, double& r31,
                       double& r32, double& r33) const
{
    r11 = q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3;
    r12 = 2.0 * (q1 * q2 - q0 * q3);
    r13 = 2.0 * (q0 * q2 + q1 * q3);
    r21 = 2.0 * (q1 * q2 + q0 * q3);
    r22 = q0 * q0 - q1 * q1 + q2 * q2 - q3 * q3;
    r23 = 2.0 * (q2 * q3 - q0 * q1);
    r31 = 2.0 * (q1 * q3 - q0 * q2);
    r32 = 2.0 * (q0 * q1 + q2 * q3);
    r33 = q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3;
}

void Aero6DofCore::stateToVec()
{
    X[0] = Ub;
    X[1] = Vb;
    X[2] = Wb;
    X[3] = Pb;
    X[4] = Qb;
    X[5] = Rb;
    X[6] = q0;
    X[7] = q1;
    X[8] = q2;
    X[9] = q3;
    X[10] = xcg;
    X[11] = ycg;
    X[12] = zcg;
}

void Aero6DofCore::vecToState()
{
    Ub = X[0];
    Vb = X[1];
    Wb = X[2];
    Pb = X[3];
    Qb = X[4];
    Rb = X[5];
    q0 = X[6];
    q1 = X[7];
    q2 = X[8];
    q3 = X[9];
    xcg = X[10];
    ycg = X[11];
    zcg = X[12];
}

bool Aero6DofCore::iterate(int iter, double dt)
{
    double r11, r12, r13, r21, r22, r23, r31, r32, r33;
    dcm(r11, r12, r13, r21, r22, r23, r31, r32, r33);
    const double H = onPositive(zcg);
    const double ge = g - k * zcg * H / m;
    const double Ia = Ix - Iy + Iz;
    const double D = 2.0 * Ixz * Ixz - 2.0 * Ix * Iz + Ixz * Ia * dt * Qb;
    const double E = 2.0 * Ix * Iz - 2.0 * Ixz * Ixz + Ixz * Ia * dt * Qb;
    const double Kq = Iy * Iz - Iz * Iz - Ixz * Ixz;
    const double Kp = Ixz * Ixz + Ix * (Ix - Iy);
    const double N3 = Iz * Lb + Ixz * Nb + Kq * Qb * Rb;
    const double N5 = Ixz * Lb + Ix * Nb + (Ix * Ix - Ix * Iy + Ixz * Ixz) * Pb * Qb;
    const double gf = m * g - k * zcg * H;

    F[0] = Ub - dt / 2.0 * ((Fx + gf * r31) / m + Rb * Vb - Qb * Wb) + d[0];
    F[1] = Vb - dt / 2.0 * ((Fy + gf * r32) / m - Rb * Ub + Pb * Wb) + d[1];
    F[2] = Wb - dt / 2.0 * ((Fz + gf * r33) / m + Qb * Ub - Pb * Vb) + d[2];
    F[3] = Pb + dt * N3 / D + d[3];
    F[4] = Qb - dt / (2.0 * Iy) * (Mb + (Iz - Ix) * Pb * Rb + Ixz * (Rb * Rb - Pb * Pb)) + d[4];
    F[5] = Rb - dt * N5 / E + d[5];
    F[6] = q0 + dt / 4.0 * (Pb * q1 + Qb * q2 + Rb * q3) + d[6];
    F[7] = q1 - dt / 4.0 * (Pb * q0 - Qb * q3 + Rb * q2) + d[7];
    F[8] = q2 - dt / 4.0 * (Pb * q3 + Qb * q0 - Rb * q1) + d[8];
    F[9] = q3 + dt / 4.0 * (Pb * q2 - Qb * q1 - Rb * q0) + d[9];
    F[10] = xcg - dt / 2.0 * (r11 * Ub + r12 * Vb + r13 * Wb) + d[10];
    F[11] = ycg - dt / 2.0 * (r21 * Ub + r22 * Vb + r23 * Wb) + d[11];
    F[12] = zcg - dt / 2.0 * (r31 * Ub + r32 * Vb + r33 * Wb) + d[12];

    for (int r = 0; r < 13; ++r) {
        for (int c = 0; c < 13; ++c) { J[r][c] = 0.0; }
    }
    // Columns: 0 Ub, 1 Vb, 2 Wb, 3 Pb, 4 Qb, 5 Rb, 6 q0, 7 q1, 8 q2, 9 q3, 10 xcg, 11 ycg, 12 zcg.
    J[0][0] = 1.0;
    J[0][1] = -dt * Rb / 2.0;
    J[0][2] = dt * Qb / 2.0;
    J[0][4] = dt * Wb / 2.0;
    J[0][5] = -dt * Vb / 2.0;
    J[0][6] = dt * q2 * ge;
    J[0][7] = -dt * q3 * ge;
    J[0][8] = dt * q0 * ge;
    J[0][9] = -dt * q1 * ge;
    J[0][12] = -k * dt * (q0 * q2 - q1 * q3) * H / m;

    J[1][0] = dt * Rb / 2.0;
    J[1][1] = 1.0;
    J[1][2] = -dt * Pb / 2.0;
    J[1][3] = -dt * Wb / 2.0;
    J[1][5] = dt * Ub / 2.0;
    J[1][6] = -dt * q1 * ge;
    J[1][7] = -dt * q0 * ge;
    J[1][8] = -dt * q3 * ge;
    J[1][9] = -dt * q2 * ge;
    J[1][12] = k * dt * (q0 * q1 + q2 * q3) * H / m;

    J[2][0] = -dt * Qb / 2.0;
    J[2][1] = dt * Pb / 2.0;
    J[2][2] = 1.0;
    J[2][3] = dt * Vb / 2.0;
    J[2][4] = -dt * Ub / 2.0;
    J[2][6] = -dt * q0 * ge;
    J[2][7] = dt * q1 * ge;
    J[2][8] = dt * q2 * ge;
    J[2][9] = -dt * q3 * ge;
    J[2][12] = k * dt * r33 * H / (2.0 * m);

    J[3][3] = 1.0;
    J[3][4] = dt * Kq * Rb / D - Ixz * Ia * dt * dt * N3 / (D * D);
    J[3][5] = dt * Kq * Qb / D;

    J[4][3] = dt * (2.0 * Ixz * Pb + (Ix - Iz) * Rb) / (2.0 * Iy);
    J[4][4] = 1.0;
    J[4][5] = -dt * ((Iz - Ix) * Pb + 2.0 * Ixz * Rb) / (2.0 * Iy);

    J[5][3] = -dt * Kp * Qb / E;
    J[5][4] = -dt * Kp * Pb / E + Ixz * Ia * dt * dt * N5 / (E * E);
    J[5][5] = 1.0;

    J[6][3] = dt * q1 / 4.0;
    J[6][4] = dt * q2 / 4.0;
    J[6][5] = dt * q3 / 4.0;
    J[6][6] = 1.0;
    J[6][7] = dt * Pb / 4.0;
    J[6][8] = dt * Qb / 4.0;
    J[6][9] = dt * Rb / 4.0;

    J[7][3] = -dt * q0 / 4.0;
    J[7][4] = dt * q3 / 4.0;
    J[7][5] = -dt * q2 / 4.0;
    J[7][6] = -dt * Pb / 4.0;
    J[7][7] = 1.0;
    J[7][8] = -dt * Rb / 4.0;
    J[7][9] = dt * Qb / 4.0;

    J[8][3] = -dt * q3 / 4.0;
    J[8][4] = -dt * q0 / 4.0;
    J[8][5] = dt * q1 / 4.0;
    J[8][6] = -dt * Qb / 4.0;
    J[8][7] = dt * Rb / 4.0;
    J[8][8] = 1.0;
    J[8][9] = -dt * Pb / 4.0;

    J[9][3] = dt * q2 / 4.0;
    J[9][4] = -dt * q1 / 4.0;
    J[9][5] = -dt * q0 / 4.0;
    J[9][6] = -dt * Rb / 4.0;
    J[9][7] = -dt * Qb / 4.0;
    J[9][8] = dt * Pb / 4.0;
    J[9][9] = 1.0;

    J[10][0] = -dt * r11 / 2.0;
    J[10][1] = -dt * r12 / 2.0;
    J[10][2] = -dt * r13 / 2.0;
    J[10][6] = -dt * (q0 * Ub - q3 * Vb + q2 * Wb);
    J[10][7] = -dt * (q1 * Ub + q2 * Vb + q3 * Wb);
    J[10][8] = -dt * (-q2 * Ub + q1 * Vb + q0 * Wb);
    J[10][9] = -dt * (-q3 * Ub - q0 * Vb + q1 * Wb);
    J[10][10] = 1.0;

    J[11][0] = -dt * r21 / 2.0;
    J[11][1] = -dt * r22 / 2.0;
    J[11][2] = -dt * r23 / 2.0;
    J[11][6] = dt * (-q3 * Ub - q0 * Vb + q1 * Wb);
    J[11][7] = dt * (-q2 * Ub + q1 * Vb + q0 * Wb);
    J[11][8] = dt * (-q1 * Ub - q2 * Vb - q3 * Wb);
    J[11][9] = dt * (-q0 * Ub + q3 * Vb - q2 * Wb);
    J[11][11] = 1.0;

    J[12][0] = -dt * r31 / 2.0;
    J[12][1] = -dt * r32 / 2.0;
    J[12][2] = -dt * r33 / 2.0;
    J[12][6] = -dt * (-q2 * Ub + q1 * Vb + q0 * Wb);
    J[12][7] = -dt * (q3 * Ub + q0 * Vb - q1 * Wb);
    J[12][8] = -dt * (-q0 * Ub + q3 * Vb - q2 * Wb);
    J[12][9] = -dt * (q1 * Ub + q2 * Vb + q3 * Wb);
    J[12][12] = 1.0;

    stateToVec();
    const bool ok = solver.solve(J, F, X, iter);
    vecToState();
    return ok;
}

void Aero6DofCore::computeDelayedParts(double dt)
{
    double r11, r12, r13, r21, r22, r23, r31, r32, r33;
    dcm(r11, r12, r13, r21, r22, r23, r31, r32, r33);
    const double H = onPositive(zcg);
    const double gf = m * g - k * zcg * H;
    const double Ia = Ix - Iy + Iz;
    const double D = 2.0 * Ixz * Ixz - 2.0 * Ix * Iz + Ixz * Ia * dt * Qb;

    d[0] = -Ub - dt / 2.0 * ((Fx + gf * r31) / m + Rb * Vb - Qb * Wb);
    d[1] = -Vb - dt / 2.0 * ((Fy + gf * r32) / m - Rb * Ub + Pb * Wb);
    d[2] = -Wb - dt / 2.0 * ((Fz + gf * r33) / m + Qb * Ub - Pb * Vb);
    d[3] = (dt * (Iz * Lb + Ixz * Nb) + 2.0 * (Ix * Iz - Ixz * Ixz) * Pb + Ixz * Ia * dt * Pb * Qb
            + (Iy * Iz - Iz * Iz - Ixz * Ixz) * dt * Qb * Rb)
           / D;
    d[4] = -Qb - dt / (2.0 * Iy) * (Mb + (Iz - Ix) * Pb * Rb + Ixz * (Rb * Rb - Pb * Pb));
    d[5] = (dt * (Ixz * Lb + Ix * Nb) + (Ix * Ix + Ixz * Ixz - Ix * Iy) * dt * Pb * Qb
            + 2.0 * (Ix * Iz - Ixz * Ixz) * Rb - Ixz * Ia * dt * Qb * Rb)
           / (2.0 * Ixz * Ixz - 2.0 * Ix * Iz - Ixz * Ia * dt * Qb);
    d[6] = -q0 + dt / 4.0 * (Pb * q1 + Qb * q2 + Rb * q3);
    d[7] = -q1 - dt / 4.0 * (Pb * q0 - Qb * q3 + Rb * q2);
    d[8] = -q2 - dt / 4.0 * (Pb * q3 + Qb * q0 - Rb * q1);
    d[9] = -q3 + dt / 4.0 * (Pb * q2 - Qb * q1 - Rb * q0);
    d[10] = -xcg - dt / 2.0 * (r11 * Ub + r12 * Vb + r13 * Wb);
    d[11] = -ycg - dt / 2.0 * (r21 * Ub + r22 * Vb + r23 * Wb);
    d[12] = -zcg - dt / 2.0 * (r31 * Ub + r32 * Vb + r33 * Wb);
}

void Aero6DofCore::velocitiesEarth(double& vx, double& vy, double& vz) const
{
    double r11, r12, r13, r21, r22, r23, r31, r32, r33;
    dcm(r11, r12, r13, r21, r22, r23, r31, r32, r33);
    vx = r11 * Ub + r12 * Vb + r13 * Wb;
    vy = r21 * Ub + r22 * Vb + r23 * Wb;
    vz = r31 * Ub + r32 * Vb + r33 * Wb;
}

void Aero6DofCore::eulerAngles(double& Phi, double& Theta, double& Psi) const
{
    Phi = Atan2L(2.0 * (q0 * q1 + q2 * q3), q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3);
    Theta = ArcSinL(2.0 * (q0 * q2 - q1 * q3));
    Psi = Atan2L(2.0 * (q1 * q2 + q0 * q3), q0 * q0 + q1 * q1 - q2 * q2 - q3 * q3);
}

// ------------------------------------------------------------------ AeroVehicleTVC

void AeroVehicleTVC::configure()
{
    mpPtvcly = addPowerPort("Ptvcly", NodeType::MechanicRotational);
    mpPtvclz = addPowerPort("Ptvclz", NodeType::MechanicRotational);
    mpPtvcry = addPowerPort("Ptvcry", NodeType::MechanicRotational);
    mpPtvcrz = addPowerPort("Ptvcrz", NodeType::MechanicRotational);

    addInputVariable("thrustl", "Thrust left engine", "N", 0.0, &mpThrustl);
    addInputVariable("thrustr", "Thrust right engine", "N", 0.0, &mpThrustr);
    addInputVariable("g0", "Gravitational acceleration", "m/s2", 9.81, &mpG0);
    addInputVariable("Mfuel", "Fuel mass", "kg", 0.0, &mpMfuel);
    addInputVariable("Mcargo", "Cargo mass", "kg", 0.0, &mpMcargo);
    addInputVariable("rho", "Air density", "kg/m3", 1.25, &mpRho);
    addInputVariable("vturbx", "Turbulence velocity x", "m/s", 0.0, &mpVturbx);
    addInputVariable("vturby", "Turbulence velocity y", "m/s", 0.0, &mpVturby);
    addInputVariable("vturbz", "Turbulence velocity z", "m/s", 0.0, &mpVturbz);
    addInputVariable("wturbx", "Turbulence rotation x", "rad/s", 0.0, &mpWturbx);
    addInputVariable("wturby", "Turbulence rotation y", "rad/s", 0.0, &mpWturby);
    addInputVariable("wturbz", "Turbulence rotation z", "rad/s", 0.0, &mpWturbz);

    addInputVariable("Cd0b", "Body drag coefficient", "", 0.004, &mpCd0b);
    addInputVariable("Ctvc", "TVC hinge coefficient", "m/rad", 0.1, &mpCtvc);
    addInputVariable("CLalphabh", "Body lift slope (horizontal)", "", 2.0, &mpCLalphabh);
    addInputVariable("CLalphabv", "Body lift slope (vertical)", "", 2.0, &mpCLalphabv);
    addInputVariable("hthrust0", "Thrust height", "", 0.0, &mpHthrust0);
    addInputVariable("Ix", "Moment of inertia x", "kg m2", 1000.0, &mpIx);
    addInputVariable("Ixz", "Product of inertia xz", "kg m2", 500.0, &mpIxz);
    addInputVariable("Iy", "Moment of inertia y", "kg m2", 3000.0, &mpIy);
    addInputVariable("Iz", "Moment of inertia z", "kg m2", 3000.0, &mpIz);
    addInputVariable("Me", "Empty mass", "kg", 5000.0, &mpMe);
    addInputVariable("Sbh", "Body area (horizontal)", "m2", 5.0, &mpSbh);
    addInputVariable("Sbv", "Body area (vertical)", "m2", 5.0, &mpSbv);
    addInputVariable("xbach", "Body aerodynamic centre (horizontal)", "m", 8.5, &mpXbach);
    addInputVariable("xbacv", "Body aerodynamic centre (vertical)", "m", 8.5, &mpXbacv);
    addInputVariable("xbcge", "Empty centre of gravity", "m", 6.0, &mpXbcge);
    addInputVariable("xcargo", "Cargo position", "m", 6.0, &mpXcargo);
    addInputVariable("xfuel", "Fuel position", "m", 6.0, &mpXfuel);
    addInputVariable("xeng", "Engine position x", "m", 0.0, &mpXeng);
    addInputVariable("yeng", "Engine position y", "m", 0.0, &mpYeng);
    addInputVariable("kground", "Ground stiffness", "N/m", 10000.0, &mpKground);
    addInputVariable("cground", "Ground damping", "Ns/m", 1000.0, &mpCground);

    addOutputVariable("xcg", "Position x (earth)", "m", 0.0, &mpXcg);
    addOutputVariable("ycg", "Position y (earth)", "m", 0.0, &mpYcg);
    addOutputVariable("zcg", "Position z (earth, down)", "m", 0.0, &mpZcg);
    addOutputVariable("vx", "Velocity x (earth)", "m/s", 0.0, &mpVx);
    addOutputVariable("vy", "Velocity y (earth)", "m/s", 0.0, &mpVy);
    addOutputVariable("vz", "Velocity z (earth)", "m/s", 0.0, &mpVz);
    addOutputVariable("Psi", "Heading", "rad", 0.0, &mpPsi);
    addOutputVariable("Thetao", "Pitch", "rad", 1.4, &mpThetao);
    addOutputVariable("Phi", "Roll", "rad", 0.0, &mpPhi);
    addOutputVariable("Ub", "Body velocity x", "m/s", 100.0, &mpUb);
    addOutputVariable("Vb", "Body velocity y", "m/s", 0.0, &mpVb);
    addOutputVariable("Wb", "Body velocity z", "m/s", 0.0, &mpWb);
    addOutputVariable("Pb", "Body roll rate", "rad/s", 0.0, &mpPb);
    addOutputVariable("Qb", "Body pitch rate", "rad/s", 0.0, &mpQb);
    addOutputVariable("Rb", "Body yaw rate", "rad/s", 0.0, &mpRb);
    addOutputVariable("q0", "Quaternion 0", "", 0.0, &mpQ0);
    addOutputVariable("q1", "Quaternion 1", "", 0.0, &mpQ1);
    addOutputVariable("q2", "Quaternion 2", "", 0.0, &mpQ2);
    addOutputVariable("q3", "Quaternion 3", "", 0.0, &mpQ3);
    addOutputVariable("AlphaAttack", "Angle of attack", "rad", 0.0, &mpAlphaAttack);
    addOutputVariable("BetaSlip", "Side slip angle", "rad", 0.0, &mpBetaSlip);
    addOutputVariable("altitude", "Altitude", "m", 0.0, &mpAltitude);
    addOutputVariable("gfx", "Acceleration x (body)", "m/s2", 0.0, &mpGfx);
    addOutputVariable("gfy", "Acceleration y (body)", "m/s2", 0.0, &mpGfy);
    addOutputVariable("gfz", "Acceleration z (body)", "m/s2", 0.0, &mpGfz);
    addOutputVariable("CL1", "Lift coefficient", "", 0.0, &mpCL1);
    addOutputVariable("Cd1", "Drag coefficient", "", 0.0, &mpCd1);
    addOutputVariable("Fax", "Aerodynamic force x", "N", 0.0, &mpFax);
    addOutputVariable("Faz", "Aerodynamic force z", "N", 0.0, &mpFaz);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"wturbx", "Cd0b", "Ctvc", "CLalphabh", "CLalphabv", "hthrust0", "Ix", "Ixz", "Iy",
                      "Iz", "Me", "Sbh", "Sbv", "xbach", "xbacv", "xbcge", "xcargo", "xfuel", "xeng",
                      "yeng", "kground", "cground"}, false);
}

void AeroVehicleTVC::explicitQuantities()
{
    Aero6DofCore& s = mCore;
    const double thrustl = *mpThrustl, thrustr = *mpThrustr, rho = *mpRho;
    const double vturbx = *mpVturbx, vturby = *mpVturby, vturbz = *mpVturbz;
    const double wturby = *mpWturby, wturbz = *mpWturbz;
    const double aly = *mpAly, alz = *mpAlz, ary = *mpAry, arz = *mpArz;
    const double Mfuel = *mpMfuel, Mcargo = *mpMcargo;

    const double v = std::sqrt(0.0001 + (s.Ub + vturbx) * (s.Ub + vturbx) + (s.Vb + vturby) * (s.Vb + vturby)
                               + (s.Wb + vturbz) * (s.Wb + vturbz));
    mAlpha = Atan2L(s.Wb + vturbz, 0.0001 + s.Ub + vturbx);
    const double qpress = rho * (v * v) / 2.0;
    mBeta = Atan2L(s.Vb + vturby,
                   std::sqrt(0.0001 + (s.Ub + vturbx) * (s.Ub + vturbx) + (s.Wb + vturbz) * (s.Wb + vturbz)));
    const double mass = Mcargo + mMe + Mfuel;
    const double xbcg = (mMe * mXbcge + Mcargo * mXcargo + Mfuel * mXfuel) / mass;
    const double Mdvtheta = mCLalphabh * qpress * mSbh * ((mXbach - xbcg) * (mXbach - xbcg)) / (0.1 + v);
    const double Mdvpsi = mCLalphabv * qpress * mSbv * ((mXbacv - xbcg) * (mXbacv - xbcg)) / (0.1 + v);

    s.Fx = -mCd0b * qpress * mSbh * std::cos(mAlpha) * std::cos(mBeta) + thrustl * std::cos(aly) * std::cos(alz)
           + thrustr * std::cos(ary) * std::cos(arz);
    s.Fy = mCLalphabv * qpress * mSbv * std::sin(mBeta) - thrustl * std::cos(alz) * std::sin(aly)
           - thrustr * std::cos(arz) * std::sin(ary);
    s.Fz = -mCLalphabh * qpress * mSbh * std::sin(mAlpha) - thrustl * std::cos(aly) * std::sin(alz)
           - thrustr * std::cos(ary) * std::sin(arz);
    s.Lb = mYeng * (thrustl * std::cos(aly) * std::sin(alz) - thrustr * std::cos(ary) * std::sin(arz));
    s.Mb = -Mdvtheta * (s.Qb + wturby) - mCLalphabh * qpress * mSbh * (mXbach - xbcg) * std::sin(mAlpha)
           + (xbcg - mXeng) * (thrustl * std::cos(aly) * std::sin(alz) + thrustr * std::cos(ary) * std::sin(arz));
    s.Nb = -Mdvpsi * (s.Rb + wturbz) + mCLalphabv * qpress * mSbv * (mXbacv - xbcg) * std::sin(mBeta)
           + (xbcg - mXeng) * (thrustl * std::cos(alz) * std::sin(aly) + thrustr * std::cos(arz) * std::sin(ary));
    s.m = mass;
    s.g = *mpG0;
}

void AeroVehicleTVC::evalOutputs()
{
    mCore.velocitiesEarth(mVx, mVy, mVz);
    mCore.eulerAngles(mPhi, mThetao, mPsi);
}

void AeroVehicleTVC::writeOutputs()
{
    const Aero6DofCore& s = mCore;
    // The port waves are the start values read at initialisation, never updated.
    *mpCly = mCly;
    *mpZcly = mZcly;
    *mpClz = mClz;
    *mpZclz = mZclz;
    *mpCry = mCry;
    *mpZcry = mZcry;
    *mpCrz = mCrz;
    *mpZcrz = mZcrz;

    *mpXcg = s.xcg;
    *mpYcg = s.ycg;
    *mpZcg = s.zcg;
    *mpVx = mVx;
    *mpVy = mVy;
    *mpVz = mVz;
    *mpPsi = mPsi;
    *mpThetao = mThetao;
    *mpPhi = mPhi;
    *mpUb = s.Ub;
    *mpVb = s.Vb;
    *mpWb = s.Wb;
    *mpPb = s.Pb;
    *mpQb = s.Qb;
    *mpRb = s.Rb;
    *mpQ0 = s.q0;
    *mpQ1 = s.q1;
    *mpQ2 = s.q2;
    *mpQ3 = s.q3;
    *mpAlphaAttack = mAlpha;
    *mpBetaSlip = mBeta;
    *mpAltitude = -s.zcg;
    *mpGfx = s.Fx / s.m;
    *mpGfy = s.Fy / s.m;
    *mpGfz = s.Fz / s.m;
    // CL1 and Cd1 are never computed by this type: they keep their start values.
    *mpFax = -1.0;
    *mpFaz = -1.0;
}

void AeroVehicleTVC::initialize()
{
    mpAly = getSafeNodeDataPtr(mpPtvcly, NodeMechanicRotational::Angle);
    mpAlz = getSafeNodeDataPtr(mpPtvclz, NodeMechanicRotational::Angle);
    mpAry = getSafeNodeDataPtr(mpPtvcry, NodeMechanicRotational::Angle);
    mpArz = getSafeNodeDataPtr(mpPtvcrz, NodeMechanicRotational::Angle);
    mpCly = getSafeNodeDataPtr(mpPtvcly, NodeMechanicRotational::WaveVariable);
    mpZcly = getSafeNodeDataPtr(mpPtvcly, NodeMechanicRotational::CharImpedance);
    mpClz = getSafeNodeDataPtr(mpPtvclz, NodeMechanicRotational::WaveVariable);
    mpZclz = getSafeNodeDataPtr(mpPtvclz, NodeMechanicRotational::CharImpedance);
    mpCry = getSafeNodeDataPtr(mpPtvcry, NodeMechanicRotational::WaveVariable);
    mpZcry = getSafeNodeDataPtr(mpPtvcry, NodeMechanicRotational::CharImpedance);
    mpCrz = getSafeNodeDataPtr(mpPtvcrz, NodeMechanicRotational::WaveVariable);
    mpZcrz = getSafeNodeDataPtr(mpPtvcrz, NodeMechanicRotational::CharImpedance);
    mCly = *mpCly;
    mZcly = *mpZcly;
    mClz = *mpClz;
    mZclz = *mpZclz;
    mCry = *mpCry;
    mZcry = *mpZcry;
    mCrz = *mpCrz;
    mZcrz = *mpZcrz;

    // Hopsan quirk: these inputs are sampled only here.
    mCd0b = *mpCd0b;
    mCLalphabh = *mpCLalphabh;
    mCLalphabv = *mpCLalphabv;
    mMe = *mpMe;
    mSbh = *mpSbh;
    mSbv = *mpSbv;
    mXbach = *mpXbach;
    mXbacv = *mpXbacv;
    mXbcge = *mpXbcge;
    mXcargo = *mpXcargo;
    mXfuel = *mpXfuel;
    mXeng = *mpXeng;
    mYeng = *mpYeng;

    Aero6DofCore& s = mCore;
    s.Ix = *mpIx;
    s.Iy = *mpIy;
    s.Iz = *mpIz;
    s.Ixz = *mpIxz;
    s.k = *mpKground;
    s.Ub = *mpUb;
    s.Vb = *mpVb;
    s.Wb = *mpWb;
    s.Pb = *mpPb;
    s.Qb = *mpQb;
    s.Rb = *mpRb;
    s.xcg = *mpXcg;
    s.ycg = *mpYcg;
    s.zcg = *mpZcg;
    mPhi = *mpPhi;
    mThetao = *mpThetao;
    mPsi = *mpPsi;
    mVx = *mpVx;
    mVy = *mpVy;
    mVz = *mpVz;
    // The quaternion start values are ignored: it is built from the Euler start values.
    s.setQuaternionFromEuler(mPhi, mThetao, mPsi);
    explicitQuantities();
    s.computeDelayedParts(mTimestep);
    // No initial step for this type.
}

void AeroVehicleTVC::simulateOneTimestep()
{
    explicitQuantities();
    for (int iter = 1; iter <= 2; ++iter) {
        if (!mCore.iterate(iter, mTimestep)) { stopSimulation("AeroVehicleTVC: singular Jacobian"); }
        evalOutputs();
    }
    mCore.computeDelayedParts(mTimestep);
    writeOutputs();
}

TLMHUB_REGISTER_COMPONENT(AeroVehicleTVC, "Aero")

} // namespace tlmhub
