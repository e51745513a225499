#pragma once
#include "core/Component.h"

namespace tlmhub {

// Activity-diagram pass-through place with two connections and no output. C-type.
class ActivityDiagramConnector : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    Port* mpPpn1 = nullptr;
    Port* mpPpn2 = nullptr;
    double* mpS1 = nullptr;
    double* mpQ1 = nullptr;
    double* mpS2 = nullptr;
    double* mpQ2 = nullptr;
    double mStated = 0.0;
};

} // namespace tlmhub
