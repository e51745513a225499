#pragma once
#include "core/Component.h"

#include <vector>

namespace tlmhub {

// C-type ideal voltage source on a multiport: every connection sees c = U, Zc = 0.
class ElectricVoltageSourceMultiPortC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpU = nullptr;
    std::vector<double*> mvpC, mvpZc;
};

} // namespace tlmhub
