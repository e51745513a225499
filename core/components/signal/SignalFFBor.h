#pragma once
#include "core/Component.h"

namespace tlmhub {

// FFB OR-join: same logic as SignalFFBloopIn; exitingb0/exitingb1 are never
// computed and keep their start values (reference behaviour).
class SignalFFBor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn0 = nullptr;
    double* mpIn1 = nullptr;
    double* mpState = nullptr;
    double* mpExiting = nullptr;
    double* mpExitingb0 = nullptr;
    double* mpExitingb1 = nullptr;
    double mOldIn0 = 0.0, mOldIn1 = 0.0, mOldExiting = 0.0;
    double mOldState0 = 0.0, mOldState1 = 0.0;
    double mExitingb0 = 0.0, mExitingb1 = 0.0;
};

} // namespace tlmhub
