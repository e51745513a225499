#include "core/System.h"

#include "core/ParameterEvaluator.h"
#include "core/hmf/PreservedXml.h"
#include "core/numerics/StepCount.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <deque>
#include <set>

namespace tlmhub {

namespace {

const char* kReservedNames[] = {"self", "Time", "time", "Frequency", "frequency"};

// The port's sort hint as the sorting algorithm sees it (system ports: internal hint).
SortHint effectiveSortHint(const Port* p)
{
    if (p->kind() == PortKind::System) return p->internalSortHint;
    return p->sortHint;
}

void collectConnected(Port* start, std::vector<Port*>& out)
{
    std::deque<Port*> todo{start};
    std::set<Port*> seen{start};
    while (!todo.empty()) {
        Port* p = todo.front();
        todo.pop_front();
        out.push_back(p);
        for (Port* q : p->connectedPorts)
            if (seen.insert(q).second) todo.push_back(q);
    }
}

System* owningSystemOf(const Port* p)
{
    Component* c = p->component();
    if (c->parentSystem()) return c->parentSystem();
    return static_cast<System*>(c);   // a root system's own port
}

// The node's owner: the system of the shallowest attached component (core.md §2.5).
System* nodeOwner(const Node* n)
{
    System* best = nullptr;
    int bestDepth = 1 << 30;
    for (const Port* p : n->ports()) {
        System* s = owningSystemOf(p);
        int d = s->depth();
        if (d < bestDepth) {
            bestDepth = d;
            best = s;
        }
    }
    return best;
}

} // namespace

std::string sanitizeName(const std::string& name)
{
    if (name.empty()) return "noName";
    std::string out = name;
    for (char& ch : out) {
        unsigned char c = static_cast<unsigned char>(ch);
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
            ch = '_';
    }
    return out;
}

namespace {

// The batch step of subsystems: each runs its own steps up to the parent's time.
void stepSubsystems(Component* const* systems, std::size_t count, double time)
{
    for (std::size_t i = 0; i < count; ++i) static_cast<System*>(systems[i])->simulateTo(time);
}

} // namespace

System::System() : Component(CqsKind::Undefined)
{
    mIsSystem = true;
    setBatchStepper(&stepSubsystems);
    setTypeName("Subsystem");
}

System::~System()
{
    // Destroy children before our own ports so node back-references stay valid.
    mOrder.clear();
    mComponents.clear();
}

System* System::rootSystem()
{
    System* s = this;
    while (s->parentSystem()) s = s->parentSystem();
    return s;
}

const System* System::rootSystem() const
{
    const System* s = this;
    while (s->parentSystem()) s = s->parentSystem();
    return s;
}

void System::makeConditional()
{
    if (mOnPort) return;
    setTypeName("ConditionalSubsystem");
    mOnPort = addInputVariable("on", "Simulate while on > 0", "", 0.0, &mpOn);
}

// ---------------------------------------------------------------- names

bool System::isNameTaken(const std::string& name) const
{
    for (const char* r : kReservedNames)
        if (name == r) return true;
    if (mComponents.count(name)) return true;
    if (port(name)) return true;
    if (parameters().find(name)) return true;
    return false;
}

std::string System::uniqueName(const std::string& desired) const
{
    std::string name = sanitizeName(desired);
    int k = 1;
    while (isNameTaken(name)) {
        std::size_t us = name.rfind('_');
        if (us != std::string::npos && us + 1 < name.size() &&
            std::isdigit(static_cast<unsigned char>(name[us + 1])))
            name.erase(us);
        name += "_" + std::to_string(k++);
    }
    return name;
}

// ---------------------------------------------------------------- components

std::string System::addComponent(std::unique_ptr<Component> component)
{
    return insertComponent(std::move(component), mOrder.size());
}

std::string System::insertComponent(std::unique_ptr<Component> component, std::size_t orderPosition)
{
    const std::string name = uniqueName(component->name());
    component->setNameRaw(name);
    component->setParentSystem(this);
    Component* raw = component.get();
    mComponents[name] = std::move(component);
    mOrder.insert(mOrder.begin() + static_cast<std::ptrdiff_t>(std::min(orderPosition, mOrder.size())), raw);
    return name;
}

Component* System::component(const std::string& name) const
{
    auto it = mComponents.find(name);
    return it == mComponents.end() ? nullptr : it->second.get();
}

System* System::subsystem(const std::string& name) const
{
    Component* c = component(name);
    return c && c->isSystem() ? static_cast<System*>(c) : nullptr;
}

std::vector<Component*> System::componentsByName() const
{
    std::vector<Component*> out;
    out.reserve(mComponents.size());
    for (const auto& [name, c] : mComponents) out.push_back(c.get());
    return out;
}

std::size_t System::countComponents() const
{
    std::size_t n = 0;
    for (Component* c : mOrder) n += c->isSystem() ? static_cast<System*>(c)->countComponents() : 1;
    return n;
}

Status System::removeComponent(const std::string& name)
{
    Component* c = component(name);
    if (!c) return {StatusCode::NotFound, "no component named '" + name + "' in system '" + this->name() + "'"};
    // Disconnect everything first.
    for (Port* p : c->ports()) {
        std::vector<Port*> targets;
        if (p->isMultiport()) {
            for (auto& sub : p->subPorts)
                for (Port* q : sub->connectedPorts) targets.push_back(q);
        } else {
            targets = p->connectedPorts;
        }
        for (Port* q : targets) {
            const std::string qComp = q->component() == this ? q->name() : q->component()->name();
            disconnect(name, p->name(), qComp, q->name());
        }
    }
    mOrder.erase(std::remove(mOrder.begin(), mOrder.end(), c), mOrder.end());
    mComponents.erase(name);
    determineKind();
    return Status::ok();
}

Result<std::string> System::renameComponent(const std::string& oldName, const std::string& newName)
{
    auto it = mComponents.find(oldName);
    if (it == mComponents.end())
        return Status{StatusCode::NotFound, "no component named '" + oldName + "' in system '" + name() + "'"};
    if (sanitizeName(newName) == oldName) return oldName;
    std::unique_ptr<Component> c = std::move(it->second);
    mComponents.erase(it);
    const std::string actual = uniqueName(newName);
    c->setNameRaw(actual);
    mComponents[actual] = std::move(c);
    return actual;
}

// ---------------------------------------------------------------- system ports

Port* System::addSystemPort(const std::string& desiredName)
{
    const std::string name = uniqueName(desiredName.empty() ? "p" : desiredName);
    auto p = std::make_unique<Port>(name, PortKind::System, NodeType::Empty, this);
    p->required = false;
    return addPortRaw(std::move(p));
}

Port* System::systemPort(const std::string& name) const
{
    Port* p = port(name);
    return p && p->kind() == PortKind::System ? p : nullptr;
}

Result<std::string> System::renameSystemPort(const std::string& oldName, const std::string& newName)
{
    if (!systemPort(oldName)) return Status{StatusCode::NotFound, "no system port named '" + oldName + "'"};
    if (sanitizeName(newName) == oldName) return oldName;
    const std::string previous = oldName;   // oldName may be the port's own name, renamed below
    const std::string actual = uniqueName(newName);
    renamePort(previous, actual);
    moveSystemPortLayout(previous, actual);
    return actual;
}

Status System::deleteSystemPort(const std::string& name)
{
    Port* p = systemPort(name);
    if (!p) return {StatusCode::NotFound, "no system port named '" + name + "'"};
    while (!p->connectedPorts.empty()) {
        Port* q = p->connectedPorts.front();
        if (q->component()->parentSystem() == this)
            disconnect(name, name, q->component()->name(), q->name());
        else if (parentSystem())
            parentSystem()->disconnect(this->name(), name,
                                       q->component() == parentSystem() ? q->name()
                                                                        : q->component()->name(),
                                       q->name());
        else
            break;
    }
    const std::string deleted = name;   // name may be the port's own name, freed below
    removePort(deleted);
    moveSystemPortLayout(deleted, {});
    return Status::ok();
}

namespace {

// Rekeys (or, for an empty new port, erases) the connection extras of `extras` that have
// the end (component, port); keys are "a.pa|b.pb" (core/hmf/PreservedXml.h).
void moveConnectionEnd(std::map<std::string, ConnectionExtras>& extras, const std::string& component,
                       const std::string& port, const std::string& newComponent, const std::string& newPort)
{
    std::map<std::string, ConnectionExtras> moved;
    for (auto it = extras.begin(); it != extras.end();) {
        preserved::ConnectionKeyParts k = preserved::parseConnectionKey(it->first);
        const bool atA = k.a == component && k.pa == port;
        const bool atB = k.b == component && k.pb == port;
        if (!atA && !atB) {
            ++it;
            continue;
        }
        if (!newPort.empty()) {
            if (atA) k.a = newComponent, k.pa = newPort;
            if (atB) k.b = newComponent, k.pb = newPort;
            moved[preserved::connectionKey(k.a, k.pa, k.b, k.pb)] = std::move(it->second);
        }
        it = extras.erase(it);
    }
    extras.merge(moved);
}

} // namespace

void System::moveSystemPortLayout(const std::string& oldName, const std::string& newName)
{
    // Inside, the system port is named twice, as component and port.
    if (auto node = systemPortExtras.extract(oldName); node && !newName.empty()) {
        node.key() = newName;
        systemPortExtras.insert(std::move(node));
    }
    moveConnectionEnd(connectionExtras, oldName, oldName, newName, newName);
    // Outside, it is a port of this subsystem, and a port on its icon.
    if (System* parent = parentSystem())
        moveConnectionEnd(parent->connectionExtras, name(), oldName, name(), newName);
    auto& icon = layout.iconPorts;
    auto port = std::find_if(icon.begin(), icon.end(), [&](const IconPort& p) { return p.name == oldName; });
    if (port == icon.end()) return;
    if (newName.empty()) icon.erase(port);
    else port->name = newName;
}

// ---------------------------------------------------------------- connections

Result<Port*> System::resolvePort(const std::string& compName, const std::string& portName) const
{
    if (Component* c = component(compName)) {
        if (Port* p = c->port(portName)) return p;
        return Status{StatusCode::NotFound, "component '" + compName + "' has no port '" + portName + "'"};
    }
    // A system port is named twice, as component and port (as the loader reads and the
    // saver writes it); another port name would let a typo connect it.
    if (Port* p = systemPort(compName)) {
        if (portName == compName) return p;
        return Status{StatusCode::NotFound, "no port '" + compName + "." + portName +
                                                "': a system port is named by its name twice ('" + compName +
                                                "." + compName + "')"};
    }
    return Status{StatusCode::NotFound,
                  "no component or system port named '" + compName + "' in system '" + name() + "'"};
}

Status System::connect(const std::string& compA, const std::string& portA, const std::string& compB,
                       const std::string& portB)
{
    const Result<Port*> a = resolvePort(compA, portA);
    if (!a) return a.status();
    const Result<Port*> b = resolvePort(compB, portB);
    if (!b) return b.status();
    if (const std::string refusal = connectPorts(*a, *b); !refusal.empty())
        return {StatusCode::IllegalConnection,
                "cannot connect " + compA + "." + portA + " to " + compB + "." + portB + ": " + refusal};
    // Kinds are re-determined; every enclosing subsystem moves to the end of its
    // parent's lists (core.md §3.3).
    determineKind();
    for (System* s = this; s->parentSystem(); s = s->parentSystem()) {
        s->parentSystem()->moveToEnd(s);
        s->parentSystem()->determineKind();
    }
    return Status::ok();
}

std::string System::connectPorts(Port* a, Port* b)
{
    if (a == b) return "a port cannot be connected to itself";
    if (a->isMultiport() && b->isMultiport()) return "both ports are multiports";
    const bool readMulti = a->kind() == PortKind::ReadMultiport || b->kind() == PortKind::ReadMultiport;
    if (!readMulti) {
        if (std::find(a->connectedPorts.begin(), a->connectedPorts.end(), b) != a->connectedPorts.end())
            return "the ports are already connected";
    }
    // Same system, or a system port of this system seen from inside.
    auto parentOf = [this](Port* p) -> System* {
        if (p->component() == this) return this;   // own system port, seen from inside
        return p->component()->parentSystem();
    };
    if (parentOf(a) != this || parentOf(b) != this)
        return "the components are not in the same system";
    const bool blankA = a->kind() == PortKind::System && !a->isConnected();
    const bool blankB = b->kind() == PortKind::System && !b->isConnected();
    if (blankA && blankB) return "two unconnected system ports cannot be connected";
    if ((a->kind() == PortKind::Read && b->isMultiport()) || (b->kind() == PortKind::Read && a->isMultiport()))
        return "a read port cannot be connected to a multiport";
    const NodeType typeA = a->nodeType(), typeB = b->nodeType();
    if (!blankA && !blankB && typeA != typeB)
        return std::string("node types differ (") + std::string(nodeTypeInfo(typeA).typeName) + " vs " +
               std::string(nodeTypeInfo(typeB).typeName) + ")";

    // Multiports get a new sub-port for this connection.
    Port* subA = nullptr;
    Port* subB = nullptr;
    if (a->isMultiport()) a = subA = a->addSubPort();
    if (b->isMultiport()) b = subB = b->addSubPort();
    auto undoSubPorts = [&]() {
        if (subA) subA->parentMultiport->removeSubPort(subA);
        if (subB) subB->parentMultiport->removeSubPort(subB);
    };

    if (a->node() == b->node()) {
        undoSubPorts();
        return "the ports already share a node";
    }
    const NodeType type = blankA ? typeB : typeA;

    // Tentative merge: every port reachable from either end, plus the two.
    std::vector<Port*> group;
    collectConnected(a, group);
    std::vector<Port*> groupB;
    collectConnected(b, groupB);
    group.insert(group.end(), groupB.begin(), groupB.end());

    int nPower = 0, nWrite = 0, nOwnSys = 0, nC = 0, nQ = 0;
    for (Port* p : group) {
        switch (p->kind()) {
        case PortKind::Power: {
            ++nPower;
            CqsKind k = p->component()->kind();
            if (!p->component()->isSystem()) {
                if (k == CqsKind::C) ++nC;
                if (k == CqsKind::Q) ++nQ;
            }
            break;
        }
        case PortKind::Write: ++nWrite; break;
        case PortKind::System:
            if (p->component() == this) ++nOwnSys;
            break;
        default: break;
        }
    }
    const char* reason = nullptr;
    if (nPower > 0 && nOwnSys > 1) reason = "one power port cannot connect to two system ports";
    else if (nPower > 2) reason = "a node can join at most two power ports";
    else if (nWrite > 1) reason = "a signal node can have only one write port";
    else if (nPower > 0 && nWrite > 0) reason = "a write port cannot connect to a power port";
    else if (nC > 1) reason = "two C-type power ports cannot be connected directly (both compute wave variables)";
    else if (nQ > 1) reason = "two Q-type power ports cannot be connected directly (both compute flows)";
    if (reason) {
        undoSubPorts();
        return reason;
    }

    // Commit: blank system ports adopt the type; everything moves to one new node.
    for (Port* p : group)
        if (p->kind() == PortKind::System && p->nodeType() != type) p->setNodeType(type);
    a->connectedPorts.push_back(b);
    b->connectedPorts.push_back(a);
    auto node = std::make_shared<Node>(type);
    for (Port* p : group) p->setNode(node);
    return {};
}

Status System::disconnect(const std::string& compA, const std::string& portA,
                          const std::string& compB, const std::string& portB)
{
    const Result<Port*> resolvedA = resolvePort(compA, portA);
    if (!resolvedA) return resolvedA.status();
    const Result<Port*> resolvedB = resolvePort(compB, portB);
    if (!resolvedB) return resolvedB.status();
    Port* a = *resolvedA;
    Port* b = *resolvedB;
    // Find the concrete (sub-)ports that are connected to each other.
    auto findPair = [](Port* x, Port* y, Port*& outX, Port*& outY) {
        std::vector<Port*> xs, ys;
        if (x->isMultiport()) for (auto& s : x->subPorts) xs.push_back(s.get()); else xs.push_back(x);
        if (y->isMultiport()) for (auto& s : y->subPorts) ys.push_back(s.get()); else ys.push_back(y);
        for (Port* px : xs)
            for (Port* py : ys)
                if (std::find(px->connectedPorts.begin(), px->connectedPorts.end(), py) != px->connectedPorts.end()) {
                    outX = px;
                    outY = py;
                    return true;
                }
        return false;
    };
    Port* pa = nullptr;
    Port* pb = nullptr;
    if (!findPair(a, b, pa, pb))
        return {StatusCode::IllegalConnection,
                "cannot disconnect " + compA + "." + portA + " from " + compB + "." + portB + ": they are not connected"};
    pa->connectedPorts.erase(std::find(pa->connectedPorts.begin(), pa->connectedPorts.end(), pb));
    pb->connectedPorts.erase(std::find(pb->connectedPorts.begin(), pb->connectedPorts.end(), pa));
    for (Port* side : {pa, pb}) {
        if (side->parentMultiport) {
            Port* mp = side->parentMultiport;
            if (side->connectedPorts.empty()) {
                mp->removeSubPort(side);
                continue;
            }
        }
        std::vector<Port*> group;
        collectConnected(side, group);
        bool onlyBlankSystemPort = group.size() == 1 && side->kind() == PortKind::System;
        if (onlyBlankSystemPort) {
            side->setNodeType(NodeType::Empty);
            continue;
        }
        auto node = std::make_shared<Node>(side->nodeType());
        for (Port* p : group) p->setNode(node);
    }
    determineKind();
    if (parentSystem()) parentSystem()->determineKind();
    return Status::ok();
}

void System::moveToEnd(Component* c)
{
    auto it = std::find(mOrder.begin(), mOrder.end(), c);
    if (it == mOrder.end()) return;
    mOrder.erase(it);
    mOrder.push_back(c);
}

CqsKind System::interfaceKind(const std::vector<const Port*>& innerPorts)
{
    int nC = 0, nQ = 0, nS = 0;
    for (const Port* q : innerPorts) {
        if (q->kind() == PortKind::Read || q->kind() == PortKind::Write ||
            q->kind() == PortKind::ReadMultiport)
            ++nS;
        else {
            CqsKind k = q->component()->kind();
            if (k == CqsKind::C) ++nC;
            else if (k == CqsKind::Q) ++nQ;
            else if (k == CqsKind::S) ++nS;
        }
    }
    if (nC > 0 && nQ == 0) return CqsKind::C;
    if (nQ > 0 && nC == 0) return CqsKind::Q;
    if (nS > 0 && nC == 0 && nQ == 0) return CqsKind::S;
    if (nC == 0 && nQ == 0 && nS == 0) return CqsKind::S;   // no interface: runs with signals
    return CqsKind::Undefined;
}

void System::determineKind()
{
    if (isRoot()) {
        mSystemKind = CqsKind::S;   // the root's kind is irrelevant; never Undefined
        return;
    }
    std::vector<const Port*> inner;
    for (Port* sp : ports()) {
        if (sp->kind() != PortKind::System) continue;
        for (Port* q : sp->connectedPorts)
            if (q->component() != this && q->component()->parentSystem() == this) inner.push_back(q);
    }
    const CqsKind k = interfaceKind(inner);
    mSystemKind = k;

    // C-type subsystems carry start values on their power system ports.
    for (Port* sp : ports()) {
        if (sp->kind() != PortKind::System) continue;
        bool innerPower = false;
        for (Port* q : sp->connectedPorts)
            if (q->component()->parentSystem() == this &&
                (q->kind() == PortKind::Power || q->kind() == PortKind::PowerMultiport))
                innerPower = true;
        const bool want = k == CqsKind::C && innerPower && sp->nodeType() != NodeType::Empty;
        if (want && !sp->hasStartNode()) {
            sp->createStartNode();
            const auto& vars = nodeTypeInfo(sp->nodeType()).variables;
            for (std::size_t i = 0; i < vars.size(); ++i) {
                Parameter p;
                p.name = sp->name() + "#" + std::string(vars[i].name);
                p.description = "startvalue";
                p.unit = std::string(vars[i].unit);
                p.value = formatNumber(sp->startValues[i]);
                p.defaultValue = p.value;
                p.isStartValue = true;
                p.doubleTarget = &sp->startValues[i];
                parameters().add(std::move(p));
            }
        } else if (!want && sp->hasStartNode()) {
            const auto& vars = nodeTypeInfo(sp->nodeType()).variables;
            for (const auto& v : vars) parameters().remove(sp->name() + "#" + std::string(v.name));
            sp->removeStartNode();
        }
    }
}

// ---------------------------------------------------------------- parameters

Status System::setSystemParameter(const std::string& pname, const std::string& value,
                                  const std::string& type, const std::string& description,
                                  const std::string& unit, bool internal)
{
    ParameterType t = ParameterType::Double;
    if (!type.empty() && !parameterTypeFromName(type, t))
        return {StatusCode::InvalidParameter, "unknown parameter type '" + type + "'", pname};
    if (Parameter* existing = parameters().find(pname)) {
        if (existing->isStartValue) {
            existing->value = value;
            return Status::ok();
        }
        existing->value = value;
        existing->type = t;
        existing->description = description;
        existing->unit = unit;
        existing->internal = internal;
        existing->bindOwnStorage();
        return Status::ok();
    }
    if (sanitizeName(pname) != pname && pname.find('#') == std::string::npos)
        return {StatusCode::InvalidParameter,
                "invalid system parameter name '" + pname + "' (letters, digits and _ only)", pname};
    if (isNameTaken(pname))
        return {StatusCode::InvalidParameter, "the name '" + pname + "' is already used in system '" + name() + "'",
                pname};
    Parameter p;
    p.name = pname;
    p.value = value;
    p.defaultValue = value;
    p.type = t;
    p.description = description;
    p.unit = unit;
    p.internal = internal;
    Parameter& added = parameters().add(std::move(p));
    added.bindOwnStorage();
    return Status::ok();
}

bool System::removeSystemParameter(const std::string& pname)
{
    return parameters().remove(pname);
}

// ---------------------------------------------------------------- simulation

void System::setTimestep(double ts)
{
    mTimestep = ts;
    for (Component* c : mOrder)
        if (!c->isSystem()) c->setTimestep(ts);
}

void System::preInitialize()
{
    // A subsystem's run lists are built in its own initialise, later: walk it by kind. Its
    // disabled components are still in Hopsan's lists at this point, so they are included.
    for (CqsKind kind : {CqsKind::S, CqsKind::C, CqsKind::Q})
        for (Component* c : mOrder) {
            const CqsKind k = c->kind() == CqsKind::Undefined ? CqsKind::S : c->kind();
            if (k == kind) c->preInitialize();
        }
}

void System::setProgressCallback(ProgressCallback cb, void* user, std::size_t interval)
{
    mProgress = cb;
    mProgressUser = user;
    mProgressInterval = interval;
}

Status System::check()
{
    if (Status structure = checkStructure(); !structure) return structure;
    ParameterEvaluator::Pass pass;
    return evaluateParameters(pass);
}

Status System::checkStructure()
{
    for (Component* c : componentsByName()) {
        if (c->kind() == CqsKind::Undefined) {
            return {StatusCode::UndefinedKind,
                    "component '" + c->name() + "' in system '" + name() +
                        "' has an undefined C/Q/S kind (a subsystem mixing C and Q interface ports?)",
                    c->modelPath()};
        }
    }
    for (Port* sp : ports()) {
        if (sp->kind() != PortKind::System) continue;
        if (sp->required && !sp->isConnected()) {
            return {StatusCode::UnconnectedPort,
                    "system port '" + sp->name() + "' of '" + name() + "' is not connected",
                    modelPath()};
        }
    }
    for (Component* c : componentsByName()) {
        if (c->isDisabled()) continue;
        for (const auto& [pname, p] : c->portsByName()) {
            if (p->required && !p->isConnected()) {
                return {StatusCode::UnconnectedPort,
                        "port '" + c->name() + "." + pname + "' in system '" + name() +
                            "' is required but not connected",
                        c->modelPath()};
            }
            auto partnerless = [&](Port* port) -> bool {
                int nPower = 0;
                for (Port* q : port->node()->ports())
                    if (q->kind() == PortKind::Power) ++nPower;
                return port->isConnected() && nPower == 1 && port->connectedPorts.size() > 0;
            };
            Port* lonely = nullptr;
            if (p->isMultiport()) {
                for (auto& sub : p->subPorts)
                    if (!lonely && partnerless(sub.get())) lonely = sub.get();
            } else if (p->node() && partnerless(p)) {
                lonely = p;
            }
            if (lonely) {
                return {StatusCode::IllegalConnection,
                        "port '" + c->name() + "." + lonely->name() + "' in system '" + name() +
                            "' is on a node with a single power port (a power port needs a partner)",
                        c->modelPath()};
            }
        }
        if (c->isSystem()) {
            Status sub = static_cast<System*>(c)->checkStructure();
            if (!sub) return sub;
        }
    }
    return Status::ok();
}

void System::buildRunLists()
{
    mS.clear();
    mC.clear();
    mQ.clear();
    mDisabled.clear();
    for (Component* c : mOrder) {
        if (c->isDisabled()) {
            mDisabled.push_back(c);
            continue;
        }
        switch (c->kind()) {
        case CqsKind::S: mS.push_back(c); break;
        case CqsKind::C: mC.push_back(c); break;
        case CqsKind::Q: mQ.push_back(c); break;
        default: mS.push_back(c); break;
        }
    }
}

void System::computeSortHintsOfSystemPorts()
{
    for (Port* sp : ports()) {
        if (sp->kind() != PortKind::System) continue;
        SortHint hint = SortHint::None;
        PortKind innerKind = PortKind::Undefined;
        bool anyPower = false;
        for (Port* q : sp->connectedPorts) {
            if (q->component() == this || q->component()->parentSystem() != this) continue;
            SortHint h = effectiveSortHint(q);
            if (h == SortHint::Source) hint = SortHint::Source;
            else if (h == SortHint::Destination && hint != SortHint::Source) hint = SortHint::Destination;
            if (q->kind() == PortKind::Power || q->kind() == PortKind::PowerMultiport) anyPower = true;
            innerKind = q->kind();
        }
        sp->internalSortHint = hint;
        sp->internalPortKind = anyPower ? PortKind::Power : innerKind;
    }
}

Status System::sortList(std::vector<Component*>& list, bool failOnLoop)
{
    std::vector<Component*> sorted;
    sorted.reserve(list.size());
    std::set<Component*> inList(list.begin(), list.end());
    std::set<Component*> placed;
    bool progress = true;
    while (progress) {
        progress = false;
        for (Component* comp : list) {
            if (placed.count(comp)) continue;
            bool ready = true;
            for (const auto& [pname, port] : comp->portsByName()) {
                if (effectiveSortHint(port) != SortHint::Destination || !port->isConnected()) continue;
                std::vector<Node*> nodes;
                if (port->isMultiport())
                    for (auto& sub : port->subPorts) nodes.push_back(sub->node());
                else
                    nodes.push_back(port->node());
                for (Node* n : nodes) {
                    Port* src = nullptr;
                    for (Port* q : n->ports())
                        if (q->sortHint == SortHint::Source) {
                            src = q;
                            break;
                        }
                    if (!src) continue;
                    Component* r = src->component();
                    if (r->parentSystem() == this) {
                        if (inList.count(r) && !placed.count(r)) ready = false;
                    } else {
                        Component* p = r->parentSystem();
                        if (p && inList.count(p) && !placed.count(p) && p->kind() == comp->kind())
                            ready = false;
                    }
                }
                if (!ready) break;
            }
            if (ready) {
                sorted.push_back(comp);
                placed.insert(comp);
                progress = true;
            }
        }
    }
    if (sorted.size() < list.size()) {
        if (failOnLoop) {
            std::string names;
            for (Component* c : list)
                if (!placed.count(c)) names += (names.empty() ? "" : ", ") + c->name();
            return {StatusCode::AlgebraicLoop,
                    "algebraic loop among signal components in system '" + name() + "': " + names, modelPath()};
        }
        return Status::ok();
    }
    list = std::move(sorted);
    return Status::ok();
}

// System parameters first: the components' values may refer to them.
Status System::evaluateParameters(ParameterEvaluator::Pass& pass)
{
    for (const auto& param : parameters().all()) {
        const Status evaluated = ParameterEvaluator::evaluate(*this, *param, pass);
        if (!evaluated)
            return {StatusCode::InvalidParameter,
                    "system parameter '" + param->name + "' of '" + name() + "': " + evaluated.message(),
                    evaluated.path()};
    }
    for (Component* c : mOrder) {
        if (c->isSystem()) {
            if (Status evaluated = static_cast<System*>(c)->evaluateParameters(pass); !evaluated) return evaluated;
            continue;
        }
        for (const auto& param : c->parameters().all()) {
            const Status evaluated = ParameterEvaluator::evaluate(*c, *param, pass);
            if (!evaluated)
                return {StatusCode::InvalidParameter,
                        "parameter '" + param->name + "' of '" + c->name() + "': " + evaluated.message(),
                        evaluated.path()};
        }
    }
    return Status::ok();
}

namespace {

void copyStartNode(Port* p, Node* n)
{
    if (!n || n->size() != p->startValues.size()) return;
    double* d = n->data();
    for (std::size_t i = 0; i < p->startValues.size(); ++i) d[i] = p->startValues[i];
    for (const auto& [wave, intensity] : nodeTypeInfo(n->type()).tlmCopyRule) d[wave] = d[intensity];
}

void loadPortStartValues(Port* p)
{
    if (!p->hasStartNode()) return;
    switch (p->kind()) {
    case PortKind::Power:
    case PortKind::Write:
        copyStartNode(p, p->node());
        break;
    case PortKind::PowerMultiport:
        for (auto& sub : p->subPorts) copyStartNode(p, sub->node());
        break;
    case PortKind::Read:
        if (!p->isConnected()) copyStartNode(p, p->node());
        break;
    case PortKind::System:
        copyStartNode(p, p->node());
        break;
    default: break;
    }
}

} // namespace

void System::loadStartValues()
{
    // Subsystems walk their unsorted lists, disabled components included (core.md §3.4).
    std::vector<Component*> s, c, q, dis;
    if (isRoot()) {
        s = mS;
        c = mC;
        q = mQ;
        dis = mDisabled;
    } else {
        for (Component* comp : mOrder) {
            switch (comp->kind()) {
            case CqsKind::C: c.push_back(comp); break;
            case CqsKind::Q: q.push_back(comp); break;
            default: s.push_back(comp); break;
            }
        }
    }
    for (auto* list : {&s, &c, &q, &dis}) {
        for (Component* comp : *list) {
            if (comp->isSystem()) {
                static_cast<System*>(comp)->loadStartValues();
                continue;
            }
            for (const auto& [pname, p] : comp->portsByName()) loadPortStartValues(p);
        }
    }
    for (const auto& [pname, p] : portsByName()) {
        if (p->kind() == PortKind::Read) {
            bool drivenFromOutside = false;
            for (Port* other : p->connectedPorts)
                if (other->kind() == PortKind::Write || other->kind() == PortKind::Power ||
                    other->kind() == PortKind::PowerMultiport)
                    drivenFromOutside = true;
            if (!drivenFromOutside && p->hasStartNode()) copyStartNode(p, p->node());
        } else if (p->hasStartNode()) {
            copyStartNode(p, p->node());
        }
    }
}

void System::computeLogSchedule(double t0, double t1)
{
    mLogSteps.clear();
    mLogCounter = 0;
    const double Ts = mTimestep;
    double ts = std::max(t0, logStartTime);
    if (ts > t1) ts = t1;
    const double avail = (t1 - ts) / Ts + 1.0;
    const std::size_t N = requestedLogSamples;
    std::size_t nSlots = avail < static_cast<double>(N) ? static_cast<std::size_t>(avail) : N;
    if (nSlots == 0) {
        mLogTime.clear();
        return;
    }
    const double ls = std::max(t0, logStartTime);
    const double dtLog = (t1 - ls) / static_cast<double>(nSlots - 1);
    double logT = ls;
    double simT = t0;
    std::size_t k = roundSteps((logT - simT) / Ts);
    mLogSteps.reserve(nSlots);
    mLogSteps.push_back(k);
    simT = simT + static_cast<double>(k) * Ts;
    while (mLogSteps.size() < nSlots) {
        logT = logT + dtLog;
        k = roundSteps((logT - simT) / Ts);
        simT = simT + static_cast<double>(k) * Ts;
        mLogSteps.push_back(mLogSteps.back() + k);
    }
    mLogTime.assign(nSlots, 0.0);
}

void System::allocateLogStorage()
{
    mLoggedNodes.clear();
    std::set<Node*> seen;
    auto consider = [&](Port* p) {
        Node* n = p->node();
        if (!n || !seen.insert(n).second) return;
        if (nodeOwner(n) != this) return;
        n->logOwner = this;
        const auto& ps = n->ports();
        bool wants = false;
        for (Port* q : ps) wants = wants || q->wantsLogging;
        const bool loneInput = ps.size() < 2 && (ps.empty() || ps.front()->kind() == PortKind::Read);
        if (loneInput || !wants || mLogSteps.empty() || n->size() == 0) {
            n->logData.clear();
            return;
        }
        mLoggedNodes.push_back(n);
    };
    for (Component* c : mOrder) {
        for (Port* p : c->ports()) {
            if (p->isMultiport())
                for (auto& sub : p->subPorts) consider(sub.get());
            else
                consider(p);
        }
    }
    for (Port* p : ports())
        if (!p->isMultiport()) consider(p);

    // One row per log step: the logged nodes' values side by side. Nodes whose data lie
    // next to each other in the node block (most of them, both being in model order) are
    // copied by one run.
    mLogRowSize = 0;
    mLogCopies.clear();
    for (Node* n : mLoggedNodes) {
        if (!mLogCopies.empty() && mLogCopies.back().from + mLogCopies.back().count == n->data())
            mLogCopies.back().count += n->size();
        else
            mLogCopies.push_back({n->data(), n->size()});
        mLogRowSize += n->size();
    }
    mLogArena.reserve(mLogSteps.size() * mLogRowSize);
    std::size_t offset = 0;
    for (Node* n : mLoggedNodes) {
        n->logData.assign(mLogArena.data() + offset, mLogRowSize, mLogSteps.size());
        offset += n->size();
    }
}

void System::logSample()
{
    if (mLogCounter >= mLogSteps.size() || mLogSteps[mLogCounter] != mTakenSteps) return;
    mLogTime[mLogCounter] = mTime;
    double* row = mLogArena.data() + mLogCounter * mLogRowSize;
    for (const LogCopy& copy : mLogCopies) {
        std::copy(copy.from, copy.from + copy.count, row);
        row += copy.count;
    }
    ++mLogCounter;
}

void System::propagateTimestep()
{
    for (auto* list : {&mS, &mC, &mQ}) {
        for (Component* c : *list) {
            if (c->isSystem()) {
                auto* sub = static_cast<System*>(c);
                double ts = mTimestep;
                if (!sub->inheritTimestep) ts = sub->desiredTimestep > 0.0 ? sub->desiredTimestep : mTimestep;
                sub->setTimestep(ts);
            } else {
                c->setTimestep(mTimestep);
            }
        }
    }
}

namespace {

void collectNodes(System& s, std::vector<Node*>& out, std::set<Node*>& seen)
{
    auto take = [&](Port* p) {
        if (p->isMultiport()) {
            for (auto& sub : p->subPorts)
                if (seen.insert(sub->node()).second) out.push_back(sub->node());
        } else if (p->node() && seen.insert(p->node()).second) {
            out.push_back(p->node());
        }
    };
    for (Port* p : s.ports()) take(p);
    for (Component* c : s.componentsInOrder()) {
        for (Port* p : c->ports()) take(p);
        if (c->isSystem()) collectNodes(*static_cast<System*>(c), out, seen);
    }
}

} // namespace

// Move every node's data into one contiguous block, in component order, so the step loop
// walks memory mostly forwards. Pointers are bound after this, in initialize().
void System::packNodeData()
{
    std::vector<Node*> nodes;
    std::set<Node*> seen;
    collectNodes(*this, nodes, seen);
    std::size_t total = 0;
    for (Node* n : nodes) total += n->size();
    std::vector<double> arena(total);
    std::size_t offset = 0;
    for (Node* n : nodes) {
        n->relocate(arena.data() + offset);   // copies from the old block, still alive here
        offset += n->size();
    }
    mNodeArena.swap(arena);
}

std::vector<Node*> System::allNodes()
{
    std::vector<Node*> nodes;
    std::set<Node*> seen;
    collectNodes(*this, nodes, seen);
    return nodes;
}

Status System::initialize(double t0, double t1, ParameterEvaluation evaluation)
{
    mStopRequested.store(false);
    if (isRoot()) {
        packNodeData();
        mTimestep = desiredTimestep;
        startTime = t0;
        stopTime = t1;
    }
    if (isRoot()) {
        mRandom.reseed(1);
        mDrawsRandomNumbers = false;
    }
    return initializeInternal(t0, t1, evaluation);
}

Status System::initializeInternal(double t0, double t1, ParameterEvaluation evaluation)
{
    buildRunLists();
    System* root = rootSystem();
    if (isRoot()) {
        for (auto* list : {&mS, &mC, &mQ})
            for (Component* c : *list) c->preInitialize();
    }
    mTime = t0;
    mTakenSteps = 0;
    if (mTimestep < 10.0 * DBL_MIN) {
        addErrorMessage("time step too low");
        return {StatusCode::InvalidSettings, "time step too low", modelPath()};
    }
    computeLogSchedule(t0, t1);
    allocateLogStorage();
    propagateTimestep();
    for (auto* list : {&mS, &mC, &mQ})
        for (Component* c : *list)
            if (c->isSystem()) static_cast<System*>(c)->computeSortHintsOfSystemPorts();
    if (const Status sorted = sortList(mS, true); !sorted) {
        root->postMessage({MessageType::Error, sorted.message(), "AlgebraicLoop", sorted.path()});
        return sorted;
    }
    sortList(mC, false);
    sortList(mQ, false);
    if (isRoot()) {
        if (evaluation == ParameterEvaluation::Evaluate) {
            ParameterEvaluator::Pass pass;
            if (const Status evaluated = evaluateParameters(pass); !evaluated) {
                root->postMessage({MessageType::Error, evaluated.message(), "Parameter", evaluated.path()});
                return evaluated;
            }
        }
        loadStartValues();
    }
    for (auto* list : {&mS, &mC, &mQ}) {
        for (Component* c : *list) {
            c->bindAutoVariables();
            if (c->isSystem()) {
                auto* sub = static_cast<System*>(c);
                sub->requestedLogSamples = requestedLogSamples;
                sub->logStartTime = logStartTime;
                if (Status started = sub->initializeInternal(t0, t1, evaluation); !started) {
                    root->requestStop();
                    return started;
                }
            } else {
                c->mTime = t0;
                c->initialize();
            }
            if (root->stopRequested()) return root->initFailure(*c);
        }
    }
    if (mOnPort) bindAutoVariables();
    // Only now is it known whether anything draws random numbers (components take the
    // stream in initialize()), and subsystems initialise inside this loop.
    if (isRoot()) buildStepBatches(mDrawsRandomNumbers ? StepBatches::Order::Keep : StepBatches::Order::Regroup);
    logSample();
    return Status::ok();
}

void System::buildStepBatches(StepBatches::Order order)
{
    mBatchS = StepBatches(mS, order);
    mBatchC = StepBatches(mC, order);
    mBatchQ = StepBatches(mQ, order);
    for (auto* list : {&mS, &mC, &mQ})
        for (Component* c : *list)
            if (c->isSystem()) static_cast<System*>(c)->buildStepBatches(order);
}

// A component that stopped the simulation in its initialize(): its first error is the reason.
Status System::initFailure(const Component& c) const
{
    const std::string path = c.modelPath();
    for (const Message& m : mMessages)
        if ((m.type == MessageType::Error || m.type == MessageType::Fatal) && m.source == path)
            return {StatusCode::InitFailed, m.text, path};
    return {StatusCode::InitFailed, "'" + c.name() + "' stopped the simulation while initialising", path};
}




void System::stepOnce()
{
    const double t = mTime;
    mBatchS.step(t);
    mBatchC.step(t);
    mBatchQ.step(t);
    ++mTakenSteps;
    logSample();
}

void System::simulateTo(double parentTime)
{
    const std::size_t n = roundSteps(std::max(parentTime - mTime, 0.0) / mTimestep);
    for (std::size_t i = 0; i < n; ++i) {
        mTime += mTimestep;
        if (mpOn && !(*mpOn > 0.0)) {
            // Frozen: only time advances and nodes are logged.
            ++mTakenSteps;
            logSample();
            continue;
        }
        stepOnce();
    }
}

std::size_t System::stepsUntil(double tStop) const
{
    return roundSteps(std::max(tStop - mTime, 0.0) / mTimestep);
}

bool System::simulate(double tStop) { return simulateSteps(stepsUntil(tStop)); }

bool System::simulateSteps(std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i) {
        if (interrupted()) break;
        mTime += mTimestep;
        stepOnce();
        if (mProgress && mProgressInterval && (i + 1) % mProgressInterval == 0)
            mProgress(mProgressUser, i + 1, n);
    }
    return !stopRequested();
}

void System::postMessage(Message m)
{
    System* root = rootSystem();
    std::lock_guard<std::mutex> lock(root->mMessagesMutex);
    root->mMessages.push_back(std::move(m));
}

void System::finalize()
{
    for (auto* list : {&mS, &mC, &mQ}) {
        for (Component* c : *list) c->finalize();
    }
    // Disabled components go back to the end of the insertion order (core.md §3.6).
    for (Component* c : mDisabled) moveToEnd(c);
}

} // namespace tlmhub
