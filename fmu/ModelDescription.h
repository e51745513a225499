#pragma once
// What an FMI 2.0 co-simulation FMU's modelDescription.xml says, as far as tlmhub writes
// (fmu/ModelDescriptionWriter.cpp) and reads (fmu/ModelDescriptionParser.cpp) it.
#include "core/Status.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tlmhub::fmu {

enum class Causality { Parameter, CalculatedParameter, Input, Output, Local, Independent };
enum class Variability { Constant, Fixed, Tunable, Discrete, Continuous };
enum class VariableType { Real, Integer, Boolean, String };

const char* causalityName(Causality causality);        // "parameter", ... as the standard spells it
const char* variabilityName(Variability variability);  // "fixed", ...
const char* variableTypeName(VariableType type);       // "Real", ...

struct ScalarVariable {
    std::string name;
    std::uint32_t valueReference = 0;
    Causality causality = Causality::Local;
    Variability variability = Variability::Continuous;
    VariableType type = VariableType::Real;
    std::string description;
    std::string unit;
    std::optional<double> start;   // Real, Integer and Boolean starts as a number
    std::string stringStart;       // a String variable's start
};

// A power port of the FMU, carried as TLM variables (tlmhub's vendor annotation, written
// and read by tlmhub only; other tools see plain real inputs and outputs):
//  kind 'C': the FMU takes the wave variable and characteristic impedance and gives back
//            effort and flow (inside it, a Q-type component meets a ...InterfaceC);
//  kind 'Q': the FMU takes effort and flow and gives back the wave variable and impedance.
// In modelDescription.xml, after DefaultExperiment (as the schema orders it):
//   <VendorAnnotations><Tool name="tlmhub">
//     <PowerPort name="P1" nodeType="NodeHydraulic" kind="C">
//       <Input slot="c" variable="P1.c"/><Input slot="Zc" variable="P1.Zc"/>
//       <Output slot="q" variable="P1.q"/><Output slot="p" variable="P1.p"/> ...
//     </PowerPort> ...
//   </Tool></VendorAnnotations>
// `slot` is the node variable's short name (core/NodeTypes.cpp), `variable` a ScalarVariable's
// name; inputs and outputs each in node slot order.
struct PowerPort {
    std::string name;       // the interface component's name in the exported model
    std::string nodeType;   // "NodeHydraulic"
    char kind = 'C';
    // (node variable short name, FMU variable name), e.g. ("c", "P1.c")
    std::vector<std::pair<std::string, std::string>> inputs;
    std::vector<std::pair<std::string, std::string>> outputs;
};

struct ModelDescription {
    std::string fmiVersion = "2.0";
    std::string modelName;
    std::string modelIdentifier;   // binaries/linux64/<modelIdentifier>.so
    std::string guid;
    std::string description;
    std::string generationTool;
    bool canHandleVariableCommunicationStepSize = true;
    bool canGetAndSetFMUstate = false;
    bool canSerializeFMUstate = false;
    std::optional<double> startTime, stopTime, tolerance, stepSize;   // DefaultExperiment
    std::vector<ScalarVariable> variables;
    // ModelStructure/Outputs: 1-based indices into `variables`, as the standard counts.
    std::vector<std::size_t> outputs;
    std::vector<PowerPort> powerPorts;
};

std::string writeModelDescription(const ModelDescription& description);
// Refuses (InvalidModel, naming what is wrong) text that is not an FMI 2.0 co-simulation
// description: missing attributes, duplicate value references or names, illegal
// causality/variability pairs, outputs that are not output variables.
Result<ModelDescription> parseModelDescription(std::string_view xml);

} // namespace tlmhub::fmu
