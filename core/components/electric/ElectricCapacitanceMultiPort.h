#pragma once
#include "core/Component.h"

#include <vector>

namespace tlmhub {

// C-type capacitance to ground on a multiport, TLM with low-pass filtering.
class ElectricCapacitanceMultiPort : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPel1 = nullptr;
    double mCapacitance = 1.0e-4;
    double* mpAlpha = nullptr;
    double mZc = 0.0;
    std::size_t mN = 0;
    std::vector<double*> mvpI, mvpC, mvpZc;
    std::vector<double> mvC0;
};

} // namespace tlmhub
