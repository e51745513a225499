#include "core/components/electric/ElectricBattery.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

#include <cmath>

namespace tlmhub {

void ElectricBattery::configure()
{
    mpPel1 = addPowerPort("Pel1", NodeType::Electric);
    addInputVariable("cond", "Inner conductance", "1/ohm", 1000.0, &mpCond);
    addInputVariable("unom", "Nominal voltage", "V", 12.0, &mpUnom);
    addInputVariable("capacity", "Capacity", "Ah", 41.0, &mpCapacity);
    addInputVariable("kappa", "Exponent of discharge curve", "", 0.1, &mpKappa);
    addInputVariable("e", "Base of the exponential", "", 2.71828, &mpE);
    addOutputVariable("soc", "State of charge", "", 1.0, &mpSoc);
    addOutputVariable("ubatt", "Internal voltage", "V", 0.0, &mpUbatt);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"cond", "unom", "capacity", "kappa", "e"}, false);
}

void ElectricBattery::initialize()
{
    mpPel1_u = getSafeNodeDataPtr(mpPel1, NodeElectric::Voltage);
    mpPel1_i = getSafeNodeDataPtr(mpPel1, NodeElectric::Current);
    mpPel1_c = getSafeNodeDataPtr(mpPel1, NodeElectric::WaveVariable);
    mpPel1_Zc = getSafeNodeDataPtr(mpPel1, NodeElectric::CharImpedance);

    mU1 = *mpPel1_u;
    mI1 = *mpPel1_i;
    // Hopsan quirk: all inputs are sampled only here.
    mCond = *mpCond;
    mUnom = *mpUnom;
    mCapacity = *mpCapacity;
    mKappa = *mpKappa;
    mE = *mpE;
    mSoc = *mpSoc;
    mUbatt = *mpUbatt;

    const double dt = mTimestep;
    mDelayed1 = (mI1 * dt - 7200.0 * mCapacity * mSoc) / (7200.0 * mCapacity);
}

void ElectricBattery::simulateOneTimestep()
{
    const double c1 = *mpPel1_c, Zc1 = *mpPel1_Zc;
    const double dt = mTimestep;
    const double cond = mCond, unom = mUnom, capacity = mCapacity, kappa = mKappa, e = mE;

    mX[0] = mSoc;
    mX[1] = mI1;
    mX[2] = mUbatt;
    mX[3] = mU1;
    for (int iter = 1; iter <= 2; ++iter) {
        const double soc = mSoc, i1 = mI1, ubatt = mUbatt, u1 = mU1;
        const double S = limit(soc, 1.0e-9, 0.9999);
        const double E = std::pow(e, 10.0 * soc / kappa);
        const double asinS = std::asin(S);
        const double arg = -(i1 * dt) / (7200.0 * capacity) - mDelayed1;

        mF[0] = soc - limit(arg, 0.001, 0.999);
        mF[1] = i1 + cond * (u1 - ubatt);
        mF[2] = ubatt - std::pow(2.0, kappa) * (E - 1.0) * unom * std::pow(asinS, kappa) / (1.0 + E);
        mF[3] = u1 - c1 - Zc1 * i1;

        // Row 2 is -d f / d soc (ln(e) uses the input e, not Euler's number).
        const double J20 =
            -std::pow(2.0, kappa) * (E - 1.0) * kappa * unom * std::pow(asinS, kappa - 1.0)
                * dxLimit(soc, 1.0e-9, 0.9999) / ((1.0 + E) * std::sqrt(1.0 - S * S))
            + 5.0 * std::pow(2.0, 1.0 + kappa) * E * (E - 1.0) * unom * std::pow(asinS, kappa) * std::log(e)
                  / (std::pow(1.0 + E, 2.0) * kappa)
            - 5.0 * std::pow(2.0, 1.0 + kappa) * E * unom * std::pow(asinS, kappa) * std::log(e)
                  / ((1.0 + E) * kappa);

        mJ[0][0] = 1.0;
        mJ[0][1] = dt * dxLimit(arg, 0.001, 0.999) / (7200.0 * capacity);
        mJ[0][2] = 0.0;
        mJ[0][3] = 0.0;
        mJ[1][0] = 0.0;
        mJ[1][1] = 1.0;
        mJ[1][2] = -cond;
        mJ[1][3] = cond;
        mJ[2][0] = J20;
        mJ[2][1] = 0.0;
        mJ[2][2] = 1.0;
        mJ[2][3] = 0.0;
        mJ[3][0] = 0.0;
        mJ[3][1] = -Zc1;
        mJ[3][2] = 0.0;
        mJ[3][3] = 1.0;

        if (!mSolver.solve(mJ, mF, mX, iter)) { stopSimulation("ElectricBattery: singular Jacobian"); }
        mSoc = mX[0];
        mI1 = mX[1];
        mUbatt = mX[2];
        mU1 = mX[3];
    }

    mDelayed1 = (mI1 * dt - 7200.0 * mCapacity * mSoc) / (7200.0 * mCapacity);

    *mpPel1_u = mU1;
    *mpPel1_i = mI1;
    *mpSoc = mSoc;
    *mpUbatt = mUbatt;
}

TLMHUB_REGISTER_COMPONENT(ElectricBattery, "Electric")

} // namespace tlmhub
