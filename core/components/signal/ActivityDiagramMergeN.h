#pragma once
#include "core/Component.h"
#include <vector>

namespace tlmhub {

// Activity-diagram merge of any number of places on the multiport Ppn1 (first
// connection has priority) into Ppn2. Q-type.
class ActivityDiagramMergeN : public ComponentQ {
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
