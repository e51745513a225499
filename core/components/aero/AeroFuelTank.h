#pragma once
#include "core/Component.h"

namespace tlmhub {

// Fuel mass integrator (Q kind, signal ports only).
class AeroFuelTank : public ComponentQ {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double *mpMassflow = nullptr, *mpMassfuel0 = nullptr, *mpMassfuel = nullptr, *mpConsfuel = nullptr;
    double mMassfuel0 = 0.0, mMassfuel = 0.0, mConsfuel = 0.0, mDelayed1 = 0.0;
};

} // namespace tlmhub
