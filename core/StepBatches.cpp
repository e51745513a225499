#include "core/StepBatches.h"

#include "core/ComponentClusters.h"

#include <algorithm>
#include <map>

namespace tlmhub {

// Regroup: a component's rank is its place among the members of its cluster (0 for a
// component linked to no other). Sorting stably by rank, then by type, keeps every
// cluster in list order (its members have rising ranks) and puts independent components
// of one type side by side: the 50 copies of a circuit become one batch per type and rank.
StepBatches::StepBatches(const std::vector<Component*>& list, Order order)
{
    std::vector<std::size_t> rank(list.size(), 0);
    std::map<BatchStepper, std::size_t> typeOrder;   // first appearance in the list
    if (order == Order::Regroup) {
        const std::vector<std::size_t> cluster = linkedClusters(list);
        std::map<std::size_t, std::size_t> membersSoFar;
        for (std::size_t i = 0; i < list.size(); ++i) rank[i] = membersSoFar[cluster[i]]++;
        for (const Component* c : list) typeOrder.emplace(c->batchStepper(), typeOrder.size());
    }
    std::vector<std::size_t> runOrder(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) runOrder[i] = i;
    if (order == Order::Regroup) {
        std::stable_sort(runOrder.begin(), runOrder.end(), [&](std::size_t a, std::size_t b) {
            if (rank[a] != rank[b]) return rank[a] < rank[b];
            return typeOrder[list[a]->batchStepper()] < typeOrder[list[b]->batchStepper()];
        });
    }
    for (std::size_t i : runOrder) {
        Component* c = list[i];
        const BatchStepper step = c->batchStepper();
        if (mBatches.empty() || mBatches.back().step != step)
            mBatches.push_back({step, static_cast<std::uint32_t>(mComponents.size()), 0});
        ++mBatches.back().count;
        mComponents.push_back(c);
    }
}

} // namespace tlmhub
