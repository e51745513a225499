#pragma once
// Pointers into the node of a pneumatic power port, bound once in initialize(); shared by
// the pneumatic components so each does not repeat the same six lookups.
#include "core/Node.h"
#include "core/Port.h"

namespace tlmhub {

struct PneumaticPortData {
    double* p = nullptr;    // pressure
    double* qm = nullptr;   // mass flow
    double* T = nullptr;    // temperature
    double* dE = nullptr;   // energy flow
    double* c = nullptr;    // wave variable
    double* Zc = nullptr;   // characteristic impedance

    // `port` must be a connected, non-multiport pneumatic port (power ports are required).
    void bind(Port* port)
    {
        double* d = port->node()->data();
        p = d + NodePneumatic::Pressure;
        qm = d + NodePneumatic::MassFlow;
        T = d + NodePneumatic::Temperature;
        dE = d + NodePneumatic::EnergyFlow;
        c = d + NodePneumatic::WaveVariable;
        Zc = d + NodePneumatic::CharImpedance;
    }
};

} // namespace tlmhub
