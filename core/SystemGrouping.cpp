// Grouping components into a new subsystem, and ungrouping a subsystem into its parent.
// Both rewire the existing connections in place rather than disconnecting and connecting
// again: the nodes, the multiports' sub-ports and every port's connection order stay as
// they were, and a system port is a pass-through into the same node (core.md §2.7), so a
// grouped model simulates exactly as before.
#include "core/System.h"

#include "core/Node.h"
#include "core/hmf/PreservedXml.h"

#include <algorithm>
#include <deque>
#include <map>
#include <set>

namespace tlmhub {

namespace {

// The ports of a component that hold connections: a multiport's sub-ports stand for it.
std::vector<Port*> connectionEnds(const Component& c)
{
    std::vector<Port*> out;
    for (Port* p : c.ports()) {
        if (p->isMultiport())
            for (const auto& sub : p->subPorts) out.push_back(sub.get());
        else
            out.push_back(p);
    }
    return out;
}

// Replaces `from` in `list` by `to` (possibly nothing), where `from` stood.
void replaceConnection(std::vector<Port*>& list, Port* from, const std::vector<Port*>& to)
{
    auto it = std::find(list.begin(), list.end(), from);
    if (it == list.end()) return;
    it = list.erase(it);
    list.insert(it, to.begin(), to.end());
}

// The port whose name and start values a (sub-)port uses.
Port* namedPort(Port* p) { return p->parentMultiport ? p->parentMultiport : p; }

// Copies the start value strings of port `from` to port `to` (same node type); the
// numbers are evaluated from them at the next initialise.
void copyStartValues(const Port* from, Port* to)
{
    if (!from->hasStartNode() || !to->hasStartNode()) return;
    to->startValues = from->startValues;
    for (const auto& v : nodeTypeInfo(to->nodeType()).variables) {
        std::string var = "#";
        var += v.name;
        const Parameter* src = from->component()->parameters().find(from->name() + var);
        Parameter* dst = to->component()->parameters().find(to->name() + var);
        if (src && dst) dst->value = src->value;
    }
}

bool isPowerPort(const Port* p)
{
    return p->kind() == PortKind::Power || p->kind() == PortKind::PowerMultiport;
}

std::string listNames(const std::set<std::string>& names)
{
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

// The components of `system` that the sort (core.md §3.3) must place after `c`: those
// reading, through a Destination port, a node that `c` writes through a Source port.
std::vector<const Component*> readersOf(const System& system, const Component& c)
{
    auto hint = [](const Port* p) { return p->kind() == PortKind::System ? p->internalSortHint : p->sortHint; };
    std::vector<const Component*> out;
    for (Port* p : connectionEnds(c)) {
        if (hint(p) != SortHint::Source) continue;
        for (const Port* r : p->node()->ports())
            if (r->component() != &c && r->component()->parentSystem() == &system && hint(r) == SortHint::Destination)
                out.push_back(r->component());
    }
    return out;
}

// Whether a group of `kind` would sit in a signal loop: a path from the selection through
// other components of the same run list back into it, which the sort could not order.
// Returns the first component on such a path, or null.
const Component* loopThrough(const System& system, const std::vector<Component*>& chosen,
                             const std::set<const Component*>& selected, CqsKind kind)
{
    for (const Component* start : chosen)
        for (const Component* first : readersOf(system, *start)) {
            if (selected.count(first) || first->kind() != kind) continue;
            std::set<const Component*> seen{first};
            std::deque<const Component*> todo{first};
            while (!todo.empty()) {
                const Component* c = todo.front();
                todo.pop_front();
                for (const Component* next : readersOf(system, *c)) {
                    if (selected.count(next)) return first;
                    if (next->kind() == kind && seen.insert(next).second) todo.push_back(next);
                }
            }
        }
    return nullptr;
}

// A connection from a selected component to one outside the selection, and what replaces
// it. The ports of one node that are connected without crossing the boundary form a
// "piece"; each piece joins the node's system port once, so the connections stay a tree
// (core.md §2.5 rejects joining a node with itself) and nothing else is lost.
struct Crossing {
    Port* inside;
    Port* outside;
    std::size_t boundaryNode;   // index of the node, and of its system port
    bool insideJoins;           // the inside end is connected to the system port
    bool outsideJoins;          // the outside end is connected to the system port
};

Status refuseGrouping(std::string reason) { return {StatusCode::IllegalGrouping, std::move(reason)}; }

} // namespace

Result<std::string> System::group(const std::vector<std::string>& names, const std::string& subsystemName)
{
    // ---- what is selected
    if (names.empty()) return refuseGrouping("nothing is selected to group");
    std::set<const Component*> selected;
    for (const std::string& n : names) {
        Component* c = component(n);
        if (!c) {
            if (systemPort(n))
                return refuseGrouping("'" + n + "' is a system port of '" + name() + "'; only components can be grouped");
            return Status{StatusCode::NotFound, "no component named '" + n + "' in system '" + name() + "'"};
        }
        if (!selected.insert(c).second) return refuseGrouping("'" + n + "' is selected twice");
    }
    std::vector<Component*> chosen;   // in this system's order
    for (Component* c : mOrder)
        if (selected.count(c)) chosen.push_back(c);

    // ---- the boundary: crossing connections, one system port per node
    // Only connections made in this system count; a selected subsystem's system ports are
    // also connected to its own content.
    auto visible = [this](const Port* p) { return p->component() == this || p->component()->parentSystem() == this; };
    std::map<const Port*, int> pieceOf;
    int pieces = 0;
    auto piece = [&](Port* start) {
        if (auto it = pieceOf.find(start); it != pieceOf.end()) return it->second;
        const bool side = selected.count(start->component()) > 0;
        const int id = pieces++;
        std::deque<Port*> todo{start};
        pieceOf[start] = id;
        while (!todo.empty()) {
            Port* p = todo.front();
            todo.pop_front();
            for (Port* q : p->connectedPorts)
                if (visible(q) && (selected.count(q->component()) > 0) == side && pieceOf.emplace(q, id).second)
                    todo.push_back(q);
        }
        return id;
    };
    std::vector<Crossing> crossings;
    std::vector<Port*> boundaryNodes;   // one inside port of each node
    std::map<const Node*, std::size_t> boundaryIndex;
    std::set<int> joined;
    std::vector<const Port*> innerInterface;
    for (Component* c : chosen)
        for (Port* p : connectionEnds(*c))
            for (Port* q : p->connectedPorts) {
                if (!visible(q) || selected.count(q->component())) continue;
                auto [at, added] = boundaryIndex.emplace(p->node(), boundaryNodes.size());
                if (added) boundaryNodes.push_back(p);
                Crossing x{p, q, at->second, joined.insert(piece(p)).second, joined.insert(piece(q)).second};
                if (x.insideJoins) innerInterface.push_back(p);
                // Hopsan gives a C-type subsystem's power system port a start node only when
                // an inner *power* port attaches to it; a subsystem port in its place would
                // silently drop this system's start values.
                if (q->component() == this && kind() == CqsKind::C && isPowerPort(p)) {
                    return refuseGrouping("'" + c->name() + "' is connected to the power system port '" +
                                          q->name() + "' of C-type system '" + name() +
                                          "', whose start values grouping would drop");
                }
                crossings.push_back(x);
            }

    const CqsKind newKind = interfaceKind(innerInterface);
    if (newKind == CqsKind::Undefined) {
        std::set<std::string> cs, qs;
        for (const Port* p : innerInterface) {
            if (p->kind() != PortKind::Read && p->kind() != PortKind::Write) {
                if (p->component()->kind() == CqsKind::C) cs.insert(p->component()->name());
                if (p->component()->kind() == CqsKind::Q) qs.insert(p->component()->name());
            }
        }
        return refuseGrouping("the subsystem would have an undefined C/Q/S kind: its system ports would lead to "
                              "both C-type (" + listNames(cs) + ") and Q-type (" + listNames(qs) +
                              ") components; select components so that the connections leaving the group are "
                              "all from C-type or all from Q-type ones");
    }

    if (const Component* c = loopThrough(*this, chosen, selected, newKind)) {
        return refuseGrouping("the subsystem would be in a signal loop through '" + c->name() +
                              "', which feeds back into it (no order of the components could run it); select '" +
                              c->name() + "' too, or fewer components");
    }

    // ---- build the subsystem (nothing below can fail)
    auto owned = std::make_unique<System>();
    System& sub = *owned;
    sub.setNameRaw(subsystemName.empty() ? "Subsystem" : subsystemName);
    sub.desiredTimestep = desiredTimestep;
    sub.requestedLogSamples = requestedLogSamples;
    sub.logStartTime = logStartTime;
    const std::size_t position =
        static_cast<std::size_t>(std::find(mOrder.begin(), mOrder.end(), chosen.front()) - mOrder.begin());
    for (Component* c : chosen) sub.insertComponent(releaseComponent(c), sub.mOrder.size());
    const std::string actual = insertComponent(std::move(owned), position);

    std::vector<Port*> systemPorts;
    for (Port* inner : boundaryNodes) {
        Port* sp = sub.addSystemPort(namedPort(inner)->name());
        sp->setNodeType(inner->nodeType());
        sp->setNode(inner->sharedNode());
        systemPorts.push_back(sp);
    }
    for (const Crossing& x : crossings) {
        Port* sp = systemPorts[x.boundaryNode];
        replaceConnection(x.inside->connectedPorts, x.outside, x.insideJoins ? std::vector{sp} : std::vector<Port*>{});
        if (x.insideJoins) sp->connectedPorts.push_back(x.inside);
        replaceConnection(x.outside->connectedPorts, x.inside, x.outsideJoins ? std::vector{sp} : std::vector<Port*>{});
        if (x.outsideJoins) sp->connectedPorts.push_back(x.outside);
    }
    sub.determineKind();
    // A C-type subsystem's port start values overwrite the inner ones (core.md §3.4 step 2):
    // start them as the inner port's, so the run starts where it did.
    for (const Crossing& x : crossings)
        if (x.insideJoins && isPowerPort(x.inside))
            copyStartValues(namedPort(x.inside), systemPorts[x.boundaryNode]);
    for (System* s = this; s; s = s->parentSystem()) s->determineKind();

    // Aliases and connection extras of the moved components go with them. The extras of a
    // cut connection match no connection in the subsystem (so they are not saved), but
    // ungroup() puts them back with the connection.
    auto isMoved = [&sub](const std::string& n) { return sub.component(n) != nullptr; };
    for (auto it = aliases.begin(); it != aliases.end();) {
        if (isMoved(it->second.substr(0, it->second.find('#')))) {
            sub.aliases.insert(*it);
            it = aliases.erase(it);
        } else {
            ++it;
        }
    }
    for (auto it = connectionExtras.begin(); it != connectionExtras.end();) {
        const preserved::ConnectionKeyParts k = preserved::parseConnectionKey(it->first);
        const bool a = isMoved(k.a), b = isMoved(k.b);
        if (a || b) {
            sub.connectionExtras.insert(*it);
            it = connectionExtras.erase(it);
        } else {
            ++it;
        }
    }
    return actual;
}

Result<std::vector<std::string>> System::ungroup(const std::string& subsystemName)
{
    System* sub = subsystem(subsystemName);
    if (!sub) return Status{StatusCode::NotFound, "no subsystem named '" + subsystemName + "' in system '" + name() + "'"};
    if (!sub->externalPath.empty())
        return refuseGrouping("'" + subsystemName + "' is an external subsystem; its content belongs to '" +
                              sub->externalPath + "'");
    if (sub->isConditional())
        return refuseGrouping("'" + subsystemName + "' is a conditional subsystem; its content would no longer "
                              "depend on its 'on' input");
    if (!sub->inheritTimestep && sub->desiredTimestep != desiredTimestep)
        return refuseGrouping("'" + subsystemName + "' runs with its own time step; its content would run with the time step of '" +
                              name() + "'");
    // Its system parameters come here; one of the same name must be the same parameter.
    for (const auto& p : sub->parameters().all()) {
        if (p->isStartValue) continue;
        if (const Parameter* mine = parameters().find(p->name)) {
            if (mine->value != p->value || mine->type != p->type) {
                return refuseGrouping("system parameter '" + p->name + "' of '" + subsystemName +
                        "' differs from the one of the same name in '" + name() + "'");
            }
        } else if (isNameTaken(p->name)) {
            return refuseGrouping("the name of system parameter '" + p->name + "' of '" + subsystemName +
                    "' is already used in '" + name() + "'");
        }
    }
    for (const auto& [alias, full] : sub->aliases)
        if (aliases.count(alias)) {
            return refuseGrouping("alias '" + alias + "' of '" + subsystemName + "' is already used in '" + name() + "'");
        }

    // ---- nothing below can fail
    std::set<std::string> systemPorts;
    for (Port* sp : sub->ports()) {
        if (sp->kind() != PortKind::System) continue;
        systemPorts.insert(sp->name());
        std::vector<Port*> in, out;
        for (Port* q : sp->connectedPorts) (q->component()->parentSystem() == sub ? in : out).push_back(q);
        // The port's start values are the ones the run started with; keep them.
        for (Port* q : in)
            if (isPowerPort(q)) copyStartValues(sp, namedPort(q));
        if (!in.empty() && !out.empty()) {
            // The first inner end takes every outer connection, the other inner ends meet
            // the first outer end: the node stays one tree, and where group() had cut such
            // connections they come back in their places.
            replaceConnection(out.front()->connectedPorts, sp, in);
            for (std::size_t i = 1; i < out.size(); ++i) replaceConnection(out[i]->connectedPorts, sp, {in.front()});
            replaceConnection(in.front()->connectedPorts, sp, out);
            for (std::size_t i = 1; i < in.size(); ++i) replaceConnection(in[i]->connectedPorts, sp, {out.front()});
            sp->connectedPorts.clear();
        }
        // What is left is one open side; disconnecting it splits the node.
        sub->deleteSystemPort(sp->name());
    }

    const std::size_t position =
        static_cast<std::size_t>(std::find(mOrder.begin(), mOrder.end(), sub) - mOrder.begin());
    std::unique_ptr<Component> owned = releaseComponent(sub);
    for (const auto& p : sub->parameters().all()) {
        if (p->isStartValue || parameters().find(p->name)) continue;
        parameters().add(*p).bindOwnStorage();
    }
    std::map<std::string, std::string> renamed;
    std::vector<std::string> moved;
    const std::vector<Component*> inner = sub->mOrder;
    for (std::size_t i = 0; i < inner.size(); ++i) {
        const std::string old = inner[i]->name();
        const std::string now = insertComponent(sub->releaseComponent(inner[i]), position + i);
        renamed[old] = now;
        moved.push_back(now);
    }
    for (const auto& [alias, full] : sub->aliases) {
        const std::size_t hash = full.find('#');
        auto it = renamed.find(full.substr(0, hash));
        aliases[alias] = it == renamed.end() ? full : it->second + full.substr(hash);
    }
    // Connection extras: those of connections to the system ports go with them; the others
    // (cut by group() or made inside) come back with the moved components' new names.
    auto nameHere = [&renamed](const std::string& n) {
        auto it = renamed.find(n);
        return it == renamed.end() ? n : it->second;
    };
    for (const auto& [key, extras] : sub->connectionExtras) {
        const preserved::ConnectionKeyParts k = preserved::parseConnectionKey(key);
        if (systemPorts.count(k.a) || systemPorts.count(k.b)) continue;
        connectionExtras[preserved::connectionKey(nameHere(k.a), k.pa, nameHere(k.b), k.pb)] = extras;
    }
    for (System* s = this; s; s = s->parentSystem()) s->determineKind();
    return moved;
}

std::unique_ptr<Component> System::releaseComponent(Component* c)
{
    mOrder.erase(std::remove(mOrder.begin(), mOrder.end(), c), mOrder.end());
    auto it = mComponents.find(c->name());
    std::unique_ptr<Component> owned = std::move(it->second);
    mComponents.erase(it);
    owned->setParentSystem(nullptr);
    return owned;
}

} // namespace tlmhub
