// Reads an FMI 2.0 co-simulation modelDescription.xml. The text comes from an FMU a user
// names, so it is treated as hostile: bounded in size and count, and every reference in it
// (value references, output indices, the power ports' variables) checked before use.
#include "fmu/ModelDescription.h"

#include "core/NodeTypes.h"

#include <pugixml.hpp>

#include <charconv>
#include <cmath>
#include <map>
#include <set>

namespace tlmhub::fmu {

namespace {

constexpr std::size_t kMaxDescriptionBytes = 16u << 20;
constexpr std::size_t kMaxVariables = 100000;
constexpr std::size_t kMaxPowerPorts = 1000;

Status invalid(const std::string& message)
{
    return {StatusCode::InvalidModel, "modelDescription.xml: " + message};
}

std::optional<double> parseReal(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '+')) text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || std::isnan(value))
        return std::nullopt;
    return value;
}

std::optional<std::uint32_t> parseValueReference(std::string_view text)
{
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

// The model identifier names the shared library inside the archive: a C identifier only.
bool isIdentifier(std::string_view text)
{
    if (text.empty() || text.size() > 200) return false;
    if (text.front() >= '0' && text.front() <= '9') return false;
    for (char c : text)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
    return true;
}

std::optional<Causality> parseCausality(std::string_view text)
{
    if (text.empty() || text == "local") return Causality::Local;
    if (text == "parameter") return Causality::Parameter;
    if (text == "calculatedParameter") return Causality::CalculatedParameter;
    if (text == "input") return Causality::Input;
    if (text == "output") return Causality::Output;
    if (text == "independent") return Causality::Independent;
    return std::nullopt;
}

std::optional<Variability> parseVariability(std::string_view text)
{
    if (text.empty() || text == "continuous") return Variability::Continuous;
    if (text == "constant") return Variability::Constant;
    if (text == "fixed") return Variability::Fixed;
    if (text == "tunable") return Variability::Tunable;
    if (text == "discrete") return Variability::Discrete;
    return std::nullopt;
}

// FMI 2.0 section 2.2.7: the combinations of causality and variability the standard allows.
bool isLegalCombination(Causality causality, Variability variability)
{
    switch (variability) {
    case Variability::Constant:
        return causality == Causality::Output || causality == Causality::Local;
    case Variability::Fixed:
    case Variability::Tunable:
        return causality == Causality::Parameter || causality == Causality::CalculatedParameter ||
               causality == Causality::Local;
    case Variability::Discrete:
        return causality == Causality::Input || causality == Causality::Output || causality == Causality::Local;
    case Variability::Continuous:
        return causality == Causality::Input || causality == Causality::Output || causality == Causality::Local ||
               causality == Causality::Independent;
    }
    return false;
}

Result<ScalarVariable> parseVariable(pugi::xml_node node, std::size_t index)
{
    const std::string where = "ScalarVariable " + std::to_string(index);
    ScalarVariable variable;
    variable.name = node.attribute("name").as_string();
    if (variable.name.empty()) return invalid(where + " has no name");
    const std::string named = where + " '" + variable.name + "'";
    const auto reference = parseValueReference(node.attribute("valueReference").as_string());
    if (!reference) return invalid(named + " has no valid valueReference");
    variable.valueReference = *reference;
    const auto causality = parseCausality(node.attribute("causality").as_string());
    if (!causality) return invalid(named + " has an unknown causality");
    const auto variability = parseVariability(node.attribute("variability").as_string());
    if (!variability) return invalid(named + " has an unknown variability");
    variable.causality = *causality;
    variable.variability = *variability;
    if (!isLegalCombination(variable.causality, variable.variability))
        return invalid(named + ": causality '" + causalityName(variable.causality) + "' with variability '" +
                       variabilityName(variable.variability) + "' is not allowed by FMI 2.0");
    variable.description = node.attribute("description").as_string();

    pugi::xml_node typeNode;
    for (pugi::xml_node child : node.children()) {
        if (child.type() != pugi::node_element) continue;
        const std::string_view tag = child.name();
        if (tag != "Real" && tag != "Integer" && tag != "Boolean" && tag != "String" && tag != "Enumeration")
            continue;
        if (typeNode) return invalid(named + " has more than one type element");
        typeNode = child;
    }
    if (!typeNode) return invalid(named + " has no type element (Real, Integer, Boolean, String, Enumeration)");
    const std::string_view tag = typeNode.name();
    // An enumeration's values travel as integers.
    variable.type = tag == "Real"      ? VariableType::Real
                    : tag == "Boolean" ? VariableType::Boolean
                    : tag == "String"  ? VariableType::String
                                       : VariableType::Integer;
    if (variable.type != VariableType::Real && variable.variability == Variability::Continuous)
        return invalid(named + ": only Real variables may be continuous (give a variability)");
    if (variable.causality == Causality::Independent && variable.type != VariableType::Real)
        return invalid(named + ": the independent variable must be Real");
    variable.unit = typeNode.attribute("unit").as_string();

    if (pugi::xml_attribute start = typeNode.attribute("start")) {
        const std::string_view text = start.as_string();
        if (variable.type == VariableType::String) {
            variable.stringStart = text;
        } else if (variable.type == VariableType::Boolean) {
            if (text == "true" || text == "1") variable.start = 1.0;
            else if (text == "false" || text == "0") variable.start = 0.0;
            else return invalid(named + " has a Boolean start that is not true or false");
        } else {
            variable.start = parseReal(text);
            if (!variable.start) return invalid(named + " has a start that is not a number");
        }
    }
    return variable;
}

Status parseVariables(pugi::xml_node root, ModelDescription& out)
{
    std::set<std::string> names;
    std::map<VariableType, std::set<std::uint32_t>> references;
    std::size_t index = 0;
    for (pugi::xml_node node : root.child("ModelVariables").children("ScalarVariable")) {
        if (++index > kMaxVariables)
            return invalid("more than " + std::to_string(kMaxVariables) + " variables");
        Result<ScalarVariable> variable = parseVariable(node, index);
        if (!variable) return variable.status();
        if (!names.insert(variable->name).second) return invalid("two variables are named '" + variable->name + "'");
        if (!references[variable->type].insert(variable->valueReference).second)
            return invalid("variable '" + variable->name + "': value reference " +
                           std::to_string(variable->valueReference) + " is used twice for " +
                           variableTypeName(variable->type) + " variables");
        out.variables.push_back(std::move(*variable));
    }
    return Status::ok();
}

Status parseOutputs(pugi::xml_node root, ModelDescription& out)
{
    std::set<std::size_t> seen;
    for (pugi::xml_node unknown : root.child("ModelStructure").child("Outputs").children("Unknown")) {
        const auto index = parseValueReference(unknown.attribute("index").as_string());
        if (!index || *index == 0 || *index > out.variables.size())
            return invalid("ModelStructure/Outputs: index '" + std::string(unknown.attribute("index").as_string()) +
                           "' is not a variable's index (1 to " + std::to_string(out.variables.size()) + ")");
        const ScalarVariable& variable = out.variables[*index - 1];
        if (variable.causality != Causality::Output)
            return invalid("ModelStructure/Outputs: index " + std::to_string(*index) + " ('" + variable.name +
                           "') is not an output");
        if (!seen.insert(*index).second)
            return invalid("ModelStructure/Outputs: index " + std::to_string(*index) + " is listed twice");
        out.outputs.push_back(*index);
    }
    return Status::ok();
}

// tlmhub's own annotation: which real inputs and outputs together form a power port.
Status parsePowerPorts(pugi::xml_node root, ModelDescription& out)
{
    std::map<std::string, const ScalarVariable*> byName;
    for (const ScalarVariable& v : out.variables) byName[v.name] = &v;
    std::set<std::string> portNames;
    std::set<std::string> usedVariables;
    for (pugi::xml_node tool : root.child("VendorAnnotations").children("Tool")) {
        if (std::string_view(tool.attribute("name").as_string()) != "tlmhub") continue;
        for (pugi::xml_node node : tool.children("PowerPort")) {
            if (out.powerPorts.size() >= kMaxPowerPorts)
                return invalid("more than " + std::to_string(kMaxPowerPorts) + " power ports");
            PowerPort port;
            port.name = node.attribute("name").as_string();
            if (port.name.empty()) return invalid("a PowerPort has no name");
            const std::string where = "PowerPort '" + port.name + "'";
            if (!portNames.insert(port.name).second) return invalid("two power ports are named '" + port.name + "'");
            port.nodeType = node.attribute("nodeType").as_string();
            NodeType type;
            if (!nodeTypeFromName(port.nodeType, type) || type == NodeType::Signal || type == NodeType::Empty)
                return invalid(where + ": unknown power node type '" + port.nodeType + "'");
            const std::string_view kind = node.attribute("kind").as_string();
            if (kind != "C" && kind != "Q") return invalid(where + ": kind must be C or Q");
            port.kind = kind.front();
            for (pugi::xml_node child : node.children()) {
                if (child.type() != pugi::node_element) continue;
                const std::string_view tag = child.name();
                const bool isInput = tag == "Input";
                if (!isInput && tag != "Output") return invalid(where + ": unknown element <" + std::string(tag) + ">");
                const std::string slot = child.attribute("slot").as_string();
                const std::string variable = child.attribute("variable").as_string();
                bool known = false;
                for (const NodeVariableInfo& info : nodeTypeInfo(type).variables) known |= info.shortName == slot;
                if (!known) return invalid(where + ": '" + slot + "' is not a variable of " + port.nodeType);
                const auto found = byName.find(variable);
                if (found == byName.end()) return invalid(where + ": no variable named '" + variable + "'");
                const ScalarVariable& v = *found->second;
                const Causality wanted = isInput ? Causality::Input : Causality::Output;
                if (v.type != VariableType::Real || v.causality != wanted)
                    return invalid(where + ": variable '" + variable + "' is not a real " +
                                   causalityName(wanted));
                if (!usedVariables.insert(variable).second)
                    return invalid(where + ": variable '" + variable + "' belongs to two power port slots");
                (isInput ? port.inputs : port.outputs).emplace_back(slot, variable);
            }
            if (port.inputs.empty() || port.outputs.empty())
                return invalid(where + " needs inputs and outputs");
            out.powerPorts.push_back(std::move(port));
        }
    }
    return Status::ok();
}

bool parseBool(pugi::xml_attribute attribute, bool fallback)
{
    if (!attribute) return fallback;
    const std::string_view text = attribute.as_string();
    return text == "true" || text == "1";
}

} // namespace

Result<ModelDescription> parseModelDescription(std::string_view xml)
{
    if (xml.size() > kMaxDescriptionBytes)
        return invalid("larger than " + std::to_string(kMaxDescriptionBytes >> 20) + " MiB");
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(xml.data(), xml.size(), pugi::parse_default);
    if (!parsed) return invalid(std::string("not XML: ") + parsed.description());
    const pugi::xml_node root = doc.child("fmiModelDescription");
    if (!root) return invalid("the root element is not <fmiModelDescription>");

    ModelDescription out;
    out.fmiVersion = root.attribute("fmiVersion").as_string();
    if (out.fmiVersion != "2.0" && out.fmiVersion.rfind("2.0.", 0) != 0)
        return invalid("fmiVersion is '" + out.fmiVersion + "', not 2.0");
    out.modelName = root.attribute("modelName").as_string();
    out.guid = root.attribute("guid").as_string();
    if (out.modelName.empty()) return invalid("no modelName");
    if (out.guid.empty()) return invalid("no guid");
    out.description = root.attribute("description").as_string();
    out.generationTool = root.attribute("generationTool").as_string();

    const pugi::xml_node cosim = root.child("CoSimulation");
    if (!cosim) return invalid("no <CoSimulation> element (not a co-simulation FMU)");
    out.modelIdentifier = cosim.attribute("modelIdentifier").as_string();
    if (!isIdentifier(out.modelIdentifier))
        return invalid("CoSimulation modelIdentifier '" + out.modelIdentifier + "' is not a C identifier");
    out.canHandleVariableCommunicationStepSize =
        parseBool(cosim.attribute("canHandleVariableCommunicationStepSize"), false);
    out.canGetAndSetFMUstate = parseBool(cosim.attribute("canGetAndSetFMUstate"), false);
    out.canSerializeFMUstate = parseBool(cosim.attribute("canSerializeFMUstate"), false);

    if (const pugi::xml_node experiment = root.child("DefaultExperiment")) {
        const auto optionalReal = [&](const char* name, std::optional<double>& target) -> Status {
            const pugi::xml_attribute attribute = experiment.attribute(name);
            if (!attribute) return Status::ok();
            target = parseReal(attribute.as_string());
            if (!target) return invalid(std::string("DefaultExperiment ") + name + " is not a number");
            return Status::ok();
        };
        for (const auto& [name, target] : {std::pair<const char*, std::optional<double>*>{"startTime", &out.startTime},
                                           {"stopTime", &out.stopTime},
                                           {"tolerance", &out.tolerance},
                                           {"stepSize", &out.stepSize}})
            if (Status read = optionalReal(name, *target); !read) return read;
    }

    if (Status read = parseVariables(root, out); !read) return read;
    if (Status read = parseOutputs(root, out); !read) return read;
    if (Status read = parsePowerPorts(root, out); !read) return read;
    return out;
}

} // namespace tlmhub::fmu
