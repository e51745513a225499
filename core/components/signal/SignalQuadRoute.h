#pragma once
#include "core/Component.h"

namespace tlmhub {

// Selects one of four inputs; the limits are tested in fixed order, not sorted.
class SignalQuadRoute : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn1 = nullptr;
    double* mpIn2 = nullptr;
    double* mpIn3 = nullptr;
    double* mpIn4 = nullptr;
    double* mpRoute = nullptr;
    double* mpOut = nullptr;
    double mLimit12 = 0.5;
    double mLimit23 = 1.5;
    double mLimit34 = 2.5;
};

} // namespace tlmhub
