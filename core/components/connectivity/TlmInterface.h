#pragma once
#include "core/Component.h"

#include <array>
#include <cmath>

namespace tlmhub {

// The end of a TLM line whose other end another simulation tool computes (Hopsan's
// <Domain>InterfaceTLM types). That tool sends effort e2 and flow f2 of its end, sampled at
// its own rate; the line delays them by Td, so this end's wave variable is
//     c = e2(t - Td) + Zc * f2(t - Td),   Zc from the parameter.
// When Td is one time step (within 1 %) the inputs are used as they are. Otherwise the last
// three distinct samples (with the times they arrived) are interpolated, linearly or
// quadratically, at t - Td, which extrapolates when Td is shorter than the sampling period.
// Spec names the domain: node type, wave/impedance slots, and the input names and units.
template <typename Spec>
class TlmInterface : public ComponentC {
public:
    void configure() override
    {
        mpP1 = addPowerPort("P1", Spec::node);
        addInputVariable(Spec::flowName, Spec::flowDescription, Spec::flowUnit, 0.0, &mpFlowIn);
        addInputVariable(Spec::effortName, Spec::effortDescription, Spec::effortUnit, 0.0, &mpEffortIn);
        addConstant("Zc", "Characteristic impedance", Spec::impedanceUnit, 0.0, mZc);
        addConstant("Td", "Time delay", "s", 0.0, mTd);
        addConditionalConstant("interpolation", "Interpolation method",
                               {"Linear Interpolation", "Quadratic Interpolation"}, 0, mInterpolation);
    }

    void initialize() override
    {
        mpP1_c = getSafeNodeDataPtr(mpP1, Spec::waveSlot);
        mpP1_Zc = getSafeNodeDataPtr(mpP1, Spec::impedanceSlot);
        // The history starts as zero samples one step apart, ending now.
        mEffort = {0.0, 0.0, 0.0};
        mFlow = {0.0, 0.0, 0.0};
        mSampleTime = {mTime - 2.0 * mTimestep, mTime - mTimestep, mTime};
    }

    void simulateOneTimestep() override
    {
        const double e2 = *mpEffortIn;
        const double f2 = *mpFlowIn;
        double e = e2;
        double f = f2;
        if (std::fabs(mTd - mTimestep) >= 0.01 * mTimestep) {
            // A new sample is recognised by a changed value of either input.
            if (e2 != mEffort[2] || f2 != mFlow[2]) {
                shiftIn(mEffort, e2);
                shiftIn(mFlow, f2);
                shiftIn(mSampleTime, mTime);
            }
            const double t = mTime - mTd;
            e = interpolate(mEffort, t);
            f = interpolate(mFlow, t);
        }
        *mpP1_c = e + mZc * f;
        *mpP1_Zc = mZc;
    }

private:
    using History = std::array<double, 3>;   // oldest first

    static void shiftIn(History& h, double value)
    {
        h[0] = h[1];
        h[1] = h[2];
        h[2] = value;
    }

    double interpolate(const History& x, double t) const
    {
        const double theta = (t - mSampleTime[1]) / (mSampleTime[2] - mSampleTime[1]);
        if (mInterpolation == 0) return x[1] + (x[2] - x[1]) * theta;
        // The parabola through three samples taken as equally spaced.
        return x[0] * theta * (theta - 1.0) / 2.0 + x[1] * (1.0 - theta * theta) + x[2] * theta * (theta + 1.0) / 2.0;
    }

    Port* mpP1 = nullptr;
    double* mpFlowIn = nullptr;
    double* mpEffortIn = nullptr;
    double* mpP1_c = nullptr;
    double* mpP1_Zc = nullptr;
    double mZc = 0.0;
    double mTd = 0.0;
    int mInterpolation = 0;
    History mEffort{};
    History mFlow{};
    History mSampleTime{};
};

} // namespace tlmhub
