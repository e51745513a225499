#include "core/components/signal/SignalPIlead.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

void SignalPIlead::computeDelayedParts(double h, double y, double yref, double k1, double w11, double w21,
                                       double w22)
{
    mD1 = (-2. * mErr * w21 + mErr * h * w21 * w22 - 2. * w22 * y + h * w21 * w22 * y + 2. * w21 * yref
           - h * w21 * w22 * yref)
          / (2. * w21 + h * w21 * w22);
    mD4 = (-2. * mUI - mIerr * k1 * h * w11) / 2.;
}

void SignalPIlead::configure()
{
    addInputVariable("yref", "Reference value", "", 0.0, &mpYref);
    addInputVariable("kx", "Gain factor", "rad/s", 1.0, &mpKx);
    addInputVariable("y", "Measured value", "", 0.0, &mpY);
    addInputVariable("wa", "Crossover frequency", "rad/s", 1.0, &mpWa);
    addInputVariable("da", "Lead damping", "", 1.0, &mpDa);
    addInputVariable("umin", "Lower output limit", "", -1.0, &mpUmin);
    addInputVariable("umax", "Upper output limit", "", 1.0, &mpUmax);
    addOutputVariable("u", "Control signal", "", 0.0, &mpU);
    addOutputVariable("err", "Filtered control error", "", 0.0, &mpErr);
    addOutputVariable("Ierr", "Limited error fed to the integrator", "", 0.0, &mpIerr);
    addOutputVariable("uI", "Integral part", "", 0.0, &mpUI);
}

void SignalPIlead::initialize()
{
    const double kx = *mpKx, wa = *mpWa, da = *mpDa;
    mU = *mpU;
    mErr = *mpErr;
    mIerr = *mpIerr;
    mUI = *mpUI;
    const double k1 = wa / kx;
    const double w11 = wa;
    const double w21 = wa / (2. * da);
    const double w22 = wa;
    computeDelayedParts(mTimestep, *mpY, *mpYref, k1, w11, w21, w22);
}

void SignalPIlead::simulateOneTimestep()
{
    const double yref = *mpYref, kx = *mpKx, y = *mpY, wa = *mpWa, da = *mpDa;
    const double umin = *mpUmin, umax = *mpUmax;
    const double h = mTimestep;
    const double k1 = wa / kx;
    const double w11 = wa;
    const double w21 = wa / (2. * da);
    const double w22 = wa;

    mX[0] = mErr;
    mX[1] = mU;
    mX[2] = mIerr;
    mX[3] = mUI;
    for (int iter = 1; iter <= 2; ++iter) {
        const double a = mErr * k1 + mUI;
        const double al = limit(a, umin, umax);
        mF[0] = mErr
                + (2. * w22 * y + h * w21 * w22 * y - 2. * w21 * yref - h * w21 * w22 * yref)
                      / (2. * w21 + h * w21 * w22)
                + mD1;
        mF[1] = mU - al;
        mF[2] = mIerr - mErr * dxLimit(al, umin, umax);
        mF[3] = mUI - (mIerr * k1 * h * w11) / 2. + mD4;

        mJ[0][0] = 1.;
        mJ[0][1] = 0.;
        mJ[0][2] = 0.;
        mJ[0][3] = 0.;
        mJ[1][0] = -(k1 * dxLimit(a, umin, umax));
        mJ[1][1] = 1.;
        mJ[1][2] = 0.;
        mJ[1][3] = -dxLimit(a, umin, umax);
        mJ[2][0] = -dxLimit(al, umin, umax);
        mJ[2][1] = 0.;
        mJ[2][2] = 1.;
        mJ[2][3] = 0.;
        mJ[3][0] = 0.;
        mJ[3][1] = 0.;
        mJ[3][2] = -(k1 * h * w11) / 2.;
        mJ[3][3] = 1.;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("SignalPIlead: singular Jacobian.");
        }
        mErr = mX[0];
        mU = mX[1];
        mIerr = mX[2];
        mUI = mX[3];
    }
    computeDelayedParts(h, y, yref, k1, w11, w21, w22);

    *mpU = mU;
    *mpErr = mErr;
    *mpIerr = mIerr;
    *mpUI = mUI;
}

TLMHUB_REGISTER_COMPONENT(SignalPIlead, "Signal")

} // namespace tlmhub
