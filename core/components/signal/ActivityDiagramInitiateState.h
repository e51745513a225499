#pragma once
#include "core/Component.h"

namespace tlmhub {

// Activity-diagram initial node: injects a token into Ppn1 on a (by default
// rising) event; with the defaults this happens during initialisation. Q-type.
class ActivityDiagramInitiateState : public ComponentQ {
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
