#include "core/components/electric/ElectricIcontroller.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void ElectricIcontroller::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    mpPel2 = addPowerPort("Pel2", NodeType::Electric);
    addInputVariable("iref", "Reference current", "A/V", 0.0, &mpIref);
    addInputVariable("resist", "Resistance", "ohm", 0.01, &mpResist);
    addInputVariable("wf", "Controller break frequency", "rad/s", 10.0, &mpWf);
    addInputVariable("umin", "Min voltage", "V", 1.0, &mpUmin);
    addInputVariable("imax", "Max current", "A", 10000.0, &mpImax);
    addInputVariable("imin", "Min current", "A", 0.01, &mpImin);
    addInputVariable("umax", "Max voltage", "V", 1000.0, &mpUmax);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"resist", "wf", "umin", "imax", "imin", "umax"}, false);
}

// Delayed part of the first-order lag (bilinear discretisation).
double ElectricIcontroller::delayedPart() const
{
    const double dt = mTimestep, wf = mWf, iref = mIref;
    const double D = limit(mU1 - mU2, mUmin, mUmax);
    return (iref * dt * wf * (mU1 - mU2) - 2.0 * mI1 * D + mI1 * dt * wf * D) / ((2.0 + dt * wf) * D);
}

void ElectricIcontroller::initialize()
{
    mpPel1_u = getSafeNodeDataPtr(mpPel1, NodeElectric::Voltage);
    mpPel1_i = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);
    mpPel2_u = getSafeNodeDataPtr(mpPel2, NodeElectric::Voltage);
    mpPel2_i = getSafeNodeDataPtr(mpPel2, NodeElectric::Current);
    mpPel2_c = getSafeNodeDataPtr(mpPel2, NodeElectric::WaveVariable);
    mpPel2_Zc = getSafeNodeDataPtr(mpPel2, NodeElectric::CharImpedance);

    mU1 = *mpPel1_u;
    mI1 = *mpPel1_i;
    mU2 = *mpPel2_u;
    mI2 = *mpPel2_i;
    mIref = *mpIref;
    // Hopsan quirk: everything except iref is sampled only here.
    mResist = *mpResist;
    mWf = *mpWf;
    mUmin = *mpUmin;
    mUmax = *mpUmax;
    mDelayed1 = delayedPart();
}

void ElectricIcontroller::simulateOneTimestep()
{
    const double c1 = *mpPel1_c, Zc1 = *mpPel1_Zc;
    const double c2 = *mpPel2_c, Zc2 = *mpPel2_Zc;
    mIref = *mpIref;
    const double dt = mTimestep, iref = mIref, resist = mResist, wf = mWf, umin = mUmin, umax = mUmax;
    const double A = dt * wf / (2.0 + dt * wf);

    mX[0] = mI1;
    mX[1] = mI2;
    mX[2] = mU1;
    mX[3] = mU2;
    for (int iter = 1; iter <= 2; ++iter) {
        const double i1 = mI1, i2 = mI2, u1 = mU1, u2 = mU2;
        const double D = limit(u1 - u2, umin, umax);
        const double lu1 = limit(u1, umin, umax);
        const double lu2 = limit(u2, umin, umax);

        mF[0] = i1 + iref * A * (u1 - u2) / D + mDelayed1;
        mF[1] = i2 + i1 * (i1 * resist + lu1) / lu2;
        mF[2] = u1 - c1 - Zc1 * i1;
        mF[3] = u2 - c2 - Zc2 * i2;

        const double j02 = A * iref / D - A * iref * (u1 - u2) * dxLimit(u1 - u2, umin, umax) / (D * D);
        mJ[0][0] = 1.0;
        mJ[0][1] = 0.0;
        mJ[0][2] = j02;
        mJ[0][3] = -j02;
        mJ[1][0] = (2.0 * i1 * resist + lu1) / lu2;
        mJ[1][1] = 1.0;
        mJ[1][2] = i1 * dxLimit(u1, umin, umax) / lu2;
        mJ[1][3] = -i1 * dxLimit(u2, umin, umax) * (i1 * resist + lu1) / (lu2 * lu2);
        mJ[2][0] = -Zc1;
        mJ[2][1] = 0.0;
        mJ[2][2] = 1.0;
        mJ[2][3] = 0.0;
        mJ[3][0] = 0.0;
        mJ[3][1] = -Zc2;
        mJ[3][2] = 0.0;
        mJ[3][3] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) { stopSimulation("ElectricIcontroller: singular Jacobian"); }
        mI1 = mX[0];
        mI2 = mX[1];
        mU1 = mX[2];
        mU2 = mX[3];
    }

    mDelayed1 = delayedPart();

    *mpPel1_u = mU1;
    *mpPel1_i = mI1;
    *mpPel2_u = mU2;
    *mpPel2_i = mI2;
}

TLMHUB_REGISTER_COMPONENT(ElectricIcontroller, "Electric")

} // namespace tlmhub
