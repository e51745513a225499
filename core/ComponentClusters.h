#pragma once
// Clusters of a run list (core.md §10): components of one list (S, C or Q) linked through a
// node, directly or through other members of the list, form one cluster. Within a cluster
// the list order matters (a signal one member writes, another reads in the same phase);
// members of different clusters never see each other's values within that phase, so whole
// clusters may run on different threads or be regrouped (core/StepBatches.h).
#include "core/Component.h"

#include <cstddef>
#include <vector>

namespace tlmhub {

// Nodes attached to a port (one per sub-port of a multiport).
std::vector<Node*> portNodes(Port* port);

// A cluster id per entry of `list`. A component inside a subsystem counts as the subsystem
// that stands in the list.
std::vector<std::size_t> linkedClusters(const std::vector<Component*>& list);

} // namespace tlmhub
