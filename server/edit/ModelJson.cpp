#include "server/edit/ModelJson.h"

#include "core/hmf/PreservedXml.h"

#include <algorithm>
#include <optional>
#include <set>
#include <utility>

namespace tlmhub::server {

namespace {

// The protocol's four port kinds; multiports report their base kind and multiport = true.
const char* portKindForJson(PortKind kind)
{
    switch (kind) {
    case PortKind::Read:
    case PortKind::ReadMultiport: return "read";
    case PortKind::Write: return "write";
    case PortKind::BiDirectionalSignal: return "bidirectional";
    case PortKind::System: return "system";
    default: return "power";
    }
}

std::string nodeTypeName(NodeType type) { return std::string(nodeTypeInfo(type).typeName); }

protocol::Pose describePose(const Pose& pose)
{
    return {.x = pose.x, .y = pose.y, .angle = pose.angle, .flipped = pose.flipped};
}

protocol::Port describePort(const Port& port)
{
    return {.name = port.name(),
            .nodeType = nodeTypeName(port.nodeType()),
            .kind = portKindForJson(port.kind()),
            .multiport = port.isMultiport(),
            .connected = port.isConnected()};
}

protocol::SystemPort describeSystemPort(const System& system, const Port& port)
{
    auto extras = system.systemPortExtras.find(port.name());
    const Pose pose = extras == system.systemPortExtras.end() ? Pose{} : extras->second.layout.pose;
    return {.name = port.name(),
            .nodeType = port.nodeType() == NodeType::Empty ? std::nullopt
                                                            : std::optional(nodeTypeName(port.nodeType())),
            .pose = describePose(pose)};
}

} // namespace

protocol::Param describeParameter(const Parameter& p)
{
    return {.name = p.name,
            .value = p.value,
            .unit = p.unit,
            .description = p.description,
            .type = parameterTypeName(p.type)};
}

protocol::SysParam describeSystemParameter(const Parameter& p)
{
    return {.name = p.name,
            .value = p.value,
            .type = parameterTypeName(p.type),
            .unit = p.unit,
            .description = p.description};
}

std::vector<ConnectionEnds> connectionsOf(const System& system)
{
    // Walk the ports as the saver does (components in insertion order, multiports by
    // sub-port, then the system's own ports), so "from" is the end the file lists first.
    std::vector<const Port*> ports;
    for (const Component* c : system.componentsInOrder())
        for (const Port* p : c->ports()) {
            if (p->isMultiport())
                for (const auto& sub : p->subPorts) ports.push_back(sub.get());
            else
                ports.push_back(p);
        }
    for (const Port* p : system.ports())
        if (p->kind() == PortKind::System) ports.push_back(p);

    auto visible = [&system](const Port* p) {
        return p->component() == &system || p->component()->parentSystem() == &system;
    };
    auto componentName = [&system](const Port* p) {
        return p->component() == &system ? p->name() : p->component()->name();
    };
    std::vector<ConnectionEnds> out;
    std::set<std::pair<const Port*, const Port*>> seen;
    for (const Port* a : ports) {
        for (const Port* b : a->connectedPorts) {
            if (seen.count({b, a}) || seen.count({a, b})) continue;
            const Port* pa = a->parentMultiport ? a->parentMultiport : a;
            const Port* pb = b->parentMultiport ? b->parentMultiport : b;
            if (!visible(pa) || !visible(pb)) continue;
            seen.insert({a, b});
            out.push_back({componentName(pa), pa->name(), componentName(pb), pb->name()});
        }
    }
    return out;
}

std::string connectionExtrasKey(const System& system, const ConnectionEnds& e, bool& reversed)
{
    reversed = false;
    std::string key = preserved::connectionKey(e.fromComponent, e.fromPort, e.toComponent, e.toPort);
    if (system.connectionExtras.contains(key)) return key;
    std::string other = preserved::connectionKey(e.toComponent, e.toPort, e.fromComponent, e.fromPort);
    if (!system.connectionExtras.contains(other)) return key;
    reversed = true;
    return other;
}

const ConnectionLayout* connectionLayout(const System& system, const ConnectionEnds& e, bool& reversed)
{
    const auto it = system.connectionExtras.find(connectionExtrasKey(system, e, reversed));
    return it == system.connectionExtras.end() ? nullptr : &it->second.layout;
}

protocol::Connection describeConnection(const System& system, const ConnectionEnds& e)
{
    std::vector<std::vector<double>> points;
    bool reversed = false;
    if (const ConnectionLayout* layout = connectionLayout(system, e, reversed)) {
        std::vector<LinePoint> line = layout->points;
        if (reversed) std::reverse(line.begin(), line.end());
        for (const LinePoint& p : line) points.push_back({p[0], p[1]});
    }
    return {.from = {.component = e.fromComponent, .port = e.fromPort},
            .to = {.component = e.toComponent, .port = e.toPort},
            .points = std::move(points)};
}

protocol::Component describeComponent(const Component& c)
{
    std::vector<protocol::Port> ports;
    for (const Port* p : c.ports()) ports.push_back(describePort(*p));
    std::vector<protocol::Param> parameters;
    for (const auto& p : c.parameters().all()) parameters.push_back(describeParameter(*p));
    return {.name = c.name(),
            .type = c.typeName(),
            .kind = c.isSystem() ? "system" : cqsKindName(c.kind()),
            .pose = describePose(c.layout.pose),
            .ports = std::move(ports),
            .parameters = std::move(parameters),
            .system = c.isSystem() ? std::optional(describeSystem(static_cast<const System&>(c))) : std::nullopt};
}

protocol::LiveControl describeLiveControl(const LiveControlLayout& c)
{
    return {.kind = c.kind, .name = c.name, .min = c.min, .max = c.max, .off = c.off, .on = c.on, .x = c.x, .y = c.y,
            .system = c.system.empty() ? std::nullopt : std::optional(c.system)};
}

LiveControlLayout liveControlOf(const protocol::LiveControl& c)
{
    return {.kind = c.kind, .name = c.name, .min = c.min, .max = c.max, .off = c.off, .on = c.on, .x = c.x, .y = c.y,
            .system = c.system.value_or(std::vector<std::string>{})};
}

protocol::System describeSystem(const System& s)
{
    std::vector<protocol::SysParam> parameters;
    for (const auto& p : s.parameters().all())
        if (!p->isStartValue) parameters.push_back(describeSystemParameter(*p));
    std::vector<protocol::SystemPort> ports;
    for (const Port* p : s.ports())
        if (p->kind() == PortKind::System) ports.push_back(describeSystemPort(s, *p));
    std::vector<protocol::Component> components;
    for (const Component* c : s.componentsInOrder()) components.push_back(describeComponent(*c));
    std::vector<protocol::Connection> connections;
    for (const ConnectionEnds& e : connectionsOf(s)) connections.push_back(describeConnection(s, e));
    std::vector<protocol::LiveControl> liveControls;
    for (const LiveControlLayout& c : s.liveControls) liveControls.push_back(describeLiveControl(c));
    return {.name = s.name(),
            .type = s.isConditional() ? "ConditionalSubsystem" : "Subsystem",
            .timestep = s.desiredTimestep,
            .inheritTimestep = s.inheritTimestep,
            .simulation = s.isRoot() ? std::optional(describeSimulationSettings(s)) : std::nullopt,
            .parameters = std::move(parameters),
            .ports = std::move(ports),
            .components = std::move(components),
            .connections = std::move(connections),
            .liveControls = liveControls.empty() ? std::nullopt : std::optional(std::move(liveControls))};
}

protocol::SimulationSettings describeSimulationSettings(const System& root)
{
    return {.start = root.startTime,
            .step = root.desiredTimestep,
            .stop = root.stopTime,
            .logSamples = static_cast<std::int64_t>(root.requestedLogSamples)};
}

protocol::Model describeModel(const System& root, const std::string& modelName)
{
    return {.name = modelName, .system = describeSystem(root)};
}

} // namespace tlmhub::server
