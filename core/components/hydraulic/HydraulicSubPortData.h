#pragma once
// The node variables of one sub-port of a hydraulic multiport. A component that loops over
// its sub-ports keeps one array of these: a step then reads one small array, not one array per
// variable (four allocations, a cache line apiece, which large models miss on every step).

namespace tlmhub {

struct HydraulicSubPortData {
    double* p = nullptr;
    double* q = nullptr;
    double* c = nullptr;
    double* Zc = nullptr;
};

} // namespace tlmhub
