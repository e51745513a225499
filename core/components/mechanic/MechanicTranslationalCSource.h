#pragma once
#include "core/Component.h"

namespace tlmhub {

// C-type source writing a signal-given wave variable and impedance to its port.
class MechanicTranslationalCSource : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpP1 = nullptr;
    double *mpInC = nullptr, *mpInZ = nullptr;
    double *mpP1_c = nullptr, *mpP1_Zc = nullptr;
};

} // namespace tlmhub
