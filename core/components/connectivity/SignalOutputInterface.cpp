#include "core/components/connectivity/SignalOutputInterface.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalOutputInterface::configure()
{
    addInputVariable("in", "Value to outside the model", "", 0.0, &mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalOutputInterface, "Connectivity")

} // namespace tlmhub
