// modelDescription.xml from a ModelDescription (FMI 2.0, chapter 2.2), co-simulation only.
#include "fmu/ModelDescription.h"

#include "core/Parameter.h"

#include <pugixml.hpp>

#include <set>
#include <sstream>

namespace tlmhub::fmu {
namespace {

void setNumber(pugi::xml_node element, const char* name, double value)
{
    element.append_attribute(name) = formatNumber(value).c_str();
}

void writeVariable(pugi::xml_node list, const ScalarVariable& variable)
{
    pugi::xml_node element = list.append_child("ScalarVariable");
    element.append_attribute("name") = variable.name.c_str();
    element.append_attribute("valueReference") = variable.valueReference;
    if (!variable.description.empty())
        element.append_attribute("description") = variable.description.c_str();
    element.append_attribute("causality") = causalityName(variable.causality);
    element.append_attribute("variability") = variabilityName(variable.variability);
    // The standard's defaults for `initial` fit every variable tlmhub writes: exact for
    // parameters (start given), none for inputs (start given), calculated for outputs and
    // locals without a start. A local or output with a start is exact.
    bool startAllowed = variable.causality != Causality::CalculatedParameter &&
                        variable.causality != Causality::Independent;
    if (variable.start && (variable.causality == Causality::Output || variable.causality == Causality::Local))
        element.append_attribute("initial") = "exact";
    pugi::xml_node type = element.append_child(variableTypeName(variable.type));
    if (variable.type == VariableType::Real && !variable.unit.empty())
        type.append_attribute("unit") = variable.unit.c_str();
    if (!startAllowed)
        return;
    if (variable.type == VariableType::String) {
        if (variable.causality == Causality::Parameter || variable.causality == Causality::Input ||
            !variable.stringStart.empty())
            type.append_attribute("start") = variable.stringStart.c_str();
    } else if (variable.start) {
        if (variable.type == VariableType::Real)
            setNumber(type, "start", *variable.start);
        else if (variable.type == VariableType::Integer)
            type.append_attribute("start") = static_cast<long long>(*variable.start);
        else
            type.append_attribute("start") = *variable.start != 0.0 ? "true" : "false";
    }
}

// tlmhub's power ports (fmu/ModelDescription.h's PowerPort gives the shape).
void writePowerPorts(pugi::xml_node root, const std::vector<PowerPort>& ports)
{
    if (ports.empty())
        return;
    pugi::xml_node tool = root.append_child("VendorAnnotations").append_child("Tool");
    tool.append_attribute("name") = "tlmhub";
    for (const PowerPort& port : ports) {
        pugi::xml_node element = tool.append_child("PowerPort");
        element.append_attribute("name") = port.name.c_str();
        element.append_attribute("nodeType") = port.nodeType.c_str();
        element.append_attribute("kind") = std::string(1, port.kind).c_str();
        for (const auto& [slot, variable] : port.inputs) {
            pugi::xml_node input = element.append_child("Input");
            input.append_attribute("slot") = slot.c_str();
            input.append_attribute("variable") = variable.c_str();
        }
        for (const auto& [slot, variable] : port.outputs) {
            pugi::xml_node output = element.append_child("Output");
            output.append_attribute("slot") = slot.c_str();
            output.append_attribute("variable") = variable.c_str();
        }
    }
}

} // namespace

std::string writeModelDescription(const ModelDescription& description)
{
    pugi::xml_document doc;
    pugi::xml_node declaration = doc.append_child(pugi::node_declaration);
    declaration.append_attribute("version") = "1.0";
    declaration.append_attribute("encoding") = "UTF-8";

    pugi::xml_node root = doc.append_child("fmiModelDescription");
    root.append_attribute("fmiVersion") = description.fmiVersion.c_str();
    root.append_attribute("modelName") = description.modelName.c_str();
    root.append_attribute("guid") = description.guid.c_str();
    if (!description.description.empty())
        root.append_attribute("description") = description.description.c_str();
    if (!description.generationTool.empty())
        root.append_attribute("generationTool") = description.generationTool.c_str();
    root.append_attribute("variableNamingConvention") = "flat";
    root.append_attribute("numberOfEventIndicators") = 0;

    pugi::xml_node cs = root.append_child("CoSimulation");
    cs.append_attribute("modelIdentifier") = description.modelIdentifier.c_str();
    cs.append_attribute("needsExecutionTool") = false;
    cs.append_attribute("canHandleVariableCommunicationStepSize") = description.canHandleVariableCommunicationStepSize;
    cs.append_attribute("canInterpolateInputs") = false;
    cs.append_attribute("maxOutputDerivativeOrder") = 0;
    cs.append_attribute("canRunAsynchronuously") = false;   // the standard's spelling
    cs.append_attribute("canBeInstantiatedOnlyOncePerProcess") = false;
    cs.append_attribute("canNotUseMemoryManagementFunctions") = true;
    cs.append_attribute("canGetAndSetFMUstate") = description.canGetAndSetFMUstate;
    cs.append_attribute("canSerializeFMUstate") = description.canSerializeFMUstate;
    cs.append_attribute("providesDirectionalDerivative") = false;

    // Every unit a variable names is declared (the standard requires it), without conversions.
    std::set<std::string> units;
    for (const ScalarVariable& variable : description.variables)
        if (variable.type == VariableType::Real && !variable.unit.empty())
            units.insert(variable.unit);
    if (!units.empty()) {
        pugi::xml_node definitions = root.append_child("UnitDefinitions");
        for (const std::string& unit : units)
            definitions.append_child("Unit").append_attribute("name") = unit.c_str();
    }

    if (description.startTime || description.stopTime || description.tolerance || description.stepSize) {
        pugi::xml_node experiment = root.append_child("DefaultExperiment");
        if (description.startTime) setNumber(experiment, "startTime", *description.startTime);
        if (description.stopTime) setNumber(experiment, "stopTime", *description.stopTime);
        if (description.tolerance) setNumber(experiment, "tolerance", *description.tolerance);
        if (description.stepSize) setNumber(experiment, "stepSize", *description.stepSize);
    }

    // The schema's order: DefaultExperiment, VendorAnnotations, ModelVariables, ModelStructure.
    writePowerPorts(root, description.powerPorts);

    pugi::xml_node variables = root.append_child("ModelVariables");
    for (const ScalarVariable& variable : description.variables)
        writeVariable(variables, variable);

    // Outputs, and as initial unknowns those outputs whose `initial` is calculated (all
    // without a start); no dependencies attribute: each may depend on every known.
    pugi::xml_node structure = root.append_child("ModelStructure");
    if (!description.outputs.empty()) {
        pugi::xml_node outputs = structure.append_child("Outputs");
        pugi::xml_node initial;
        for (std::size_t index : description.outputs) {
            outputs.append_child("Unknown").append_attribute("index") = index;
            const ScalarVariable& variable = description.variables.at(index - 1);
            if (variable.start)
                continue;
            if (!initial)
                initial = structure.append_child("InitialUnknowns");
            initial.append_child("Unknown").append_attribute("index") = index;
        }
    }

    std::ostringstream out;
    doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
    return out.str();
}

} // namespace tlmhub::fmu
