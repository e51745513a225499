#include "core/numerics/DoubleIntegratorWithDamping.h"

namespace tlmhub {

void DoubleIntegratorWithDamping::initialize(double h, double w0, double u0, double y0, double sy0)
{
    mTimeStep = h;
    mW0 = w0;
    initializeValues(u0, y0, sy0);
    mBackupU = u0;
    mBackupX = y0;
    mBackupV = sy0;
}

void DoubleIntegratorWithDamping::initializeValues(double u0, double y0, double sy0)
{
    mDelayedU = u0;
    mDelayedX = y0;
    mDelayedV = sy0;
}

void DoubleIntegratorWithDamping::integrate(double u)
{
    const double vOld = mDelayedV;
    mDelayedV = (2.0 - mW0) / (2.0 + mW0) * vOld + mTimeStep / (2.0 + mW0) * (u + mDelayedU);
    mDelayedX = mDelayedX + mTimeStep / 2.0 * (mDelayedV + vOld);
    mDelayedU = u;
}

void DoubleIntegratorWithDamping::integrateWithUndo(double u)
{
    mBackupV = mDelayedV;
    mBackupX = mDelayedX;
    mBackupU = mDelayedU;
    integrate(u);
}

void DoubleIntegratorWithDamping::redoIntegrate(double u)
{
    mDelayedV = (2.0 - mW0) / (2.0 + mW0) * mBackupV + mTimeStep / (2.0 + mW0) * (u + mBackupU);
    mDelayedX = mBackupX + mTimeStep / 2.0 * (mDelayedV + mBackupV);
    mDelayedU = u;
}

} // namespace tlmhub
