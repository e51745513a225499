#pragma once
#include "core/Component.h"

namespace tlmhub {

// Scope sink: only a connection point for plotted signals; the nodes are logged by the system.
class SignalSink : public ComponentSignal {
public:
    void configure() override;

private:
    Port* mpIn = nullptr;
    Port* mpInRight = nullptr;
    Port* mpInBottom = nullptr;
};

} // namespace tlmhub
