#include "core/components/signal/SignalSink.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalSink::configure()
{
    mpIn = addReadMultiPort("in", NodeType::Signal, false);
    mpInRight = addReadMultiPort("in_right", NodeType::Signal, false);
    // A plain read port gets its start value parameter in_bottom#Value (default 0) from the core.
    mpInBottom = addReadPort("in_bottom", NodeType::Signal, false);
}

TLMHUB_REGISTER_COMPONENT(SignalSink, "Signal")

} // namespace tlmhub
