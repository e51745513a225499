#include "core/components/signal/SignalPID.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalPID::configure()
{
    addInputVariable("yref", "Reference value", "", 0.0, &mpYref);
    addInputVariable("y", "Measured value", "", 0.0, &mpY);
    addInputVariable("dy", "Derivative of the measured value", "", 0.0, &mpDy);
    addInputVariable("Kp", "Proportional gain", "", 1.0, &mpKp);
    addInputVariable("KI", "Integral gain", "", 1.0, &mpKI);
    addInputVariable("Kd", "Derivative gain", "", 1.0, &mpKd);
    addInputVariable("umin", "Lower output limit", "", -1.0, &mpUmin);
    addInputVariable("umax", "Upper output limit", "", 1.0, &mpUmax);
    addOutputVariable("u", "Control signal", "", 0.0, &mpU);
    addOutputVariable("Ierr", "Limited error fed to the integrator", "", 0.0, &mpIerr);
    addOutputVariable("uI", "Integral part", "", 0.0, &mpUI);
}

void SignalPID::initialize()
{
    mU = *mpU;
    mIerr = *mpIerr;
    mUI = *mpUI;
    const double KI = *mpKI;
    const double h = mTimestep;
    mD = (-(mIerr * KI * h) - 2. * mUI) / 2.;
}

void SignalPID::simulateOneTimestep()
{
    const double yref = *mpYref, y = *mpY, dy = *mpDy;
    const double Kp = *mpKp, KI = *mpKI, Kd = *mpKd;
    const double umin = *mpUmin, umax = *mpUmax;
    const double h = mTimestep;

    mX[0] = mU;
    mX[1] = mIerr;
    mX[2] = mUI;
    for (int iter = 1; iter <= 2; ++iter) {
        const double e = -y + yref;
        const double v = -(dy * Kd) + mUI + Kp * e;
        const double vl = limit(v, umin, umax);
        mF[0] = mU - vl;
        mF[1] = mIerr - e * dxLimit(vl, umin, umax);
        mF[2] = -(mIerr * KI * h) / 2. + mUI + mD;

        // Jacobian as in the reference (row 0 gates with the unlimited v,
        // row 1 ignores the dependence on uI).
        mJ[0][0] = 1.;
        mJ[0][1] = 0.;
        mJ[0][2] = -dxLimit(v, umin, umax);
        mJ[1][0] = 0.;
        mJ[1][1] = 1.;
        mJ[1][2] = 0.;
        mJ[2][0] = 0.;
        mJ[2][1] = -(KI * h) / 2.;
        mJ[2][2] = 1.;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("SignalPID: singular Jacobian.");
        }
        mU = mX[0];
        mIerr = mX[1];
        mUI = mX[2];
    }
    mD = (-(mIerr * KI * h) - 2. * mUI) / 2.;

    *mpU = mU;
    *mpIerr = mIerr;
    *mpUI = mUI;
}

TLMHUB_REGISTER_COMPONENT(SignalPID, "Signal")

} // namespace tlmhub
