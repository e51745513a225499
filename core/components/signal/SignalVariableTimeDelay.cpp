#include "core/components/signal/SignalVariableTimeDelay.h"

#include "core/ComponentFactory.h"
#include <algorithm>
#include <utility>

namespace tlmhub {

void SignalVariableTimeDelay::configure()
{
    addInputVariable("dT", "Time delay", "s", 1.0, &mpDT);
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "Output signal", "", &mpOut);
    addConstant("maxMem", "Memory limit of the delay buffer", "MB", 50.0, mMaxMem);
}

void SignalVariableTimeDelay::initialize()
{
    if (*mpDT < 0.0) {
        addWarningMessage("Time delay dT is negative; it is treated as zero.");
    }
    mN = 0;
    simulateOneTimestep();
}

void SignalVariableTimeDelay::simulateOneTimestep()
{
    const double u = *mpIn;
    const std::size_t n = static_cast<std::size_t>(std::max(*mpDT, 0.0) / mTimestep + 0.5);
    if (n != mN) {
        if (static_cast<double>(n) > mMaxMem * 1e6 / 8.0) {
            stopSimulation("SignalVariableTimeDelay: requested delay needs more memory than maxMem.");
            return;
        }
        if (n > 0) {
            mSpare.initialize(static_cast<int>(n), 0.0);
            if (n < mN) {
                // Keep the n oldest samples.
                for (std::size_t i = 0; i < n; ++i) { mSpare.update(mBuf.getOldIdx(i)); }
            } else {
                // Keep every old sample, pad with the newest one (or the input if none).
                for (std::size_t i = 0; i < mN; ++i) { mSpare.update(mBuf.getOldIdx(i)); }
                const double pad = (mN > 0) ? mBuf.getNewest() : u;
                for (std::size_t i = mN; i < n; ++i) { mSpare.update(pad); }
            }
            std::swap(mBuf, mSpare);
        }
        mN = n;
    }
    if (mN == 0) {
        *mpOut = u;
    } else {
        *mpOut = mBuf.update(u);
    }
}

TLMHUB_REGISTER_COMPONENT(SignalVariableTimeDelay, "Signal")

} // namespace tlmhub
