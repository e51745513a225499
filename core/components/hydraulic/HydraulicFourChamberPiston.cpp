#include "core/components/hydraulic/HydraulicFourChamberPiston.h"

#include "core/ComponentFactory.h"

#include <algorithm>

namespace tlmhub {

void HydraulicFourChamberPiston::configure()
{
    addConstant("use_sl", "Use end stops (stroke limitation)", true, mUseEndStops);

    mpP[0] = addPowerMultiPort("P1", NodeType::Hydraulic);
    mpP[1] = addPowerMultiPort("P2", NodeType::Hydraulic);
    mpP[2] = addPowerMultiPort("P3", NodeType::Hydraulic);
    mpP[3] = addPowerMultiPort("P4", NodeType::Hydraulic);
    mpP5 = addPowerPort("P5", NodeType::Mechanic);

    addInputVariable("A_1", "Piston area 1", "m^2", 0.001, &mpA[0]);
    addInputVariable("A_2", "Piston area 2", "m^2", 0.001, &mpA[1]);
    addInputVariable("A_3", "Piston area 3", "m^2", 0.001, &mpA[2]);
    addInputVariable("A_4", "Piston area 4", "m^2", 0.001, &mpA[3]);
    addInputVariable("s_l", "Stroke", "m", 1.0, &mpSl);
    addInputVariable("V_1", "Dead volume in chamber 1", "m^3", 0.0003, &mpV0[0]);
    addInputVariable("V_2", "Dead volume in chamber 2", "m^3", 0.0003, &mpV0[1]);
    addInputVariable("V_3", "Dead volume in chamber 3", "m^3", 0.0003, &mpV0[2]);
    addInputVariable("V_4", "Dead volume in chamber 4", "m^3", 0.0003, &mpV0[3]);
    addInputVariable("B_p", "Viscous friction", "N s/m", 1000.0, &mpBp);
    addInputVariable("Beta_e", "Bulk modulus", "Pa", 1e9, &mpBetae);
    addInputVariable("c_leak12", "Leakage coefficient between chambers 1 and 2", "m^3/(s Pa)", 1e-11, &mpCLeak12);
    addInputVariable("c_leak13", "Leakage coefficient between chambers 1 and 3", "m^3/(s Pa)", 0.0, &mpCLeak13);
    addInputVariable("c_leak14", "Leakage coefficient between chambers 1 and 4", "m^3/(s Pa)", 1e-11, &mpCLeak14);
    addInputVariable("c_leak23", "Leakage coefficient between chambers 2 and 3", "m^3/(s Pa)", 0.0, &mpCLeak23);
    addInputVariable("c_leak24", "Leakage coefficient between chambers 2 and 4", "m^3/(s Pa)", 0.0, &mpCLeak24);
    addInputVariable("c_leak34", "Leakage coefficient between chambers 3 and 4", "m^3/(s Pa)", 1e-11, &mpCLeak34);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"A_1", "A_2", "A_3", "A_4", "V_1", "V_2", "V_3", "V_4"}, false);
}

void HydraulicFourChamberPiston::initialize()
{
    mCxLim = 0.0;
    mZxLim = 0.0;

    for (int k = 0; k < 4; ++k) {
        const std::size_t n = getNumPorts(mpP[k]);
        mNumPorts[k] = n;
        mvp_p[k].resize(n);
        mvp_q[k].resize(n);
        mvp_c[k].resize(n);
        mvp_Zc[k].resize(n);
        const double ps = getDefaultStartValue(mpP[k], NodeHydraulic::Pressure);
        const double qs = getDefaultStartValue(mpP[k], NodeHydraulic::Flow);
        for (std::size_t i = 0; i < n; ++i) {
            mvp_p[k][i] = getSafeMultiPortNodeDataPtr(mpP[k], i, NodeHydraulic::Pressure);
            mvp_q[k][i] = getSafeMultiPortNodeDataPtr(mpP[k], i, NodeHydraulic::Flow);
            mvp_c[k][i] = getSafeMultiPortNodeDataPtr(mpP[k], i, NodeHydraulic::WaveVariable);
            mvp_Zc[k][i] = getSafeMultiPortNodeDataPtr(mpP[k], i, NodeHydraulic::CharImpedance);
            *mvp_p[k][i] = ps;
            *mvp_q[k][i] = qs / double(n);
            *mvp_c[k][i] = ps;
        }
    }
    mpP5_x = getSafeNodeDataPtr(mpP5, NodeMechanic::Position);
    mpP5_v = getSafeNodeDataPtr(mpP5, NodeMechanic::Velocity);
    mpP5_c = getSafeNodeDataPtr(mpP5, NodeMechanic::WaveVariable);
    mpP5_Zx = getSafeNodeDataPtr(mpP5, NodeMechanic::CharImpedance);
    mpP5_me = getSafeNodeDataPtr(mpP5, NodeMechanic::EquivalentMass);

    double A[4], V0[4], p[4];
    for (int k = 0; k < 4; ++k) {
        A[k] = *mpA[k];
        V0[k] = *mpV0[k];
        p[k] = *mvp_p[k][0];
    }
    const double sl = *mpSl;
    const double bp = *mpBp;
    const double betae = *mpBetae;
    const double x5 = *mpP5_x;
    const double v5 = *mpP5_v;

    // Chambers 1 and 3 shrink with positive x, chambers 2 and 4 grow.
    double V[4];
    V[0] = V0[0] + A[0] * (-x5);
    V[1] = V0[1] + A[1] * (sl + x5);
    V[2] = V0[2] + A[2] * (-x5);
    V[3] = V0[3] + A[3] * (sl + x5);
    double Zc[4];
    for (int k = 0; k < 4; ++k) {
        const double Vmin = betae * mTimestep * mTimestep * A[k] * A[k] / (mWfak * 1.0);
        if (V[k] < Vmin) V[k] = Vmin;
        Zc[k] = (double(mNumPorts[k]) + 2.0) / 2.0 * betae / V[k] * mTimestep / (1.0 - mAlpha);
    }
    const double Zx5 = A[0] * A[0] * Zc[0] + A[1] * A[1] * Zc[1] + A[2] * A[2] * Zc[2] + A[3] * A[3] * Zc[3] + bp;

    const double qi[4] = {v5 * A[0], -v5 * A[1], v5 * A[2], -v5 * A[3]};
    for (int k = 0; k < 4; ++k) {
        mCi[k] = p[k] + Zc[k] * qi[k];
    }

    const double qLeak12 = (*mpCLeak12) * (p[0] - p[1]);
    const double qLeak13 = (*mpCLeak13) * (p[0] - p[2]);
    const double qLeak14 = (*mpCLeak14) * (p[0] - p[3]);
    const double qLeak23 = (*mpCLeak23) * (p[1] - p[2]);
    const double qLeak24 = (*mpCLeak24) * (p[1] - p[3]);
    const double qLeak34 = (*mpCLeak34) * (p[2] - p[3]);
    mCl[0] = p[0] + Zc[0] * (-qLeak12) + Zc[0] * (-qLeak13) + Zc[0] * (-qLeak14);
    mCl[1] = p[1] + Zc[1] * qLeak12 + Zc[1] * (-qLeak23) + Zc[1] * (-qLeak24);
    mCl[2] = p[2] + Zc[2] * qLeak13 + Zc[2] * qLeak23 + Zc[2] * (-qLeak34);
    // Hopsan uses Zc3 for the 1-4 and 3-4 terms of chamber 4 here (kept).
    mCl[3] = p[3] + Zc[2] * qLeak14 + Zc[3] * qLeak24 + Zc[2] * qLeak34;

    const double c5 = A[0] * mCi[0] - A[1] * mCi[1] + A[2] * mCi[2] - A[3] * mCi[3];

    for (int k = 0; k < 4; ++k) {
        for (std::size_t i = 0; i < mNumPorts[k]; ++i) {
            *mvp_c[k][i] = p[k] + Zc[k] * (*mvp_q[k][i]);
            *mvp_Zc[k][i] = Zc[k];
        }
    }
    *mpP5_c = c5;
    *mpP5_Zx = Zx5;
}

void HydraulicFourChamberPiston::simulateOneTimestep()
{
    double Zc[4];
    double A[4], V0[4];
    for (int k = 0; k < 4; ++k) {
        Zc[k] = *mvp_Zc[k][0];   // previous step's impedance
        A[k] = *mpA[k];
        V0[k] = *mpV0[k];
    }
    const double x5 = *mpP5_x;
    const double v5 = *mpP5_v;
    double me5 = *mpP5_me;
    const double sl = *mpSl;
    const double bp = *mpBp;
    const double betae = *mpBetae;
    const double cLeak12 = *mpCLeak12, cLeak13 = *mpCLeak13, cLeak14 = *mpCLeak14;
    const double cLeak23 = *mpCLeak23, cLeak24 = *mpCLeak24, cLeak34 = *mpCLeak34;

    const double qLeak12 = cLeak12 * (mCl[0] - mCl[1]) / (1.0 + cLeak12 * (Zc[0] + Zc[1]));
    const double qLeak13 = cLeak13 * (mCl[0] - mCl[2]) / (1.0 + cLeak13 * (Zc[0] + Zc[2]));
    const double qLeak14 = cLeak14 * (mCl[0] - mCl[3]) / (1.0 + cLeak14 * (Zc[0] + Zc[3]));
    const double qLeak23 = cLeak23 * (mCl[1] - mCl[2]) / (1.0 + cLeak23 * (Zc[1] + Zc[2]));
    const double qLeak24 = cLeak24 * (mCl[1] - mCl[3]) / (1.0 + cLeak24 * (Zc[1] + Zc[3]));
    const double qLeak34 = cLeak34 * (mCl[2] - mCl[3]) / (1.0 + cLeak34 * (Zc[2] + Zc[3]));

    const double qi[4] = {v5 * A[0], -v5 * A[1], v5 * A[2], -v5 * A[3]};

    double V[4];
    V[0] = V0[0] + A[0] * (-x5);
    V[1] = V0[1] + A[1] * (sl + x5);
    V[2] = V0[2] + A[2] * (-x5);
    V[3] = V0[3] + A[3] * (sl + x5);
    if (me5 <= 0.0) {
        if (mTime > mTimestep * 1.5) {
            stopSimulation("The equivalent mass 'me' has to be greater than 0.");
        } else {
            addWarningMessage("Equivalent mass 'me' not initialized to a value greater than 0.");
            me5 = 1.0;
        }
    }
    for (int k = 0; k < 4; ++k) {
        const double Vmin = betae * mTimestep * mTimestep * A[k] * A[k] / (mWfak * me5);
        if (V[k] < Vmin) V[k] = Vmin;
    }

    // Signed leakage flows into each chamber's leakage port, in summation order.
    const double leak[4][3] = {
        {-qLeak12, -qLeak13, -qLeak14},
        {qLeak12, -qLeak23, -qLeak24},
        {qLeak13, qLeak23, -qLeak34},
        {qLeak14, qLeak24, qLeak34},
    };

    double pmean[4];
    for (int k = 0; k < 4; ++k) {
        const double z = (double(mNumPorts[k]) + 2.0) / 2.0 * betae / V[k] * mTimestep / (1.0 - mAlpha);
        Zc[k] = z;
        double m = (mCi[k] + 2.0 * z * qi[k])
                   + (mCl[k] + 2.0 * z * leak[k][0] + 2.0 * z * leak[k][1] + 2.0 * z * leak[k][2]);
        for (std::size_t i = 0; i < mNumPorts[k]; ++i) {
            m += (*mvp_c[k][i]) + 2.0 * z * (*mvp_q[k][i]);
        }
        m = m / (double(mNumPorts[k]) + 2.0);
        pmean[k] = m;
        mCi[k] = std::max(0.0, mAlpha * mCi[k] + (1.0 - mAlpha) * (2.0 * m - mCi[k] - 2.0 * z * qi[k]));
        mCl[k] = std::max(0.0, mAlpha * mCl[k]
                                   + (1.0 - mAlpha) * (2.0 * m - mCl[k] - 2.0 * z * leak[k][0]
                                                       - 2.0 * z * leak[k][1] - 2.0 * z * leak[k][2]));
    }

    if (mUseEndStops) {
        limitStroke(x5, v5, me5, sl);
    } else {
        mCxLim = 0.0;
        mZxLim = 0.0;
    }

    const double c5 = A[0] * mCi[0] - A[1] * mCi[1] + A[2] * mCi[2] - A[3] * mCi[3] + mCxLim;
    // Hopsan uses Zc3 for chamber 4 in the rod impedance (kept on purpose).
    const double Zx5 = A[0] * A[0] * Zc[0] + A[1] * A[1] * Zc[1] + A[2] * A[2] * Zc[2] + A[3] * A[3] * Zc[2]
                       + bp + mZxLim;

    for (int k = 0; k < 4; ++k) {
        for (std::size_t i = 0; i < mNumPorts[k]; ++i) {
            const double c = *mvp_c[k][i];
            *mvp_c[k][i] = std::max(0.0, mAlpha * c + (1.0 - mAlpha) * (2.0 * pmean[k] - c - 2.0 * Zc[k] * (*mvp_q[k][i])));
            *mvp_Zc[k][i] = Zc[k];
        }
    }
    *mpP5_c = c5;
    *mpP5_Zx = Zx5;
}

// Stiff, filtered spring force pushing the rod back inside [-s_l, 0];
// CxLim/ZxLim are members so the filter uses the previous step's value.
void HydraulicFourChamberPiston::limitStroke(double x5, double v5, double me, double sl)
{
    const double alfa = 0.5;
    double newCxLim = 0.0;
    if (-x5 > sl) {
        const double ZxLim0 = mWfak * me / mTimestep;
        mZxLim = ZxLim0 / (1.0 - alfa);
        const double FxLim = ZxLim0 * (x5 + sl) / mTimestep;
        newCxLim = FxLim + mZxLim * v5;
    } else if (-x5 < 0.0) {
        const double ZxLim0 = mWfak * me / mTimestep;
        mZxLim = ZxLim0 / (1.0 - alfa);
        const double FxLim = ZxLim0 * x5 / mTimestep;
        newCxLim = FxLim + mZxLim * v5;
    } else {
        mZxLim = 0.0;
        mCxLim = 0.0;
        newCxLim = 0.0;
    }
    mCxLim = alfa * mCxLim + (1.0 - alfa) * newCxLim;
}

TLMHUB_REGISTER_COMPONENT(HydraulicFourChamberPiston, "Hydraulic")

} // namespace tlmhub
