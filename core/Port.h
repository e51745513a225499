#pragma once
// Ports: a component's connection points (core.md §2.2-2.4).
#include "core/NodeTypes.h"

#include <memory>
#include <string>
#include <vector>

namespace tlmhub {

class Component;
class Node;

// Enumeration order matters: "kind >= Multiport" means any multiport (core.md §2.2).
enum class PortKind {
    Undefined,
    Power,
    BiDirectionalSignal,
    Read,
    Write,
    System,
    Multiport,
    PowerMultiport,
    ReadMultiport
};

enum class SortHint { None, Source, Destination, IndependentDestination };

const char* portKindName(PortKind kind);

class Port {
public:
    Port(std::string name, PortKind kind, NodeType nodeType, Component* owner);
    ~Port();
    Port(const Port&) = delete;
    Port& operator=(const Port&) = delete;

    const std::string& name() const { return mName; }
    void setName(std::string name) { mName = std::move(name); }
    PortKind kind() const { return mKind; }
    NodeType nodeType() const { return mNodeType; }
    Component* component() const { return mOwner; }
    bool isMultiport() const { return mKind >= PortKind::Multiport; }

    // The node this port reads and writes. Never null for non-multiports.
    Node* node() const { return mNode.get(); }
    const std::shared_ptr<Node>& sharedNode() const { return mNode; }
    void setNode(std::shared_ptr<Node> node);
    // Give the port a fresh private node of its type (after disconnect / on creation).
    void resetNode();
    // Change the node type (system ports adopt the type of what they connect to).
    void setNodeType(NodeType type);

    // Ports this one is directly connected to.
    std::vector<Port*> connectedPorts;
    bool isConnected() const { return !connectedPorts.empty() || !subPorts.empty(); }

    bool required = true;
    SortHint sortHint = SortHint::None;
    std::string description;
    bool wantsLogging = true;

    // Start node (holds start values; core.md §2.3); empty if the port has none.
    std::vector<double> startValues;
    bool hasStartNode() const { return !startValues.empty(); }
    void createStartNode();
    void removeStartNode() { startValues.clear(); }

    // Multiport: one sub-port per connection, in connection order.
    std::vector<std::unique_ptr<Port>> subPorts;
    Port* parentMultiport = nullptr;
    Port* addSubPort();
    void removeSubPort(Port* sub);

    // Signal label applied on load (`signalquantity`).
    std::string signalQuantity;

    // For system ports: internal sort hint / internal port kind (core.md §2.7).
    SortHint internalSortHint = SortHint::None;
    PortKind internalPortKind = PortKind::Undefined;

private:
    std::string mName;
    PortKind mKind;
    NodeType mNodeType;
    Component* mOwner;
    std::shared_ptr<Node> mNode;
};

} // namespace tlmhub
