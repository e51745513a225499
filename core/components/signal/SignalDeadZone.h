#pragma once
#include "core/Component.h"

namespace tlmhub {

// Dead zone: 0 strictly inside (u_dstart, u_dend), input minus the edge outside.
// An input equal to u_dstart takes the last branch (reference quirk).
class SignalDeadZone : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpU_dstart = nullptr;
    double* mpU_dend = nullptr;
    double* mpOut = nullptr;
};

} // namespace tlmhub
