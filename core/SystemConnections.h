#pragma once
// The connections made in one system, each once, in a stable order: the order a model file
// lists them in. Saving and copying a model both walk them this way, so a copy connects its
// multiports' sub-ports in the order a saved and reloaded model would.
#include "core/System.h"

#include <functional>
#include <map>
#include <string>

namespace tlmhub {

struct SystemConnection {
    // The ends as the model names them: a multiport, not its sub-port; a system port of
    // this system by its own name as both component and port. Oriented as the model file
    // that was loaded listed the connection, so its extras (the line's points) still run
    // from start to end.
    std::string startComponent, startPort, endComponent, endPort;
    // The connection's layout and preserved model-file content; null if it has none.
    const ConnectionExtras* extras = nullptr;
};

void forEachConnection(const System& system, const std::function<void(const SystemConnection&)>& visit);

} // namespace tlmhub
