#include "core/components/electric/ElectricPWMdceq.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void ElectricPWMdceq::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    mpPel2 = addPowerPort("Pel2", NodeType::Electric);
    addInputVariable("tfac", "Duty fraction Tc/Tp", "", 1.0, &mpTfac);
    addInputVariable("resist0", "Resistance at full duty", "ohm", 0.01, &mpResist0);
    addInputVariable("resist1", "Resistance at zero duty", "ohm", 10.0, &mpResist1);
    addInputVariable("umin", "Min voltage", "V", 0.01, &mpUmin);
    addInputVariable("umax", "Max voltage", "V", 1000.0, &mpUmax);
    addOutputVariable("uel10", "Internal voltage", "V", 0.0, &mpUel10);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"resist0", "resist1", "umin", "umax"}, false);
}

void ElectricPWMdceq::initialize()
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
    mU10 = *mpUel10;
    // Hopsan quirk: only tfac is re-read during stepping.
    mResist0 = *mpResist0;
    mResist1 = *mpResist1;
    mUmin = *mpUmin;
    mUmax = *mpUmax;
}

void ElectricPWMdceq::simulateOneTimestep()
{
    const double c1 = *mpPel1_c, Zc1 = *mpPel1_Zc;
    const double c2 = *mpPel2_c, Zc2 = *mpPel2_Zc;
    const double tf = limit(*mpTfac, 0.0, 1.0);
    const double resist0 = mResist0, resist1 = mResist1, umin = mUmin, umax = mUmax;

    mX[0] = mU2;
    mX[1] = mU10;
    mX[2] = mI1;
    mX[3] = mU1;
    mX[4] = mI2;
    for (int iter = 1; iter <= 2; ++iter) {
        const double u2 = mU2, u10 = mU10, i1 = mI1, u1 = mU1, i2 = mI2;
        const double lu2 = limit(u2, umin, umax);
        const double lu10 = limit(u10, umin, umax);

        mF[0] = u2 - u10 * tf;
        mF[1] = u10 - u1 - i1 * (resist1 - (resist1 - resist0) * tf);
        mF[2] = i1 + i2 * lu2 / lu10;
        mF[3] = u1 - c1 - Zc1 * i1;
        // Divides by Zc2: the node at Pel2 must have a non-zero impedance.
        mF[4] = i2 + (c2 - u2) / Zc2;

        mJ[0][0] = 1.0;
        mJ[0][1] = -tf;
        mJ[0][2] = 0.0;
        mJ[0][3] = 0.0;
        mJ[0][4] = 0.0;
        mJ[1][0] = 0.0;
        mJ[1][1] = 1.0;
        mJ[1][2] = -resist1 + (resist1 - resist0) * tf;
        mJ[1][3] = -1.0;
        mJ[1][4] = 0.0;
        mJ[2][0] = i2 * dxLimit(u2, umin, umax) / lu10;
        mJ[2][1] = -i2 * dxLimit(u10, umin, umax) * lu2 / (lu10 * lu10);
        mJ[2][2] = 1.0;
        mJ[2][3] = 0.0;
        mJ[2][4] = lu2 / lu10;
        mJ[3][0] = 0.0;
        mJ[3][1] = 0.0;
        mJ[3][2] = -Zc1;
        mJ[3][3] = 1.0;
        mJ[3][4] = 0.0;
        mJ[4][0] = -1.0 / Zc2;
        mJ[4][1] = 0.0;
        mJ[4][2] = 0.0;
        mJ[4][3] = 0.0;
        mJ[4][4] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) { stopSimulation("ElectricPWMdceq: singular Jacobian"); }
        mU2 = mX[0];
        mU10 = mX[1];
        mI1 = mX[2];
        mU1 = mX[3];
        mI2 = mX[4];
    }

    *mpPel1_u = mU1;
    *mpPel1_i = mI1;
    *mpPel2_u = mU2;
    *mpPel2_i = mI2;
    *mpUel10 = mU10;
}

TLMHUB_REGISTER_COMPONENT(ElectricPWMdceq, "Electric")

} // namespace tlmhub
