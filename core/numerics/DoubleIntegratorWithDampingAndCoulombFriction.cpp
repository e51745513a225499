#include "core/numerics/DoubleIntegratorWithDampingAndCoulombFriction.h"

namespace tlmhub {

void DoubleIntegratorWithDampingAndCoulombFriction::initialize(double h, double w0, double Fs, double Fk, double u0,
                                                               double y0, double sy0)
{
    mTimeStep = h;
    mW0 = w0;
    mUs = Fs;
    mUk = Fk;
    initializeValues(u0, y0, sy0);
    mBackupU = u0;
    mBackupX = y0;
    mBackupV = sy0;
    mMode = 0;
}

void DoubleIntegratorWithDampingAndCoulombFriction::initializeValues(double u0, double y0, double sy0)
{
    mDelayedU = u0;
    mDelayedX = y0;
    mDelayedV = sy0;
}

void DoubleIntegratorWithDampingAndCoulombFriction::integrate(double u)
{
    const double vOld = mDelayedV;
    // Effective input that would bring the velocity exactly to zero this step.
    const double ues = -(2.0 - mW0) / mTimeStep * vOld - mDelayedU;

    switch (mMode) {
    case 0:
        // Sticking: only decide the mode; motion starts on the next step.
        if (u >= mUs) {
            mMode = 1;
        } else if (u <= -mUs) {
            mMode = -1;
        }
        break;
    case 1:
        if (ues > u - mUk) {
            mDelayedV = 0.0; // velocity would change sign: stop, hold position
            mMode = 0;
        } else {
            const double ue = u - mUk;
            mDelayedV = (2.0 - mW0) / (2.0 + mW0) * vOld + mTimeStep / (2.0 + mW0) * (ue + mDelayedU);
            mDelayedX = mDelayedX + mTimeStep / 2.0 * (mDelayedV + vOld);
            mDelayedU = ue;
        }
        break;
    case -1:
        if (ues < u + mUk) {
            mDelayedV = 0.0;
            mMode = 0;
        } else {
            const double ue = u + mUk;
            mDelayedV = (2.0 - mW0) / (2.0 + mW0) * vOld + mTimeStep / (2.0 + mW0) * (ue + mDelayedU);
            mDelayedX = mDelayedX + mTimeStep / 2.0 * (mDelayedV + vOld);
            mDelayedU = ue;
        }
        break;
    default:
        mMode = 0;
        break;
    }
}

void DoubleIntegratorWithDampingAndCoulombFriction::integrateWithUndo(double u)
{
    mBackupV = mDelayedV;
    mBackupX = mDelayedX;
    mBackupU = mDelayedU;
    integrate(u);
}

void DoubleIntegratorWithDampingAndCoulombFriction::redoIntegrate(double u)
{
    mDelayedV = (2.0 - mW0) / (2.0 + mW0) * mBackupV + mTimeStep / (2.0 + mW0) * (u + mBackupU);
    mDelayedX = mBackupX + mTimeStep / 2.0 * (mDelayedV + mBackupV);
    mDelayedU = u;
}

} // namespace tlmhub
