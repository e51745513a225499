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

    // For the transitions: the ActionN places attached to a port (they own a token lock),
    // and locking them all (places of other types count as success; with several ActionN
    // the last attempt decides).
    static void collectAttached(Port* port, std::vector<ActivityDiagramActionN*>& out);
    static bool tryLockAll(const std::vector<ActivityDiagramActionN*>& places);

private:
    double* mpState = nullptr;
    Port* mpPpn1 = nullptr;
    std::vector<double*> mpS;
    std::vector<double*> mpQ;
    bool mLocked = false;
};

} // namespace tlmhub
