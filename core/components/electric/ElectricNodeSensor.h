#pragma once
#include "core/Component.h"

namespace tlmhub {

// Reads all four variables of an electric node (voltage, current, wave variable, impedance).
class ElectricNodeSensor : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpP1_u = nullptr;
    double* mpP1_i = nullptr;
    double* mpP1_c = nullptr;
    double* mpP1_Zc = nullptr;
    double* mpOutU = nullptr;
    double* mpOutI = nullptr;
    double* mpOutC = nullptr;
    double* mpOutZc = nullptr;
};

} // namespace tlmhub
