// Fuzzes the FMU modelDescription.xml parser: every description it accepts must hold what
// the importer relies on (outputs index output variables, power ports name known real
// variables), and every refusal is an invalid model with a message.
#include "fmu/ModelDescription.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace tlmhub::fmu;
    const tlmhub::Result<ModelDescription> parsed =
        parseModelDescription(std::string_view(reinterpret_cast<const char*>(data), size));
    if (!parsed) {
        if (parsed.status().code() != tlmhub::StatusCode::InvalidModel || parsed.status().message().empty())
            std::abort();
        return 0;
    }
    for (std::size_t index : parsed->outputs)
        if (index == 0 || index > parsed->variables.size() ||
            parsed->variables[index - 1].causality != Causality::Output)
            std::abort();
    for (const PowerPort& port : parsed->powerPorts)
        for (const auto* slots : {&port.inputs, &port.outputs})
            for (const auto& [slot, name] : *slots) {
                bool found = false;
                for (const ScalarVariable& v : parsed->variables) found |= v.name == name && v.type == VariableType::Real;
                if (!found) std::abort();
            }
    return 0;
}
