#include "core/components/signal/SignalEarthCoordinates.h"

#include "core/ComponentFactory.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

// The literals 57.2958, 28.6479 and 0.0174533 are those of the reference model.
void SignalEarthCoordinates::computeDelayedParts(double h, double tc, double vx, double vy, double R)
{
    mD1 = (0.5 * (-2. * mLat * R - 57.2958 * h * tc * vx)) / R;
    mD2 = (0.5 * (-2. * mLon * R - 57.2958 * h * tc * vy * Sec(0.0174533 * mLat))) / R;
    mD3 = (-(h * tc) - 2. * mTE) / 2.;
}

void SignalEarthCoordinates::configure()
{
    addInputVariable("timecomp", "Time compression factor", "", 1.0, &mpTimecomp);
    addInputVariable("vxcg", "Northward speed", "m/s", 0.0, &mpVxcg);
    addInputVariable("vycg", "Eastward speed", "m/s", 0.0, &mpVycg);
    addInputVariable("R", "Earth radius", "m", 6367500.0, &mpR);
    addOutputVariable("timeE", "Effective time", "sec", 0.0, &mpTimeE);
    addOutputVariable("longitude", "Longitude (degrees)", "m", 0.0, &mpLongitude);
    addOutputVariable("lattitude", "Latitude (degrees)", "m", 0.0, &mpLattitude);
}

void SignalEarthCoordinates::initialize()
{
    mLat = *mpLattitude;
    mLon = *mpLongitude;
    mTE = *mpTimeE;
    computeDelayedParts(mTimestep, *mpTimecomp, *mpVxcg, *mpVycg, *mpR);
    simulateOneTimestep();
}

void SignalEarthCoordinates::simulateOneTimestep()
{
    const double tc = *mpTimecomp, vx = *mpVxcg, vy = *mpVycg, R = *mpR;
    const double h = mTimestep;

    mX[0] = mLat;
    mX[1] = mLon;
    mX[2] = mTE;
    for (int iter = 1; iter <= 2; ++iter) {
        mF[0] = mLat - (28.6479 * h * tc * vx) / R + mD1;
        mF[1] = mLon + mD2 - (28.6479 * h * tc * vy * Sec(0.0174533 * mLat)) / R;
        mF[2] = -(h * tc) / 2. + mTE + mD3;

        mJ[0][0] = 1.;
        mJ[0][1] = 0.;
        mJ[0][2] = 0.;
        mJ[1][0] = (-0.5 * h * tc * vy * Sec(0.0174533 * mLat) * Tan(0.0174533 * mLat)) / R;
        mJ[1][1] = 1.;
        mJ[1][2] = 0.;
        mJ[2][0] = 0.;
        mJ[2][1] = 0.;
        mJ[2][2] = 1.;

        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("SignalEarthCoordinates: singular Jacobian.");
        }
        mLat = mX[0];
        mLon = mX[1];
        mTE = mX[2];
    }
    computeDelayedParts(h, tc, vx, vy, R);

    *mpTimeE = mTE;
    *mpLongitude = mLon;
    *mpLattitude = mLat;
}

TLMHUB_REGISTER_COMPONENT(SignalEarthCoordinates, "Signal")

} // namespace tlmhub
