#pragma once
// A run list (S, C or Q) as batches of components of one type, so a step makes one indirect
// call per batch instead of a virtual call per component, and each type's equations can be
// inlined into its batch loop (the way Box2D steps its solver data by type).
//
// Regrouping keeps what the list order means: members of one cluster (core/ComponentClusters.h)
// stay in list order, and only independent components change places. A model that draws from
// the shared random stream keeps its whole list order (the draws would change), and then
// only neighbours of one type share a batch.
#include "core/Component.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tlmhub {

class StepBatches {
public:
    enum class Order { Regroup, Keep };
    StepBatches() = default;
    StepBatches(const std::vector<Component*>& list, Order order);

    void step(double time) const
    {
        for (const Batch& b : mBatches) b.step(mComponents.data() + b.begin, b.count, time);
    }
    std::size_t batchCount() const { return mBatches.size(); }
    // The components in the order step() runs them.
    const std::vector<Component*>& components() const { return mComponents; }

private:
    struct Batch {
        BatchStepper step;
        std::uint32_t begin;
        std::uint32_t count;
    };
    std::vector<Component*> mComponents;
    std::vector<Batch> mBatches;
};

// The batch step of component type T: a direct call of T's equations per component.
template <typename T>
void stepBatchOf(Component* const* components, std::size_t count, double time)
{
    for (std::size_t i = 0; i < count; ++i) {
        T* c = static_cast<T*>(components[i]);
        c->mTime = time;
        c->T::simulateOneTimestep();
    }
}

} // namespace tlmhub
