#include "core/components/signal/SignalPID2.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalPID2::configure()
{
    addInputVariable("e", "Control error", "", 0.0, &mpE);
    addInputVariable("de", "Derivative of the control error", "", 0.0, &mpDe);
    addOutputVariable("u", "Control signal", "", &mpU);
    addConstant("K", "Proportional gain", "", 1.0, mK);
    addConstant("Ti", "Integral time", "s", 1.0, mTi);
    addConstant("Tt", "Tracking time constant", "s", 1.0, mTt);
    addConstant("Td", "Derivative time", "s", 0.0, mTd);
    addConstant("Umin", "Anti-windup lower level", "", -1e+100, mUmin);
    addConstant("Umax", "Anti-windup upper level", "", 1e+100, mUmax);
    addConstant("Uoutmin", "Lower output limit", "", -1e+100, mUoutmin);
    addConstant("Uoutmax", "Upper output limit", "", 1e+100, mUoutmax);
    mpDePort = port("de");
}

void SignalPID2::initialize()
{
    mI = 0.0;
    mEprev = 0.0;
    mUseDe = mpDePort->isConnected();
    if (mTt < mTi) {
        addWarningMessage("Tt is smaller than Ti; the tracking time constant should be larger.");
    }
    if (mUmin > mUmax) {
        addErrorMessage("Umin is larger than Umax.");
    }
    if (mUoutmin > mUoutmax) {
        addErrorMessage("Uoutmin is larger than Uoutmax.");
    }
}

void SignalPID2::simulateOneTimestep()
{
    const double h = mTimestep;
    const double err = *mpE;
    double dErr;
    if (mUseDe) {
        dErr = *mpDe;
    } else {
        dErr = (err - mEprev) / h;
        mEprev = err;
    }
    mI = mI + mK * h / mTi * err;
    double v = mK * err + mI + mK * mTd * dErr;
    // Back-calculation uses the unclamped v; v itself is not recomputed.
    if (v > mUmax) {
        mI = mI + h / mTt * (mUmax - v);
    } else if (v < mUmin) {
        mI = mI + h / mTt * (mUmin - v);
    }
    if (v > mUoutmax) {
        v = mUoutmax;
    } else if (v < mUoutmin) {
        v = mUoutmin;
    }
    *mpU = v;
}

TLMHUB_REGISTER_COMPONENT(SignalPID2, "Signal")

} // namespace tlmhub
