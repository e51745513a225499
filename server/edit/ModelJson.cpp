#include "server/edit/ModelJson.h"

#include "core/hmf/PreservedXml.h"
#include "server/edit/GuiLayout.h"

#include <algorithm>
#include <set>
#include <utility>

namespace tlmhub::server {

namespace {

using nlohmann::json;

// The protocol's four port kinds; multiports report their base kind and multiport = true.
const char* portKindForJson(PortKind kind)
{
    switch (kind) {
    case PortKind::Read:
    case PortKind::ReadMultiport: return "read";
    case PortKind::Write: return "write";
    case PortKind::System: return "system";
    default: return "power";
    }
}

std::string nodeTypeName(NodeType type) { return std::string(nodeTypeInfo(type).typeName); }

json portToJson(const Port& port)
{
    return {{"name", port.name()},
            {"node_type", nodeTypeName(port.nodeType())},
            {"kind", portKindForJson(port.kind())},
            {"multiport", port.isMultiport()},
            {"connected", port.isConnected()}};
}

json systemPortToJson(const System& system, const Port& port)
{
    auto extras = system.preservedSystemPortXml.find(port.name());
    const Pose pose = extras == system.preservedSystemPortXml.end() ? Pose{} : readPose(extras->second);
    return {{"name", port.name()},
            {"node_type", port.nodeType() == NodeType::Empty ? json(nullptr) : json(nodeTypeName(port.nodeType()))},
            {"pose", pose}};
}

} // namespace

json parameterToJson(const Parameter& p)
{
    return {{"name", p.name},
            {"value", p.value},
            {"unit", p.unit},
            {"description", p.description},
            {"type", parameterTypeName(p.type)}};
}

json systemParameterToJson(const Parameter& p)
{
    return {{"name", p.name},
            {"value", p.value},
            {"type", parameterTypeName(p.type)},
            {"unit", p.unit},
            {"description", p.description}};
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

const std::string* preservedConnectionXml(const System& system, const ConnectionEnds& e, bool& reversed)
{
    const auto& extras = system.preservedConnectionXml;
    reversed = false;
    auto it = extras.find(preserved::connectionKey(e.fromComponent, e.fromPort, e.toComponent, e.toPort));
    if (it == extras.end()) {
        it = extras.find(preserved::connectionKey(e.toComponent, e.toPort, e.fromComponent, e.fromPort));
        reversed = it != extras.end();
    }
    return it == extras.end() ? nullptr : &it->second;
}

json connectionToJson(const System& system, const ConnectionEnds& e)
{
    json points = json::array();
    bool reversed = false;
    if (const std::string* xml = preservedConnectionXml(system, e, reversed)) {
        std::vector<LinePoint> line = readLinePoints(*xml);
        if (reversed) std::reverse(line.begin(), line.end());
        for (const LinePoint& p : line) points.push_back({p[0], p[1]});
    }
    return {{"from", {{"component", e.fromComponent}, {"port", e.fromPort}}},
            {"to", {{"component", e.toComponent}, {"port", e.toPort}}},
            {"points", points}};
}

json componentToJson(const Component& c)
{
    json ports = json::array();
    for (const Port* p : c.ports()) ports.push_back(portToJson(*p));
    json parameters = json::array();
    for (const auto& p : c.parameters().all()) parameters.push_back(parameterToJson(*p));
    json out = {{"name", c.name()},
                {"type", c.typeName()},
                {"kind", c.isSystem() ? "system" : cqsKindName(c.kind())},
                {"pose", readPose(c.preservedXml)},
                {"ports", ports},
                {"parameters", parameters}};
    if (c.isSystem()) out["system"] = systemToJson(static_cast<const System&>(c));
    return out;
}

json systemToJson(const System& s)
{
    json parameters = json::array();
    for (const auto& p : s.parameters().all())
        if (!p->isStartValue) parameters.push_back(systemParameterToJson(*p));
    json ports = json::array();
    for (const Port* p : s.ports())
        if (p->kind() == PortKind::System) ports.push_back(systemPortToJson(s, *p));
    json components = json::array();
    for (const Component* c : s.componentsInOrder()) components.push_back(componentToJson(*c));
    json connections = json::array();
    for (const ConnectionEnds& e : connectionsOf(s)) connections.push_back(connectionToJson(s, e));

    json out = {{"name", s.name()},
                {"type", s.isConditional() ? "ConditionalSubsystem" : "Subsystem"},
                {"timestep", s.desiredTimestep},
                {"inherit_timestep", s.inheritTimestep},
                {"parameters", parameters},
                {"ports", ports},
                {"components", components},
                {"connections", connections}};
    if (s.isRoot()) out["simulation"] = simulationSettingsToJson(s);
    return out;
}

json simulationSettingsToJson(const System& root)
{
    return {{"start", root.startTime},
            {"step", root.desiredTimestep},
            {"stop", root.stopTime},
            {"log_samples", root.requestedLogSamples}};
}

json modelToJson(const System& root, const std::string& modelName)
{
    return {{"name", modelName}, {"system", systemToJson(root)}};
}

} // namespace tlmhub::server
