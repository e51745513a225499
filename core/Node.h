#pragma once
// A node: the data vector shared by every port of one connection group (core.md §1, §2.5).
#include "core/NodeTypes.h"

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace tlmhub {

class Port;
class System;

// One node's logged samples: a view into its system's LogArena, which stores a log step's
// values of all the system's logged nodes side by side (a row per sample), so logging a
// step writes one contiguous row.
class LogBuffer {
public:
    // `first`: this node's values in sample 0; `stride`: values per row.
    void assign(double* first, std::size_t stride, std::size_t samples)
    {
        mData = samples ? first : nullptr;
        mStride = stride;
        mSamples = samples;
    }
    void clear() { assign(nullptr, 0, 0); }
    bool empty() const { return mSamples == 0; }
    std::size_t samples() const { return mSamples; }
    double* sample(std::size_t slot) { return mData + slot * mStride; }
    double value(std::size_t slot, std::size_t variable) const { return mData[slot * mStride + variable]; }
    // Sample 0 of `variable`; sample i is `stride()` values further.
    const double* first(std::size_t variable) const { return mData + variable; }
    std::size_t stride() const { return mStride; }

private:
    double* mData = nullptr;
    std::size_t mStride = 0;
    std::size_t mSamples = 0;
};

class Node {
public:
    explicit Node(NodeType type);

    NodeType type() const { return mType; }
    std::size_t size() const { return mSize; }
    double* data() { return mData; }
    const double* data() const { return mData; }
    double value(int id) const { return mData[id]; }
    void setValue(int id, double v) { mData[id] = v; }
    void resetToCreatedValues();

    // Move the data into external storage (contiguous node arena); values are kept.
    void relocate(double* storage);

    const std::vector<Port*>& ports() const { return mPorts; }
    void attach(Port* port);
    void detach(Port* port);

    // Signal quantity/unit label (§1.5); label only.
    std::string signalQuantity;
    std::string signalUnit;

    // --- logging (§4) ---
    // Logged samples, each of size() values.
    LogBuffer logData;
    System* logOwner = nullptr;   // system whose time vector belongs to logData
    // Copies the current values into sample `slot` of logData.
    void logSample(std::size_t slot) { std::copy(mData, mData + size(), logData.sample(slot)); }

private:
    NodeType mType;
    std::size_t mSize;
    std::vector<double> mOwnData;
    double* mData;
    std::vector<Port*> mPorts;
};

} // namespace tlmhub
