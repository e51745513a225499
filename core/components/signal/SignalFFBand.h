#pragma once
#include "core/Component.h"

namespace tlmhub {

// FFB AND-join: activated when either branch fires; exits when both branches were
// active in the previous step.
class SignalFFBand : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn0 = nullptr;
    double* mpIn1 = nullptr;
    double* mpState = nullptr;
    double* mpExiting = nullptr;
    double mOldIn0 = 0.0, mOldIn1 = 0.0, mOldExiting = 0.0;
    double mOldState0 = 0.0, mOldState1 = 0.0;
};

} // namespace tlmhub
