#pragma once
#include "core/Component.h"
#include <vector>

namespace tlmhub {

// Activity-diagram final place with any number of incoming connections; same
// equations as ActivityDiagramActionN without token locking. C-type.
class ActivityDiagramFinalNode : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpState = nullptr;
    Port* mpPpn1 = nullptr;
    std::vector<double*> mpS;
    std::vector<double*> mpQ;
};

} // namespace tlmhub
