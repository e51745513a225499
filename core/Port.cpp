#include "core/Port.h"

#include "core/Node.h"

#include <algorithm>

namespace tlmhub {

const char* portKindName(PortKind kind)
{
    switch (kind) {
    case PortKind::Power: return "PowerPort";
    case PortKind::BiDirectionalSignal: return "BiDirectionalSignalPort";
    case PortKind::Read: return "ReadPort";
    case PortKind::Write: return "WritePort";
    case PortKind::System: return "SystemPort";
    case PortKind::Multiport: return "MultiPort";
    case PortKind::PowerMultiport: return "PowerMultiPort";
    case PortKind::ReadMultiport: return "ReadMultiPort";
    default: return "UndefinedPort";
    }
}

Port::Port(std::string name, PortKind kind, NodeType nodeType, Component* owner)
    : mName(std::move(name)), mKind(kind), mNodeType(nodeType), mOwner(owner)
{
    if (!isMultiport()) resetNode();
    if (kind == PortKind::Read || kind == PortKind::ReadMultiport) sortHint = SortHint::Destination;
    if (kind == PortKind::Write) sortHint = SortHint::Source;
    if (isMultiport()) wantsLogging = false;
}

Port::~Port()
{
    if (mNode) mNode->detach(this);
}

void Port::setNode(std::shared_ptr<Node> node)
{
    if (mNode) mNode->detach(this);
    mNode = std::move(node);
    if (mNode) mNode->attach(this);
}

void Port::resetNode()
{
    setNode(std::make_shared<Node>(mNodeType));
}

void Port::setNodeType(NodeType type)
{
    mNodeType = type;
    resetNode();
}

void Port::createStartNode()
{
    const auto& vars = nodeTypeInfo(mNodeType).variables;
    startValues.resize(vars.size());
    for (std::size_t i = 0; i < vars.size(); ++i) startValues[i] = vars[i].createdValue;
}

Port* Port::addSubPort()
{
    PortKind subKind = mKind == PortKind::PowerMultiport ? PortKind::Power : PortKind::Read;
    auto sub = std::make_unique<Port>(mName, subKind, mNodeType, mOwner);
    sub->parentMultiport = this;
    sub->wantsLogging = false;
    sub->sortHint = sortHint;
    subPorts.push_back(std::move(sub));
    return subPorts.back().get();
}

void Port::removeSubPort(Port* sub)
{
    subPorts.erase(std::remove_if(subPorts.begin(), subPorts.end(),
                                  [sub](const auto& p) { return p.get() == sub; }),
                   subPorts.end());
}

} // namespace tlmhub
