#include "fmu/ModelInterface.h"

#include "core/NodeTypes.h"
#include "core/Node.h"
#include "core/ParameterPath.h"
#include "core/Port.h"
#include "core/Simulation.h"

#include <cctype>
#include <cstdlib>
#include <set>

namespace tlmhub::fmu {
namespace {

constexpr const char* kTimestepName = "tlmhub.timestep";

bool endsWith(const std::string& text, const std::string& suffix)
{
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A C identifier from a model name: other bytes become '_', a leading digit gets a '_'.
std::string cIdentifier(const std::string& name)
{
    std::string id;
    for (char ch : name)
        id += std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' ? ch : '_';
    if (id.empty())
        id = "model";
    if (std::isdigit(static_cast<unsigned char>(id.front())))
        id.insert(id.begin(), '_');
    return id;
}

bool isCIdentifier(const std::string& id)
{
    return !id.empty() && cIdentifier(id) == id;
}

// A parameter's value string as a number: FMU parameters carry their start as a number, so
// an expression ("2*a") is refused rather than guessed.
std::optional<double> numberOf(const std::string& text)
{
    const char* begin = text.c_str();
    char* end = nullptr;
    double value = std::strtod(begin, &end);
    if (end == begin)
        return std::nullopt;
    while (*end != '\0' && std::isspace(static_cast<unsigned char>(*end)))
        ++end;
    if (*end != '\0')
        return std::nullopt;
    return value;
}

class InterfaceBuilder {
public:
    Status addSignal(const Component& component, const char* portName, Causality causality);
    Status addPowerPort(const Component& component, char kind);
    Status addParameter(const std::string& path, const Parameter& parameter);
    Status addTimestep(double timestep);
    Result<ModelInterface> finish(ModelDescription description);

private:
    struct Entry {
        ScalarVariable variable;
        VariableBinding binding;
    };
    Status add(std::vector<Entry>& list, Entry entry);

    std::vector<Entry> mInputs, mOutputs, mParameters;
    std::vector<PowerPort> mPowerPorts;
    std::set<std::string> mNames;
};

Status InterfaceBuilder::add(std::vector<Entry>& list, Entry entry)
{
    if (!mNames.insert(entry.variable.name).second)
        return {StatusCode::InvalidModel, "two FMU variables would be named '" + entry.variable.name + "'"};
    list.push_back(std::move(entry));
    return Status::ok();
}

Status InterfaceBuilder::addSignal(const Component& component, const char* portName, Causality causality)
{
    const Port* port = component.port(portName);
    if (port == nullptr)
        return {StatusCode::InvalidModel, std::string("interface component has no port '") + portName + "'",
                component.name()};
    Entry entry;
    entry.variable.name = component.name();
    entry.variable.causality = causality;
    entry.variable.variability = Variability::Continuous;
    entry.variable.description = port->description;
    if (causality == Causality::Input)
        entry.variable.start = port->hasStartNode() ? port->startValues[NodeSignal::Value]
                                                    : port->node()->value(NodeSignal::Value);
    entry.binding = {VariableBinding::Kind::NodeSlot, component.name(), portName, NodeSignal::Value, {}};
    return add(causality == Causality::Input ? mInputs : mOutputs, std::move(entry));
}

Status InterfaceBuilder::addPowerPort(const Component& component, char kind)
{
    const Port* port = component.port("P1");
    if (port == nullptr)
        return {StatusCode::InvalidModel, "power interface component has no port 'P1'", component.name()};
    const NodeTypeInfo& info = nodeTypeInfo(port->nodeType());
    PowerPort powerPort{component.name(), std::string(info.typeName), kind, {}, {}};
    for (std::size_t slot = 0; slot < info.variables.size(); ++slot) {
        const NodeVariableInfo& var = info.variables[slot];
        if (var.kind == NodeVariableKind::Hidden)
            continue;
        // A C-type interface takes the TLM slots from outside, a Q-type one the others.
        bool isTlm = var.kind == NodeVariableKind::TLM;
        bool input = (kind == 'C') == isTlm;
        Entry entry;
        entry.variable.name = component.name() + "." + std::string(var.shortName);
        entry.variable.causality = input ? Causality::Input : Causality::Output;
        entry.variable.variability = Variability::Continuous;
        entry.variable.description = std::string(var.name);
        entry.variable.unit = std::string(var.unit);
        if (input)
            entry.variable.start = port->hasStartNode() ? port->startValues[slot] : port->node()->value(int(slot));
        entry.binding = {VariableBinding::Kind::NodeSlot, component.name(), "P1", int(slot), {}};
        auto& sides = input ? powerPort.inputs : powerPort.outputs;
        sides.emplace_back(std::string(var.shortName), entry.variable.name);
        if (Status s = add(input ? mInputs : mOutputs, std::move(entry)); !s)
            return s;
    }
    mPowerPorts.push_back(std::move(powerPort));
    return Status::ok();
}

Status InterfaceBuilder::addParameter(const std::string& path, const Parameter& parameter)
{
    if (parameter.type != ParameterType::Double)
        return {StatusCode::InvalidParameter,
                std::string("only real parameters can be FMU parameters, this one is ") +
                    parameterTypeName(parameter.type),
                path};
    std::optional<double> start = numberOf(parameter.value);
    if (!start)
        return {StatusCode::InvalidParameter,
                "an FMU parameter needs a number as its value, not '" + parameter.value + "'", path};
    Entry entry;
    entry.variable.name = path;
    entry.variable.causality = Causality::Parameter;
    entry.variable.variability = Variability::Fixed;
    entry.variable.description = parameter.description;
    entry.variable.unit = parameter.unit;
    entry.variable.start = start;
    entry.binding = {VariableBinding::Kind::Parameter, {}, {}, 0, path};
    return add(mParameters, std::move(entry));
}

Status InterfaceBuilder::addTimestep(double timestep)
{
    Entry entry;
    entry.variable.name = kTimestepName;
    entry.variable.causality = Causality::Parameter;
    entry.variable.variability = Variability::Fixed;
    entry.variable.description = "Simulation time step";
    entry.variable.unit = "s";
    entry.variable.start = timestep;
    entry.binding.kind = VariableBinding::Kind::Timestep;
    return add(mParameters, std::move(entry));
}

Result<ModelInterface> InterfaceBuilder::finish(ModelDescription description)
{
    ModelInterface result;
    for (auto* list : {&mInputs, &mOutputs, &mParameters}) {
        for (Entry& entry : *list) {
            entry.variable.valueReference = std::uint32_t(description.variables.size());
            if (entry.variable.causality == Causality::Output)
                description.outputs.push_back(description.variables.size() + 1);
            description.variables.push_back(std::move(entry.variable));
            result.bindings.push_back(std::move(entry.binding));
        }
    }
    description.powerPorts = std::move(mPowerPorts);
    result.description = std::move(description);
    return result;
}

} // namespace

Result<ModelInterface> describeInterface(const System& root, const InterfaceOptions& options)
{
    ModelDescription description;
    description.modelName = root.name();
    description.modelIdentifier = options.modelIdentifier.empty() ? cIdentifier(root.name()) : options.modelIdentifier;
    if (!isCIdentifier(description.modelIdentifier))
        return Status{StatusCode::InvalidSettings,
                      "the model identifier must be a C identifier, not '" + description.modelIdentifier + "'"};
    description.startTime = root.startTime;
    description.stopTime = root.stopTime;
    description.stepSize = root.desiredTimestep;

    InterfaceBuilder builder;
    for (const Component* component : root.componentsByName()) {
        const std::string& type = component->typeName();
        Status status;
        if (type == "SignalInputInterface")
            status = builder.addSignal(*component, "out", Causality::Input);
        else if (type == "SignalOutputInterface")
            status = builder.addSignal(*component, "in", Causality::Output);
        else if (endsWith(type, "InterfaceC") || endsWith(type, "InterfaceQ"))
            status = builder.addPowerPort(*component, type.back());
        if (!status)
            return status;
    }
    for (const auto& parameter : root.parameters().all()) {
        if (parameter->type != ParameterType::Double)
            continue;   // string, boolean... system parameters have no FMI 2.0 real form
        if (Status s = builder.addParameter(parameter->name, *parameter); !s)
            return s;
    }
    for (const std::string& path : options.parameters) {
        if (path.find('.') == std::string::npos)
            return Status{StatusCode::NotFound, "a component parameter is named 'Comp.param'", path};
        // findParameter only looks the path up; it takes a mutable System for its callers that edit.
        Result<ParameterRef> found = findParameter(const_cast<System&>(root), path);
        if (!found)
            return found.status();
        if (Status s = builder.addParameter(path, *found->parameter); !s)
            return s;
    }
    if (Status s = builder.addTimestep(root.desiredTimestep); !s)
        return s;
    return builder.finish(std::move(description));
}

Status takeInputStartsFromInitialisation(ModelInterface& modelInterface, const Model& model)
{
    Result<Simulation> compiled = compile(model, {.logSamples = 0});
    if (!compiled)
        return compiled.status();
    if (Status started = compiled->initialise(); !started)
        return started;
    const System& root = compiled->system();
    auto& variables = modelInterface.description.variables;
    for (std::size_t i = 0; i < variables.size(); ++i) {
        const VariableBinding& binding = modelInterface.bindings[i];
        if (variables[i].causality == Causality::Input && binding.kind == VariableBinding::Kind::NodeSlot)
            variables[i].start = root.component(binding.component)->port(binding.port)->node()->value(binding.slot);
    }
    return Status::ok();
}

} // namespace tlmhub::fmu
