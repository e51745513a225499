#pragma once
#include "core/Component.h"
#include <vector>

namespace tlmhub {

// Activity-diagram fork from the place on Ppn2 into any number of places on the
// multiport Ppn1. Q-type.
class ActivityDiagramForkN : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpEvent = nullptr;
    double* mpDiffevent = nullptr;
    double* mpState = nullptr;
    Port* mpPpn1 = nullptr;
    Port* mpPpn2 = nullptr;
    std::vector<double*> mpS;
    std::vector<double*> mpQ;
    double* mpS2 = nullptr;
    double* mpQ2 = nullptr;
    double mOldEvent = 0.0;
};

} // namespace tlmhub
