// Trapezoidal integrator y = integral of u dt (utilities.md §7, §7.1).
#pragma once

#include "core/numerics/Delay.h"

namespace tlmhub {

class Integrator
{
public:
    void initialize(double h, double u0 = 0.0, double y0 = 0.0)
    {
        mTimeStep = h;
        mDelayedU = u0;
        mDelayedY = y0;
    }

    void initializeValues(double u0, double y0)
    {
        mDelayedU = u0;
        mDelayedY = y0;
    }

    double update(double u)
    {
        mDelayedY = mDelayedY + mTimeStep / 2.0 * (u + mDelayedU);
        mDelayedU = u;
        return mDelayedY;
    }

    double value() const { return mDelayedY; }
    double delayedU() const { return mDelayedU; }

protected:
    double mDelayedU = 0.0;
    double mDelayedY = 0.0;
    double mTimeStep = 0.0;
};

// Integrator with a configurable backup of (uPrev, yPrev) for iterative callers.
class IntegratorWithBackup : public Integrator
{
public:
    void initialize(double h, double u0 = 0.0, double y0 = 0.0)
    {
        Integrator::initialize(h, u0, y0);
        setBackupLength(1);
    }

    void setBackupLength(int n)
    {
        mBackupU.initialize(n, mDelayedU);
        mBackupY.initialize(n, mDelayedY);
    }

    void backup()
    {
        mBackupU.update(mDelayedU);
        mBackupY.update(mDelayedY);
    }

    // n = 1 restores the most recent backup; n = 0 is treated as 1.
    void restoreBackup(int n = 1)
    {
        const std::size_t m = static_cast<std::size_t>((n > 0) ? n - 1 : 0);
        mDelayedU = mBackupU.getIdx(m);
        mDelayedY = mBackupY.getIdx(m);
    }

    double updateWithBackup(double u)
    {
        backup();
        return update(u);
    }

private:
    Delay mBackupU;
    Delay mBackupY;
};

} // namespace tlmhub
