#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type benchmark load generator: a CPU-burning loop with no physical meaning.
class HydraulicDummyQ : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpIn = nullptr;
    double* mpP1_p = nullptr;
};

} // namespace tlmhub
