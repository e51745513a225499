#pragma once
#include "core/Component.h"

namespace tlmhub {

// Q-type electric boundary that imposes both node variables from input signals: voltage
// and current are written as given, whatever the C side's wave says.
class ElectricQSource : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double* mpInU = nullptr;
    double* mpInI = nullptr;
    double* mpP1_u = nullptr;
    double* mpP1_i = nullptr;
};

} // namespace tlmhub
