#include "core/components/signal/SignalSteadyStateIdentifier.h"

#include "core/ComponentFactory.h"
#include "core/numerics/WhiteGaussianNoise.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace tlmhub {

void SignalSteadyStateIdentifier::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addOutputVariable("out", "1 at steady state, else 0", "", &mpOut);
    addConditionalConstant("method", "Identification method",
                           {"Rectangular sliding window", "Variance ratio test (F-test)",
                            "Exponentially weighted variance ratio (R-test)"},
                           0, mMethod);
    addInputVariable("tol", "Tolerance", "", 1.0, &mpTol);
    addInputVariable("wl", "Window length (methods 0 and 1)", "s", 0.1, &mpWl);
    addInputVariable("sd", "Standard deviation of added noise (methods 1 and 2)", "", 0.01, &mpSd);
    addInputVariable("l1", "Filter factor 1 (method 2)", "", 0.1, &mpL1);
    addInputVariable("l2", "Filter factor 2 (method 2)", "", 0.1, &mpL2);
    addInputVariable("l3", "Filter factor 3 (method 2)", "", 0.1, &mpL3);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"wl"}, false);
}

void SignalSteadyStateIdentifier::initialize()
{
    mpRandom = &randomStream();
    // Window length fixed from the t0 value of wl (truncated quotient).
    const double q = std::floor(*mpWl / mTimestep);
    const long long n = (q > 0.0) ? static_cast<long long>(q) : 0;
    mN = static_cast<std::size_t>(n);
    mK = 0;
    mXd = *mpIn;
    mXfd = *mpIn;
    mDfd = 0.0;
    // Checked for every method, even method 2 which does not use the window.
    if (n <= 2) {
        stopSimulation("Window too small: wl must be larger than 2 time steps");
        return;
    }
    mWindow.assign(mN, 0.0);
    mNoisy.assign(mN, 0.0);
    // Evaluated once at t0 (puts the first input in the window, may draw noise).
    simulateOneTimestep();
}

void SignalSteadyStateIdentifier::simulateOneTimestep()
{
    if (mN <= 2) return;
    const double in = *mpIn;
    const double tol = *mpTol;

    if (mMethod == 0 || mMethod == 1) {
        mWindow[mK] = in;
        ++mK;
        if (mK == mN) mK = 0;
    }

    if (mMethod == 0) {
        double xmax = mWindow[0];
        double xmin = mWindow[0];
        for (std::size_t i = 1; i < mN; ++i) {
            xmax = std::max(xmax, mWindow[i]);
            xmin = std::min(xmin, mWindow[i]);
        }
        *mpOut = (xmax - xmin < tol) ? 1.0 : 0.0;
    } else if (mMethod == 1) {
        const double sd = *mpSd;
        const double dN = static_cast<double>(mN);
        const double dN1 = static_cast<double>(mN - 1);
        double sum = 0.0;
        for (std::size_t i = 0; i < mN; ++i) {
            mNoisy[i] = mWindow[i] + sd * WhiteGaussianNoise::getValue(*mpRandom);
            sum += mNoisy[i];
        }
        const double m = sum / dN;
        double s1 = 0.0;
        for (std::size_t i = 0; i < mN; ++i) {
            const double d = mNoisy[i] - m;
            s1 += d * d;
        }
        s1 = s1 / dN1;
        // Consecutive pairs in chronological order, starting at the oldest entry.
        double s2 = 0.0;
        std::size_t prev = mK;
        for (std::size_t j = 0; j + 1 < mN; ++j) {
            std::size_t next = prev + 1;
            if (next == mN) next = 0;
            const double d = mNoisy[next] - mNoisy[prev];
            s2 += d * d;
            prev = next;
        }
        s2 = s2 / dN1;
        s1 = std::max(DBL_MIN, std::fabs(s1));
        s2 = std::max(DBL_MIN, std::fabs(s2));
        *mpOut = (s1 / s2 < tol) ? 1.0 : 0.0;
    } else {
        const double l1 = *mpL1;
        const double l2 = *mpL2;
        const double l3 = *mpL3;
        const double x = in + *mpSd * WhiteGaussianNoise::getValue(*mpRandom);
        const double e1 = x - mXfd;
        const double vf = l2 * (e1 * e1);
        double s1 = (2.0 - l1) / 2.0 * vf;
        const double e2 = x - mXd;
        const double df = l3 * (e2 * e2) + (1.0 - l3) * mDfd;
        double s2 = df / 2.0;
        s1 = std::max(DBL_MIN, std::fabs(s1));
        s2 = std::max(DBL_MIN, std::fabs(s2));
        *mpOut = (s1 / s2 < tol) ? 1.0 : 0.0;
        mXd = x;
        mXfd = l1 * x + (1.0 - l1) * mXfd;
        mDfd = df;
    }
}

TLMHUB_REGISTER_COMPONENT(SignalSteadyStateIdentifier, "Signal")

} // namespace tlmhub
