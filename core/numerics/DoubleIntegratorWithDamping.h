// Double integrator (acceleration -> velocity -> position) with numerical
// damping w0 on the first integral (utilities.md §9).
#pragma once

namespace tlmhub {

class DoubleIntegratorWithDamping
{
public:
    void initialize(double h, double w0, double u0 = 0.0, double y0 = 0.0, double sy0 = 0.0);
    void initializeValues(double u0, double y0, double sy0);
    void setDamping(double w0) { mW0 = w0; }

    void integrate(double u);
    void integrateWithUndo(double u);
    // Recomputes the last step from the backup with a new input.
    void redoIntegrate(double u);

    double valueFirst() const { return mDelayedV; }  // velocity
    double valueSecond() const { return mDelayedX; } // position

private:
    double mDelayedU = 0.0;
    double mDelayedX = 0.0;
    double mDelayedV = 0.0;
    double mBackupU = 0.0;
    double mBackupX = 0.0;
    double mBackupV = 0.0;
    double mTimeStep = 0.0;
    double mW0 = 0.0;
};

} // namespace tlmhub
