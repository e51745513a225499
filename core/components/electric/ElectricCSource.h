#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type electric boundary whose wave variable and characteristic impedance are input
// signals: the node then holds u = c + Zc * i.
class ElectricCSource : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpInC = nullptr;
    double* mpInZ = nullptr;
    double* mpP1_c = nullptr;
    double* mpP1_Zc = nullptr;
};

} // namespace tlmhub
