#include "core/SystemConnections.h"

#include "core/hmf/PreservedXml.h"

#include <set>
#include <utility>
#include <vector>

namespace tlmhub {

void forEachConnection(const System& s, const std::function<void(const SystemConnection&)>& visit)
{
    auto nameOf = [&s](const Port* p) { return p->component() == &s ? p->name() : p->component()->name(); };
    // Only connections made in this system (both ends visible from here).
    auto visible = [&s](const Port* p) { return p->component() == &s || p->component()->parentSystem() == &s; };
    std::set<std::pair<const Port*, const Port*>> seen;
    auto emit = [&](const Port* a, const Port* b) {
        if (seen.count({b, a}) || seen.count({a, b})) return;
        const Port* pa = a->parentMultiport ? a->parentMultiport : a;
        const Port* pb = b->parentMultiport ? b->parentMultiport : b;
        if (!visible(pa) || !visible(pb)) return;
        seen.insert({a, b});
        const ConnectionExtras* extras = nullptr;
        auto it = s.connectionExtras.find(preserved::connectionKey(nameOf(pa), pa->name(), nameOf(pb), pb->name()));
        if (it == s.connectionExtras.end()) {
            it = s.connectionExtras.find(preserved::connectionKey(nameOf(pb), pb->name(), nameOf(pa), pa->name()));
            if (it != s.connectionExtras.end()) std::swap(pa, pb);
        }
        if (it != s.connectionExtras.end()) extras = &it->second;
        visit({nameOf(pa), pa->name(), nameOf(pb), pb->name(), extras});
    };
    // By connection order of the ports: the sub-components' in insertion order, then the
    // system's own system ports.
    std::vector<const Port*> ports;
    for (Component* c : s.componentsInOrder())
        for (Port* p : c->ports()) {
            if (p->isMultiport())
                for (const auto& sub : p->subPorts) ports.push_back(sub.get());
            else
                ports.push_back(p);
        }
    for (Port* p : s.ports())
        if (p->kind() == PortKind::System) ports.push_back(p);
    // A multiport's connections come in the order of its sub-ports, which is the order they
    // were made in and matters to its equations: each is listed from the multiport's side.
    for (const Port* p : ports)
        for (const Port* q : p->connectedPorts)
            if (p->parentMultiport || !q->parentMultiport) emit(p, q);
}

} // namespace tlmhub
