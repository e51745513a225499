// Double integrator with numerical damping and static/kinetic Coulomb
// friction expressed in input units, with a 3-valued motion mode
// (utilities.md §10).
#pragma once

namespace tlmhub {

class DoubleIntegratorWithDampingAndCoulombFriction
{
public:
    // Always starts in mode 0 (sticking), regardless of sy0.
    void initialize(double h, double w0, double Fs, double Fk, double u0 = 0.0, double y0 = 0.0, double sy0 = 0.0);
    void initializeValues(double u0, double y0, double sy0);
    void setFriction(double Fs, double Fk)
    {
        mUs = Fs;
        mUk = Fk;
    }
    void setDamping(double w0) { mW0 = w0; }

    void integrate(double u);
    void integrateWithUndo(double u);
    // Recomputes the last step from the backup, ignoring friction (as the reference).
    void redoIntegrate(double u);

    double valueFirst() const { return mDelayedV; }  // velocity
    double valueSecond() const { return mDelayedX; } // position
    int mode() const { return mMode; }

private:
    double mDelayedU = 0.0;
    double mDelayedX = 0.0;
    double mDelayedV = 0.0;
    double mBackupU = 0.0;
    double mBackupX = 0.0;
    double mBackupV = 0.0;
    double mTimeStep = 0.0;
    double mW0 = 0.0;
    double mUs = 0.0;
    double mUk = 0.0;
    int mMode = 0;
};

} // namespace tlmhub
