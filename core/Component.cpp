#include "core/Component.h"

#include "core/FileAccess.h"

#include "core/System.h"

#include <cassert>
#include <filesystem>

namespace tlmhub {

void stepVirtually(Component* const* components, std::size_t count, double time)
{
    for (std::size_t i = 0; i < count; ++i) {
        components[i]->mTime = time;
        components[i]->simulateOneTimestep();
    }
}

const char* cqsKindName(CqsKind kind)
{
    switch (kind) {
    case CqsKind::C: return "C";
    case CqsKind::Q: return "Q";
    case CqsKind::S: return "S";
    default: return "UndefinedCQSType";
    }
}

Component::Component(CqsKind kind) : mKind(kind) {}

Component::~Component() = default;

int Component::depth() const
{
    int d = 0;
    for (const System* s = mParent; s; s = s->parentSystem()) ++d;
    return d;
}

Port* Component::port(const std::string& name) const
{
    auto it = mPortsByName.find(name);
    return it == mPortsByName.end() ? nullptr : it->second;
}

std::vector<Port*> Component::ports() const
{
    std::vector<Port*> out;
    out.reserve(mPorts.size());
    for (const auto& p : mPorts) out.push_back(p.get());
    return out;
}

bool Component::renamePort(const std::string& oldName, const std::string& newName)
{
    Port* p = port(oldName);
    if (!p || port(newName)) return false;
    mPortsByName.erase(oldName);
    p->setName(newName);
    mPortsByName[newName] = p;
    // Start-value parameters follow the port name.
    for (const auto& param : mParameters.all()) {
        if (param->isStartValue && param->name.rfind(oldName + "#", 0) == 0)
            param->name = newName + param->name.substr(oldName.size());
    }
    return true;
}

Port* Component::addPortRaw(std::unique_ptr<Port> port)
{
    Port* raw = port.get();
    mPortsByName[raw->name()] = raw;
    mPorts.push_back(std::move(port));
    return raw;
}

bool Component::removePort(const std::string& name)
{
    Port* p = port(name);
    if (!p) return false;
    mPortsByName.erase(name);
    for (auto it = mPorts.begin(); it != mPorts.end(); ++it) {
        if (it->get() == p) {
            mPorts.erase(it);
            break;
        }
    }
    return true;
}

Port* Component::addPortInternal(const std::string& name, PortKind kind, NodeType type, bool required)
{
    auto port = std::make_unique<Port>(name, kind, type, this);
    port->required = required;
    Port* raw = addPortRaw(std::move(port));
    const bool startNode = kind == PortKind::Read || kind == PortKind::Write ||
                           ((kind == PortKind::Power || kind == PortKind::PowerMultiport) &&
                            mKind == CqsKind::C);
    if (startNode) {
        raw->createStartNode();
        registerStartValueParameters(raw);
    }
    return raw;
}

void Component::registerStartValueParameters(Port* port)
{
    const auto& vars = nodeTypeInfo(port->nodeType()).variables;
    for (std::size_t i = 0; i < vars.size(); ++i) {
        Parameter p;
        p.name = port->name() + "#" + std::string(vars[i].name);
        p.description = "startvalue";
        p.unit = std::string(vars[i].unit);
        p.type = ParameterType::Double;
        p.value = formatNumber(port->startValues[i]);
        p.defaultValue = p.value;
        p.isStartValue = true;
        p.doubleTarget = &port->startValues[i];
        mParameters.add(std::move(p));
    }
}

Port* Component::addPowerPort(const std::string& name, NodeType type, bool required)
{
    return addPortInternal(name, PortKind::Power, type, required);
}

Port* Component::addReadPort(const std::string& name, NodeType type, bool required)
{
    return addPortInternal(name, PortKind::Read, type, required);
}

Port* Component::addWritePort(const std::string& name, NodeType type, bool required)
{
    return addPortInternal(name, PortKind::Write, type, required);
}

Port* Component::addPowerMultiPort(const std::string& name, NodeType type, bool required)
{
    return addPortInternal(name, PortKind::PowerMultiport, type, required);
}

Port* Component::addReadMultiPort(const std::string& name, NodeType type, bool required)
{
    return addPortInternal(name, PortKind::ReadMultiport, type, required);
}

Port* Component::addBiDirectionalSignalPort(const std::string& name, NodeType type, bool required)
{
    return addPortInternal(name, PortKind::BiDirectionalSignal, type, required);
}

Port* Component::addInputVariable(const std::string& name, const std::string& description,
                                  const std::string& unit, double defaultValue, double** data)
{
    Port* p = addPortInternal(name, PortKind::Read, NodeType::Signal, false);
    p->description = description;
    setDefaultStartValue(p, NodeSignal::Value, defaultValue);
    if (Parameter* param = mParameters.find(name + "#Value")) {
        param->description = description;
        param->unit = unit;
        param->liveChangeable = true;
    }
    p->node()->signalUnit = unit;
    mAutoBindings.push_back({p, data});
    return p;
}

void Component::setLiveChangeable(std::initializer_list<std::string_view> variables, bool changeable)
{
    for (std::string_view variable : variables) {
        Parameter* p = mParameters.find(std::string(variable) + "#Value");
        assert(p && "setLiveChangeable names a variable without a start value");
        if (p) p->liveChangeable = changeable;
    }
}

Port* Component::addOutputVariable(const std::string& name, const std::string& description,
                                   const std::string& unit, double** data)
{
    Port* p = addPortInternal(name, PortKind::Write, NodeType::Signal, false);
    p->description = description;
    disableStartValue(p, NodeSignal::Value);
    p->node()->signalUnit = unit;
    mAutoBindings.push_back({p, data});
    return p;
}

Port* Component::addOutputVariable(const std::string& name, const std::string& description,
                                   const std::string& unit, double defaultValue, double** data)
{
    Port* p = addPortInternal(name, PortKind::Write, NodeType::Signal, false);
    p->description = description;
    setDefaultStartValue(p, NodeSignal::Value, defaultValue);
    if (Parameter* param = mParameters.find(name + "#Value")) {
        param->description = description;
        param->unit = unit;
    }
    p->node()->signalUnit = unit;
    mAutoBindings.push_back({p, data});
    return p;
}

void Component::bindAutoVariables()
{
    for (const auto& b : mAutoBindings) *b.data = getSafeNodeDataPtr(b.port, NodeSignal::Value);
}

void Component::addConstant(const std::string& name, const std::string& description,
                            const std::string& unit, double defaultValue, double& variable)
{
    variable = defaultValue;
    Parameter p;
    p.name = name;
    p.description = description;
    p.unit = unit;
    p.type = ParameterType::Double;
    p.value = formatNumber(defaultValue);
    p.defaultValue = p.value;
    p.doubleTarget = &variable;
    mParameters.add(std::move(p));
}

void Component::addConstant(const std::string& name, const std::string& description,
                            const std::string& unit, int defaultValue, int& variable)
{
    variable = defaultValue;
    Parameter p;
    p.name = name;
    p.description = description;
    p.unit = unit;
    p.type = ParameterType::Integer;
    p.value = std::to_string(defaultValue);
    p.defaultValue = p.value;
    p.intTarget = &variable;
    mParameters.add(std::move(p));
}

void Component::addConstant(const std::string& name, const std::string& description,
                            bool defaultValue, bool& variable)
{
    variable = defaultValue;
    Parameter p;
    p.name = name;
    p.description = description;
    p.type = ParameterType::Bool;
    p.value = defaultValue ? "true" : "false";
    p.defaultValue = p.value;
    p.boolTarget = &variable;
    mParameters.add(std::move(p));
}

void Component::addConstant(const std::string& name, const std::string& description,
                            const std::string& defaultValue, std::string& variable,
                            ParameterType type)
{
    variable = defaultValue;
    Parameter p;
    p.name = name;
    p.description = description;
    p.type = type;
    p.value = defaultValue;
    p.defaultValue = p.value;
    p.stringTarget = &variable;
    mParameters.add(std::move(p));
}

void Component::addConditionalConstant(const std::string& name, const std::string& description,
                                       std::vector<std::string> alternatives, int defaultIndex,
                                       int& variable)
{
    variable = defaultIndex;
    Parameter p;
    p.name = name;
    p.description = description;
    p.type = ParameterType::Conditional;
    p.value = std::to_string(defaultIndex);
    p.defaultValue = p.value;
    p.conditions = std::move(alternatives);
    p.intTarget = &variable;
    mParameters.add(std::move(p));
}

void Component::setDefaultStartValue(Port* port, int id, double value)
{
    if (!port || !port->hasStartNode() || id < 0 ||
        static_cast<std::size_t>(id) >= port->startValues.size())
        return;
    port->startValues[id] = value;
    const std::string pname =
        port->name() + "#" + std::string(nodeTypeInfo(port->nodeType()).variables[id].name);
    if (Parameter* p = mParameters.find(pname)) {
        p->value = formatNumber(value);
        p->defaultValue = p->value;
    }
}

void Component::disableStartValue(Port* port, int id)
{
    if (!port || !port->hasStartNode()) return;
    const std::string pname =
        port->name() + "#" + std::string(nodeTypeInfo(port->nodeType()).variables[id].name);
    mParameters.remove(pname);
}

double Component::getDefaultStartValue(const Port* port, int id) const
{
    if (!port || !port->hasStartNode() || id < 0 ||
        static_cast<std::size_t>(id) >= port->startValues.size())
        return 0.0;
    return port->startValues[id];
}

double* Component::getSafeNodeDataPtr(Port* port, int id)
{
    if (!port || id < 0) return &mDummy[0];
    if (port->isMultiport()) return getSafeMultiPortNodeDataPtr(port, 0, id);
    Node* n = port->node();
    if (!n || static_cast<std::size_t>(id) >= n->size()) return &mDummy[0];
    return n->data() + id;
}

double* Component::getSafeMultiPortNodeDataPtr(Port* port, std::size_t subIndex, int id, double initialValue)
{
    double* data = getSafeMultiPortNodeDataPtr(port, subIndex, id);
    *data = initialValue;
    return data;
}

double* Component::getSafeMultiPortNodeDataPtr(Port* port, std::size_t subIndex, int id)
{
    if (!port || id < 0) return &mDummy[0];
    if (!port->isMultiport()) return getSafeNodeDataPtr(port, id);
    if (subIndex >= port->subPorts.size()) {
        // An unconnected multiport reads a dummy: its node type's created value.
        const auto& vars = nodeTypeInfo(port->nodeType()).variables;
        if (static_cast<std::size_t>(id) < vars.size() && static_cast<std::size_t>(id) < 32)
            mDummy[id] = port->hasStartNode() ? port->startValues[id] : vars[id].createdValue;
        return &mDummy[id < 32 ? id : 0];
    }
    Node* n = port->subPorts[subIndex]->node();
    if (static_cast<std::size_t>(id) >= n->size()) return &mDummy[0];
    return n->data() + id;
}

std::size_t Component::getNumPorts(const Port* port) const
{
    if (!port) return 0;
    return port->isMultiport() ? port->subPorts.size() : 1;
}

void Component::addMessage(MessageType type, const std::string& text, const std::string& tag)
{
    System* root = mParent ? mParent->rootSystem() : nullptr;
    if (!root && isSystem()) root = static_cast<System*>(this)->rootSystem();
    const std::string full = mName.empty() ? text : mName + ": " + text;
    if (root) root->postMessage({type, full, tag, modelPath()});
}

std::string Component::modelPath() const
{
    if (!mParent) return {};
    const std::string outer = mParent->modelPath();
    return outer.empty() ? mName : outer + "$" + mName;
}

void Component::stopSimulation(const std::string& reason)
{
    if (!reason.empty()) addErrorMessage(reason);
    System* root = mParent ? mParent->rootSystem() : nullptr;
    if (!root && isSystem()) root = static_cast<System*>(this)->rootSystem();
    if (root) root->requestStop();
}

void Component::endSimulation(const std::string& reason)
{
    System* root = mParent ? mParent->rootSystem() : nullptr;
    if (!root && isSystem()) root = static_cast<System*>(this)->rootSystem();
    if (!root) return;
    root->postMessage({MessageType::Info, reason, "SimulationEnded", modelPath(), StatusCode::SimulationEnded});
    root->requestStop();
}

RandomStream& Component::randomStream()
{
    System* root = mParent ? mParent->rootSystem() : static_cast<System*>(this);
    root->mDrawsRandomNumbers = true;
    return root->mRandom;
}

std::string Component::modelDirectory() const
{
    const System* root = mParent ? mParent->rootSystem() : nullptr;
    if (!root && isSystem()) root = static_cast<const System*>(this)->rootSystem();
    return root ? root->modelDirectory : std::string();
}

std::string Component::findFilePath(const std::string& path)
{
    namespace fs = std::filesystem;
    if (!modelFileAccessAllowed()) {
        addMessage(MessageType::Error, "file access is disabled for models on this server ('" + path + "')");
        return {};
    }
    fs::path p(path);
    if (p.is_absolute() || path.empty()) return path;
    fs::path candidate = fs::path(modelDirectory()) / p;
    return candidate.lexically_normal().string();
}

} // namespace tlmhub
