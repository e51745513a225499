#pragma once
#include "core/Component.h"

namespace tlmhub {

// Activity-diagram action place with two connections: holds a token until a
// transition removes it. C-type; writes State, reads Flow.
class ActivityDiagramAction : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpState = nullptr;
    Port* mpPpn1 = nullptr;
    Port* mpPpn2 = nullptr;
    double* mpS1 = nullptr;
    double* mpQ1 = nullptr;
    double* mpS2 = nullptr;
    double* mpQ2 = nullptr;
    double mStated = 0.0;
};

} // namespace tlmhub
