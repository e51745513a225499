#pragma once
#include "core/Component.h"

namespace tlmhub {

// Activity-diagram final (sink) transition: removes the token from Ppn1 on an event. Q-type.
class ActivityDiagramFinal : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpEvent = nullptr;
    double* mpDiffEvent = nullptr;
    Port* mpPpn1 = nullptr;
    double* mpS1 = nullptr;
    double* mpQ1 = nullptr;
    double mOldEvent = 0.0;
};

} // namespace tlmhub
