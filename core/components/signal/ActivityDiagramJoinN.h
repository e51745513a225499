#pragma once
#include "core/Component.h"
#include <vector>

namespace tlmhub {

// Activity-diagram join of any number of places on the multiport Ppn1 into Ppn2;
// fires when all incoming places are marked and Ppn2 is empty. Q-type.
class ActivityDiagramJoinN : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPpn1 = nullptr;
    Port* mpPpn2 = nullptr;
    std::vector<double*> mpS;
    std::vector<double*> mpQ;
    double* mpS2 = nullptr;
    double* mpQ2 = nullptr;
};

} // namespace tlmhub
