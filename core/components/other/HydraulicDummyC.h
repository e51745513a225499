#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type benchmark load generator: a CPU-burning loop with no physical meaning.
class HydraulicDummyC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpIn = nullptr;
    double* mpP1_c = nullptr;
};

} // namespace tlmhub
