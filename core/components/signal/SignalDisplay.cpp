#include "core/components/signal/SignalDisplay.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void SignalDisplay::configure()
{
    addInputVariable("in", "Input signal", "", 0.0, &mpIn);
    addConstant("description", "Text shown with the value", std::string(""), mDescription, ParameterType::String);
    addConstant("unit", "Unit shown with the value", std::string(""), mUnit, ParameterType::String);
    addConstant("unitscaling", "Display scale factor", "", 1.0, mUnitscaling);
    addConstant("precision", "Number of displayed digits", "", 8, mPrecision);
    addConstant("backgroundcolor", "Background colour (R,G,B)", std::string("255,255,255"), mBackgroundcolor, ParameterType::String);
    addConstant("textcolor", "Text colour (R,G,B)", std::string("0,50,80"), mTextcolor, ParameterType::String);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"in"}, false);
}

void SignalDisplay::initialize()
{
    // Nothing to set up.
}

void SignalDisplay::simulateOneTimestep()
{
    // Nothing to compute in a batch simulation.
}

TLMHUB_REGISTER_COMPONENT(SignalDisplay, "Signal")

} // namespace tlmhub
