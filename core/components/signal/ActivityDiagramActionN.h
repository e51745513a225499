#pragma once
#include "core/Component.h"
#include <vector>

namespace tlmhub {

// Activity-diagram action place with any number of connections and a per-step
// token lock (transitions call tryAndLockToken; the lock is cleared at the end of
// each step of this place). C-type.
class ActivityDiagramActionN : public ComponentC {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;
    // True (and locked) if the token was free this step, false if already taken.
    bool tryAndLockToken();

private:
    double* mpState = nullptr;
    Port* mpPpn1 = nullptr;
    std::vector<double*> mpS;
    std::vector<double*> mpQ;
    bool mLocked = false;
};

} // namespace tlmhub
