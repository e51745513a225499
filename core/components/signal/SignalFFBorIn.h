#pragma once
#include "core/Component.h"

namespace tlmhub {

// FFB OR-split entry: same model as SignalFFBloop.
class SignalFFBorIn : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn0 = nullptr;
    double* mpDivert = nullptr;
    double* mpState = nullptr;
    double* mpOut0 = nullptr;
    double* mpOut1 = nullptr;
    double mOldState = 0.0, mOldIn0 = 0.0, mOldOut0 = 0.0, mOldOut1 = 0.0;
};

} // namespace tlmhub
