#include "core/components/electric/ElectricInductance.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void ElectricInductance::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    mpPel2 = addPowerPort("Pel2", NodeType::Electric);
    addInputVariable("Induct", "Inductance", "A/(Vs)", 0.1, &mpInduct);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"Induct"}, false);
}

void ElectricInductance::initialize()
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
    // Hopsan quirk: the inductance is sampled only here.
    mInduct = *mpInduct;
    const double dt = mTimestep, L = mInduct;
    mDelayed1 = (-2.0 * mI2 * L - dt * mU1 + dt * mU2) / (2.0 * L);
}

void ElectricInductance::simulateOneTimestep()
{
    const double c1 = *mpPel1_c, Zc1 = *mpPel1_Zc;
    const double c2 = *mpPel2_c, Zc2 = *mpPel2_Zc;
    const double dt = mTimestep, L = mInduct;

    // Unknowns: (i2, u1, u2), starting from the previous step.
    mX[0] = mI2;
    mX[1] = mU1;
    mX[2] = mU2;
    for (int iter = 1; iter <= 2; ++iter) {
        mF[0] = mI2 + dt * (mU2 - mU1) / (2.0 * L) + mDelayed1;
        mF[1] = mU1 - c1 + Zc1 * mI2;
        mF[2] = mU2 - c2 - Zc2 * mI2;

        mJ[0][0] = 1.0;
        mJ[0][1] = -dt / (2.0 * L);
        mJ[0][2] = dt / (2.0 * L);
        mJ[1][0] = Zc1;
        mJ[1][1] = 1.0;
        mJ[1][2] = 0.0;
        mJ[2][0] = -Zc2;
        mJ[2][1] = 0.0;
        mJ[2][2] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) { stopSimulation("ElectricInductance: singular Jacobian"); }
        mI2 = mX[0];
        mU1 = mX[1];
        mU2 = mX[2];
        mI1 = -mI2;
    }

    mDelayed1 = (-2.0 * mI2 * L - dt * mU1 + dt * mU2) / (2.0 * L);

    *mpPel1_u = mU1;
    *mpPel1_i = mI1;
    *mpPel2_u = mU2;
    *mpPel2_i = mI2;
}

TLMHUB_REGISTER_COMPONENT(ElectricInductance, "Electric")

} // namespace tlmhub
