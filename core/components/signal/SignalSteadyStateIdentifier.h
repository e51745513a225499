#pragma once
#include "core/Component.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tlmhub {

// Flags (1/0) whether the input is at steady state, by a sliding-window range test (0),
// a windowed variance ratio test on noisy samples (1) or an exponentially weighted
// R-test (2). Methods 1 and 2 add artificial white noise from the shared rand() stream.
class SignalSteadyStateIdentifier : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    RandomStream* mpRandom = nullptr;
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double* mpTol = nullptr;
    double* mpWl = nullptr;
    double* mpSd = nullptr;
    double* mpL1 = nullptr;
    double* mpL2 = nullptr;
    double* mpL3 = nullptr;
    int mMethod = 0;

    std::vector<double> mWindow;  // circular window of the last N inputs
    std::vector<double> mNoisy;   // window plus noise (method 1), preallocated
    std::size_t mN = 0;
    std::size_t mK = 0;           // next write index = oldest entry
    double mXd = 0.0;             // method 2 delayed states
    double mXfd = 0.0;
    double mDfd = 0.0;
};

} // namespace tlmhub
