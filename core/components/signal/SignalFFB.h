#pragma once
#include "core/Component.h"

namespace tlmhub {

// Functional flow block: set by a rising edge of `set`, reset by exit/exitb/leave,
// signals a completed exit. exitb enters as a level, not an edge (reference quirk).
class SignalFFB : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpSet = nullptr;
    double* mpExit = nullptr;
    double* mpExitb = nullptr;
    double* mpLeave = nullptr;
    double* mpState = nullptr;
    double* mpExiting = nullptr;
    double* mpExitingb = nullptr;
    double mOldState = 0.0, mOldSet = 0.0, mOldExit = 0.0, mOldLeave = 0.0;
};

} // namespace tlmhub
