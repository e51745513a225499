#include "core/components/signal/SignalTimeAccelerator.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalTimeAccelerator::computeDelayedParts(double h, double tc, double vx, double vy)
{
    mD1 = (-(h * tc * vx) - 2. * mXcgE) / 2.;
    mD2 = (-(h * tc * vy) - 2. * mYcgE) / 2.;
    mD3 = (-(h * tc) - 2. * mTimeE) / 2.;
}

void SignalTimeAccelerator::configure()
{
    addInputVariable("timecomp", "Time compression factor", "", 1.0, &mpTimecomp);
    addInputVariable("massflow", "Mass flow", "kg/s", 0.0, &mpMassflow);
    addInputVariable("vxcg", "Velocity x", "m", 0.0, &mpVxcg);
    addInputVariable("vycg", "Velocity y", "m", 0.0, &mpVycg);
    addOutputVariable("timeE", "Effective time", "sec", 0.0, &mpTimeE);
    addOutputVariable("massflowE", "Scaled mass flow", "kg", 0.0, &mpMassflowE);
    addOutputVariable("xcgE", "Position x", "m", 0.0, &mpXcgE);
    addOutputVariable("ycgE", "Position y", "m", 0.0, &mpYcgE);
}

void SignalTimeAccelerator::initialize()
{
    mTimeE = *mpTimeE;
    mMassflowE = *mpMassflowE;
    mXcgE = *mpXcgE;
    mYcgE = *mpYcgE;
    computeDelayedParts(mTimestep, *mpTimecomp, *mpVxcg, *mpVycg);
    simulateOneTimestep();
}

void SignalTimeAccelerator::simulateOneTimestep()
{
    const double tc = *mpTimecomp, massflow = *mpMassflow, vx = *mpVxcg, vy = *mpVycg;
    const double h = mTimestep;

    mX[0] = mXcgE;
    mX[1] = mYcgE;
    mX[2] = mTimeE;
    for (int iter = 1; iter <= 2; ++iter) {
        mF[0] = -(h * tc * vx) / 2. + mXcgE + mD1;
        mF[1] = -(h * tc * vy) / 2. + mYcgE + mD2;
        mF[2] = -(h * tc) / 2. + mTimeE + mD3;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) { mJ[i][j] = (i == j) ? 1. : 0.; }
        }
        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("SignalTimeAccelerator: singular Jacobian.");
        }
        mXcgE = mX[0];
        mYcgE = mX[1];
        mTimeE = mX[2];
        mMassflowE = massflow * tc;
    }
    computeDelayedParts(h, tc, vx, vy);

    *mpTimeE = mTimeE;
    *mpMassflowE = mMassflowE;
    *mpXcgE = mXcgE;
    *mpYcgE = mYcgE;
}

TLMHUB_REGISTER_COMPONENT(SignalTimeAccelerator, "Signal")

} // namespace tlmhub
