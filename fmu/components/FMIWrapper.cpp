// FMIWrapper: an imported FMI 2.0 co-simulation FMU (fmu/FmuWrapper.h). A signal component
// for an FMU of real inputs and outputs only; a C-type one for an FMU whose power ports are
// of kind Q (the FMU takes effort and flow and gives the wave variable and impedance, so
// this side plays the capacitance). FMUs with kind C power ports go into FMIWrapperQ.
#include "core/ComponentFactory.h"
#include "fmu/FmuWrapper.h"

namespace tlmhub::fmu {

class FMIWrapper : public FmuWrapper {
public:
    FMIWrapper() : FmuWrapper(CqsKind::S, 'Q', "FMIWrapperQ") {}
    CqsKind kind() const override { return hasPowerPorts() ? CqsKind::C : CqsKind::S; }
};

TLMHUB_REGISTER_COMPONENT(FMIWrapper, "Connectivity")

} // namespace tlmhub::fmu
