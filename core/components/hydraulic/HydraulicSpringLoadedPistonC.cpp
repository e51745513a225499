#include "core/components/hydraulic/HydraulicSpringLoadedPistonC.h"

#include "core/ComponentFactory.h"

#include <algorithm>

namespace tlmhub {

void HydraulicSpringLoadedPistonC::configure()
{
    addConstant("use_sl", "Use end stops (stroke limitation)", true, mUseEndStops);

    mpP1 = addPowerMultiPort("P1", NodeType::Hydraulic);
    mpP2 = addPowerMultiPort("P2", NodeType::Hydraulic);
    mpP3 = addPowerPort("P3", NodeType::Mechanic);

    addInputVariable("A_1", "Piston area 1", "m^2", 0.001, &mpA1);
    addInputVariable("A_2", "Piston area 2", "m^2", 0.001, &mpA2);
    addInputVariable("s_l", "Stroke", "m", 1.0, &mpSl);
    addInputVariable("F_s", "Spring force", "N", 1000.0, &mpFs);
    addInputVariable("V_1", "Dead volume in chamber 1", "m^3", 0.0003, &mpV01);
    addInputVariable("V_2", "Dead volume in chamber 2", "m^3", 0.0003, &mpV02);
    addInputVariable("B_p", "Viscous friction", "N s/m", 1000.0, &mpBp);
    addInputVariable("Beta_e", "Bulk modulus", "Pa", 1e9, &mpBetae);
    addInputVariable("c_leak", "Leakage coefficient", "m^3/(s Pa)", 1e-11, &mpCLeak);
}

void HydraulicSpringLoadedPistonC::initialize()
{
    mNumPorts1 = getNumPorts(mpP1);
    mNumPorts2 = getNumPorts(mpP2);
    mP1.resize(mNumPorts1);
    mP2.resize(mNumPorts2);

    const double A1 = *mpA1;
    const double A2 = *mpA2;
    const double sl = *mpSl;
    const double V01 = *mpV01;
    const double V02 = *mpV02;
    const double bp = *mpBp;
    const double betae = *mpBetae;
    const double cLeak = *mpCLeak;

    const double p1s = getDefaultStartValue(mpP1, NodeHydraulic::Pressure);
    const double q1s = getDefaultStartValue(mpP1, NodeHydraulic::Flow);
    for (std::size_t i = 0; i < mNumPorts1; ++i) {
        mP1[i].p = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::Pressure);
        mP1[i].q = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::Flow);
        mP1[i].c = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::WaveVariable);
        mP1[i].Zc = getSafeMultiPortNodeDataPtr(mpP1, i, NodeHydraulic::CharImpedance);
        *mP1[i].p = p1s;
        *mP1[i].q = q1s / double(mNumPorts1);
        *mP1[i].c = p1s;
    }
    const double p2s = getDefaultStartValue(mpP2, NodeHydraulic::Pressure);
    const double q2s = getDefaultStartValue(mpP2, NodeHydraulic::Flow);
    for (std::size_t i = 0; i < mNumPorts2; ++i) {
        mP2[i].p = getSafeMultiPortNodeDataPtr(mpP2, i, NodeHydraulic::Pressure);
        mP2[i].q = getSafeMultiPortNodeDataPtr(mpP2, i, NodeHydraulic::Flow);
        mP2[i].c = getSafeMultiPortNodeDataPtr(mpP2, i, NodeHydraulic::WaveVariable);
        mP2[i].Zc = getSafeMultiPortNodeDataPtr(mpP2, i, NodeHydraulic::CharImpedance);
        *mP2[i].p = p2s;
        *mP2[i].q = q2s / double(mNumPorts2);
        *mP2[i].c = p2s;
    }
    mpP3_x = getSafeNodeDataPtr(mpP3, NodeMechanic::Position);
    mpP3_v = getSafeNodeDataPtr(mpP3, NodeMechanic::Velocity);
    mpP3_c = getSafeNodeDataPtr(mpP3, NodeMechanic::WaveVariable);
    mpP3_Zx = getSafeNodeDataPtr(mpP3, NodeMechanic::CharImpedance);
    mpP3_me = getSafeNodeDataPtr(mpP3, NodeMechanic::EquivalentMass);

    const double p1 = *mP1[0].p;
    const double p2 = *mP2[0].p;
    const double x3 = *mpP3_x;
    const double v3 = *mpP3_v;

    double V1 = V01 + A1 * (-x3);
    double V2 = V02 + A2 * (sl + x3);
    const double V1min = betae * mTimestep * mTimestep * A1 * A1 / (mWfak * 1.0);
    const double V2min = betae * mTimestep * mTimestep * A2 * A2 / (mWfak * 1.0);
    if (V1 < V1min) V1 = V1min;
    if (V2 < V2min) V2 = V2min;

    const double Zc1 = (double(mNumPorts1) + 2.0) / 2.0 * betae / V1 * mTimestep / (1.0 - mAlpha);
    const double Zc2 = (double(mNumPorts2) + 2.0) / 2.0 * betae / V2 * mTimestep / (1.0 - mAlpha);
    const double Zx3 = A1 * A1 * Zc1 + A2 * A2 * Zc2 + bp;

    const double qi1 = v3 * A1;
    const double qi2 = -v3 * A2;
    ci1 = p1 + Zc1 * qi1;
    ci2 = p2 + Zc2 * qi2;
    const double qLeak = cLeak * (p1 - p2);
    cl1 = p1 + Zc1 * (-qLeak);
    cl2 = p2 + Zc2 * qLeak;

    // The spring force is not applied at initialisation.
    const double c3 = A1 * ci1 - A2 * ci2;

    for (std::size_t i = 0; i < mNumPorts1; ++i) {
        *mP1[i].c = p1 + Zc1 * (*mP1[i].q);
        *mP1[i].Zc = Zc1;
    }
    for (std::size_t i = 0; i < mNumPorts2; ++i) {
        *mP2[i].c = p2 + Zc2 * (*mP2[i].q);
        *mP2[i].Zc = Zc2;
    }
    *mpP3_c = c3;
    *mpP3_Zx = Zx3;
}

void HydraulicSpringLoadedPistonC::simulateOneTimestep()
{
    double Zc1 = *mP1[0].Zc;
    double Zc2 = *mP2[0].Zc;
    const double x3 = *mpP3_x;
    const double v3 = *mpP3_v;
    double me = *mpP3_me;

    const double A1 = *mpA1;
    const double A2 = *mpA2;
    const double sl = *mpSl;
    const double Fs = *mpFs;
    const double V01 = *mpV01;
    const double V02 = *mpV02;
    const double bp = *mpBp;
    const double betae = *mpBetae;
    const double cLeak = *mpCLeak;

    const double qLeak = cLeak * (cl1 - cl2) / (1.0 + cLeak * (Zc1 + Zc2));
    const double qi1 = v3 * A1;
    const double qi2 = -v3 * A2;

    double V1 = V01 + A1 * (-x3);
    double V2 = V02 + A2 * (sl + x3);
    if (me <= 0.0) {
        if (mTime > mTimestep * 1.5) {
            stopSimulation("The equivalent mass 'me' has to be greater than 0.");
        } else {
            addWarningMessage("Equivalent mass 'me' not initialized to a value greater than 0.");
            me = 1.0;
        }
    }
    const double V1min = betae * mTimestep * mTimestep * A1 * A1 / (mWfak * me);
    const double V2min = betae * mTimestep * mTimestep * A2 * A2 / (mWfak * me);
    if (V1 < V1min) V1 = V1min;
    if (V2 < V2min) V2 = V2min;

    // Chamber 1 (wave variables are kept non-negative).
    Zc1 = (double(mNumPorts1) + 2.0) / 2.0 * betae / V1 * mTimestep / (1.0 - mAlpha);
    double c1mean = (ci1 + 2.0 * Zc1 * qi1) + (cl1 + 2.0 * Zc1 * (-qLeak));
    for (std::size_t i = 0; i < mNumPorts1; ++i) {
        c1mean += (*mP1[i].c) + 2.0 * Zc1 * (*mP1[i].q);
    }
    c1mean = c1mean / (double(mNumPorts1) + 2.0);
    ci1 = std::max(0.0, mAlpha * ci1 + (1.0 - mAlpha) * (2.0 * c1mean - ci1 - 2.0 * Zc1 * qi1));
    cl1 = std::max(0.0, mAlpha * cl1 + (1.0 - mAlpha) * (2.0 * c1mean - cl1 - 2.0 * Zc1 * (-qLeak)));

    // Chamber 2.
    Zc2 = (double(mNumPorts2) + 2.0) / 2.0 * betae / V2 * mTimestep / (1.0 - mAlpha);
    double c2mean = (ci2 + 2.0 * Zc2 * qi2) + (cl2 + 2.0 * Zc2 * qLeak);
    for (std::size_t i = 0; i < mNumPorts2; ++i) {
        c2mean += (*mP2[i].c) + 2.0 * Zc2 * (*mP2[i].q);
    }
    c2mean = c2mean / (double(mNumPorts2) + 2.0);
    ci2 = std::max(0.0, mAlpha * ci2 + (1.0 - mAlpha) * (2.0 * c2mean - ci2 - 2.0 * Zc2 * qi2));
    cl2 = std::max(0.0, mAlpha * cl2 + (1.0 - mAlpha) * (2.0 * c2mean - cl2 - 2.0 * Zc2 * qLeak));

    double CxLim = 0.0;
    double ZxLim = 0.0;
    if (mUseEndStops) {
        limitStroke(CxLim, ZxLim, x3, v3, me, sl);
    }

    const double c3 = A1 * ci1 - A2 * ci2 + CxLim;
    const double Zx3 = A1 * A1 * Zc1 + A2 * A2 * Zc2 + bp + ZxLim;

    for (std::size_t i = 0; i < mNumPorts1; ++i) {
        const double c = *mP1[i].c;
        *mP1[i].c = std::max(0.0, mAlpha * c + (1.0 - mAlpha) * (2.0 * c1mean - c - 2.0 * Zc1 * (*mP1[i].q)));
        *mP1[i].Zc = Zc1;
    }
    for (std::size_t i = 0; i < mNumPorts2; ++i) {
        const double c = *mP2[i].c;
        *mP2[i].c = std::max(0.0, mAlpha * c + (1.0 - mAlpha) * (2.0 * c2mean - c - 2.0 * Zc2 * (*mP2[i].q)));
        *mP2[i].Zc = Zc2;
    }
    *mpP3_c = c3 - Fs;
    *mpP3_Zx = Zx3;
}

// Stiff spring force pushing the piston back inside [-s_l, 0].
void HydraulicSpringLoadedPistonC::limitStroke(double& CxLim, double& ZxLim, double x3, double v3, double me,
                                               double sl) const
{
    const double alfa = 0.5;
    double newCxLim = 0.0;
    if (-x3 > sl) {
        const double ZxLim0 = mWfak * me / mTimestep;
        ZxLim = ZxLim0 / (1.0 - alfa);
        const double FxLim = ZxLim0 * (x3 + sl) / mTimestep;
        newCxLim = FxLim + ZxLim * v3;
    } else if (-x3 < 0.0) {
        const double ZxLim0 = mWfak * me / mTimestep;
        ZxLim = ZxLim0 / (1.0 - alfa);
        const double FxLim = ZxLim0 * x3 / mTimestep;
        newCxLim = FxLim + ZxLim * v3;
    } else {
        ZxLim = 0.0;
    }
    // Hopsan filters with an uninitialised local that its compiled library treats as 0,
    // so the "filter" keeps no memory of the previous step (reference: end-stop quirk).
    CxLim = (1.0 - alfa) * newCxLim;
}

TLMHUB_REGISTER_COMPONENT(HydraulicSpringLoadedPistonC, "Hydraulic")

} // namespace tlmhub
