#pragma once
#include "core/Component.h"
#include "core/numerics/Delay.h"
#include <cstddef>

namespace tlmhub {

// Transport delay whose length dT is an input, re-evaluated every step. The buffer
// is rebuilt (keeping old samples) whenever the rounded number of samples changes;
// a delay below half a step means pass-through.
class SignalVariableTimeDelay : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpDT = nullptr;
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    double mMaxMem = 50.0;
    // Two buffers so a rebuild can copy from the old one; mN = 0 means empty.
    Delay mBuf;
    Delay mSpare;
    std::size_t mN = 0;
};

} // namespace tlmhub
