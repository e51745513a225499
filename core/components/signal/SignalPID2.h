#pragma once
#include "core/Component.h"

namespace tlmhub {

// Discrete PID on an error signal with back-calculation anti-windup (Tt) and a
// separate output clamp. de is only used when it is connected.
class SignalPID2 : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpE = nullptr;
    double* mpDe = nullptr;
    double* mpU = nullptr;
    double mK = 1.0;
    double mTi = 1.0;
    double mTt = 1.0;
    double mTd = 0.0;
    double mUmin = -1e+100;
    double mUmax = 1e+100;
    double mUoutmin = -1e+100;
    double mUoutmax = 1e+100;
    Port* mpDePort = nullptr;
    double mI = 0.0;
    double mEprev = 0.0;
    bool mUseDe = false;
};

} // namespace tlmhub
