#include "core/ComponentClusters.h"

#include "core/System.h"

#include <map>
#include <numeric>

namespace tlmhub {

std::vector<Node*> portNodes(Port* port)
{
    std::vector<Node*> nodes;
    if (port->isMultiport())
        for (auto& sub : port->subPorts) nodes.push_back(sub->node());
    else if (port->node())
        nodes.push_back(port->node());
    return nodes;
}

std::vector<std::size_t> linkedClusters(const std::vector<Component*>& list)
{
    std::vector<std::size_t> parent(list.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    std::map<const Component*, std::size_t> index;
    for (std::size_t i = 0; i < list.size(); ++i) index[list[i]] = i;
    for (std::size_t i = 0; i < list.size(); ++i) {
        for (Port* p : list[i]->ports()) {
            for (Node* n : portNodes(p)) {
                for (Port* q : n->ports()) {
                    const Component* owner = q->component();
                    while (owner && !index.count(owner)) owner = owner->parentSystem();
                    if (!owner) continue;
                    const std::size_t a = find(i), b = find(index[owner]);
                    if (a != b) parent[a] = b;
                }
            }
        }
    }
    std::vector<std::size_t> cluster(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) cluster[i] = find(i);
    return cluster;
}

} // namespace tlmhub
