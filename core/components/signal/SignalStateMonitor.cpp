#include "core/components/signal/SignalStateMonitor.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/MathematicaWrappers.h"

namespace tlmhub {

void SignalStateMonitor::computeDelayedParts(double h, double thau)
{
    mD1 = (h * mY1f - 2. * thau * mY1f - h * Abs(*mpY1)) / (h + 2. * thau);
    mD2 = (h * mY2f - 2. * thau * mY2f - h * Abs(*mpY2)) / (h + 2. * thau);
    mD3 = (h * mY3f - 2. * thau * mY3f - h * Abs(*mpY3)) / (h + 2. * thau);
}

void SignalStateMonitor::configure()
{
    addInputVariable("y1", "Monitored signal 1", "", 0.0, &mpY1);
    addInputVariable("y2", "Monitored signal 2", "", 0.0, &mpY2);
    addInputVariable("y3", "Monitored signal 3", "", 0.0, &mpY3);
    addInputVariable("sOn", "Extra trigger", "", 0.0, &mpSOn);
    addInputVariable("y10", "Threshold 1", "", 0.02, &mpY10);
    addInputVariable("y20", "Threshold 2", "", 0.02, &mpY20);
    addInputVariable("y30", "Threshold 3", "", 0.02, &mpY30);
    addInputVariable("thau", "Filter time constant", "sec", 1.0, &mpThau);
    addOutputVariable("s1", "Alarm flag", "", 0.0, &mpS1);
    addOutputVariable("y1f", "Filtered |y1|", "", 0.0, &mpY1f);
    addOutputVariable("y2f", "Filtered |y2|", "", 0.0, &mpY2f);
    addOutputVariable("y3f", "Filtered |y3|", "", 0.0, &mpY3f);
}

void SignalStateMonitor::initialize()
{
    mS1 = *mpS1;
    mY1f = *mpY1f;
    mY2f = *mpY2f;
    mY3f = *mpY3f;
    computeDelayedParts(mTimestep, *mpThau);
    simulateOneTimestep();
}

void SignalStateMonitor::simulateOneTimestep()
{
    const double y1 = *mpY1, y2 = *mpY2, y3 = *mpY3, sOn = *mpSOn;
    const double y10 = *mpY10, y20 = *mpY20, y30 = *mpY30, thau = *mpThau;
    const double h = mTimestep;

    mX[0] = mY1f;
    mX[1] = mY2f;
    mX[2] = mY3f;
    mX[3] = mS1;
    for (int iter = 1; iter <= 2; ++iter) {
        mF[0] = mY1f - (h * Abs(y1)) / (h + 2. * thau) + mD1;
        mF[1] = mY2f - (h * Abs(y2)) / (h + 2. * thau) + mD2;
        mF[2] = mY3f - (h * Abs(y3)) / (h + 2. * thau) + mD3;
        mF[3] = mS1
                - onPositive(-0.5 + sOn + onPositive(-Abs(y10) + Abs(mY1f)) + onPositive(-Abs(y20) + Abs(mY2f))
                             + onPositive(-Abs(y30) + Abs(mY3f)));
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) { mJ[i][j] = (i == j) ? 1. : 0.; }
        }
        if (!mSolver.solve(mJ, mF, mX, iter)) {
            stopSimulation("SignalStateMonitor: singular Jacobian.");
        }
        mY1f = mX[0];
        mY2f = mX[1];
        mY3f = mX[2];
        mS1 = mX[3];
    }
    computeDelayedParts(h, thau);

    *mpS1 = mS1;
    *mpY1f = mY1f;
    *mpY2f = mY2f;
    *mpY3f = mY3f;
}

TLMHUB_REGISTER_COMPONENT(SignalStateMonitor, "Signal")

} // namespace tlmhub
