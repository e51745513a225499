#pragma once
#include "core/Component.h"

#include <vector>

namespace tlmhub {

// C-type pressure source on a multiport; every connection sees the set pressure
// with zero impedance.
class HydraulicMultiPressureSourceC : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpMP = nullptr;
    double* mpIn = nullptr;
    std::size_t mNumPorts = 0;
    std::vector<double*> mvpMP_c, mvpMP_Zc;
};

} // namespace tlmhub
