#include "core/ComponentFactory.h"
#include "core/components/connectivity/TlmInterface.h"

namespace tlmhub {

struct MechanicInterfaceTLMSpec {
    static constexpr NodeType node = NodeType::Mechanic;
    static constexpr int waveSlot = NodeMechanic::WaveVariable;
    static constexpr int impedanceSlot = NodeMechanic::CharImpedance;
    static constexpr const char* flowName = "v2";
    static constexpr const char* flowDescription = "Received (delayed) velocity";
    static constexpr const char* flowUnit = "m/s";
    static constexpr const char* effortName = "f2";
    static constexpr const char* effortDescription = "Received (delayed) force";
    static constexpr const char* effortUnit = "N";
    static constexpr const char* impedanceUnit = "N s/m";
};

using MechanicInterfaceTLM = TlmInterface<MechanicInterfaceTLMSpec>;

TLMHUB_REGISTER_COMPONENT(MechanicInterfaceTLM, "Connectivity")

} // namespace tlmhub
