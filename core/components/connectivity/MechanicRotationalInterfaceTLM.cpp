#include "core/ComponentFactory.h"
#include "core/components/connectivity/TlmInterface.h"

namespace tlmhub {

struct MechanicRotationalInterfaceTLMSpec {
    static constexpr NodeType node = NodeType::MechanicRotational;
    static constexpr int waveSlot = NodeMechanicRotational::WaveVariable;
    static constexpr int impedanceSlot = NodeMechanicRotational::CharImpedance;
    static constexpr const char* flowName = "w2";
    static constexpr const char* flowDescription = "Received (delayed) angular velocity";
    static constexpr const char* flowUnit = "rad/s";
    static constexpr const char* effortName = "t2";
    static constexpr const char* effortDescription = "Received (delayed) torque";
    static constexpr const char* effortUnit = "Nm";
    static constexpr const char* impedanceUnit = "Nm s/rad";
};

using MechanicRotationalInterfaceTLM = TlmInterface<MechanicRotationalInterfaceTLMSpec>;

TLMHUB_REGISTER_COMPONENT(MechanicRotationalInterfaceTLM, "Connectivity")

} // namespace tlmhub
