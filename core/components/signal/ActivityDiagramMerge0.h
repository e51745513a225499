#pragma once
#include "core/Component.h"

namespace tlmhub {

// Activity-diagram unconditional merge of Ppn1/Ppn2 into Ppn3. Q-type.
class ActivityDiagramMerge0 : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPpn1 = nullptr;
    Port* mpPpn2 = nullptr;
    Port* mpPpn3 = nullptr;
    double* mpS1 = nullptr;
    double* mpQ1 = nullptr;
    double* mpS2 = nullptr;
    double* mpQ2 = nullptr;
    double* mpS3 = nullptr;
    double* mpQ3 = nullptr;
};

} // namespace tlmhub
