#include "core/Node.h"

#include <algorithm>
#include <cstring>

namespace tlmhub {

Node::Node(NodeType type)
    : mType(type), mSize(nodeSize(type)), mOwnData(mSize), mData(mOwnData.data())
{
    resetToCreatedValues();
}

void Node::resetToCreatedValues()
{
    const auto& vars = nodeTypeInfo(mType).variables;
    for (std::size_t i = 0; i < mSize; ++i) mData[i] = vars[i].createdValue;
}

void Node::relocate(double* storage)
{
    if (mSize) std::memcpy(storage, mData, mSize * sizeof(double));
    mData = storage;
}

void Node::attach(Port* port)
{
    if (std::find(mPorts.begin(), mPorts.end(), port) == mPorts.end()) mPorts.push_back(port);
}

void Node::detach(Port* port)
{
    mPorts.erase(std::remove(mPorts.begin(), mPorts.end(), port), mPorts.end());
}

} // namespace tlmhub
