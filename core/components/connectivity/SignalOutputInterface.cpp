#include "core/components/connectivity/SignalOutputInterface.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalOutputInterface::configure()
{
    addInputVariable("in", "Value to outside the model", "", 0.0, &mpIn);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"in"}, false);
}

TLMHUB_REGISTER_COMPONENT(SignalOutputInterface, "Connectivity")

} // namespace tlmhub
