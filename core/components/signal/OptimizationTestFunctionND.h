#pragma once
#include "core/Component.h"
#include "core/numerics/OptimizationTestFunctions.h"

#include <array>
#include <string>

namespace tlmhub {

// out = f(x1, ..., xN) for one of the test functions defined in any dimension, chosen by
// the constant `function`: 0 Rosenbrock, 1 sphere, 2 Styblinski-Tang. The 5D and 6D
// types are this with N = 5 and N = 6.
template <std::size_t N>
class OptimizationTestFunctionND : public ComponentSignal {
public:
    void configure() override
    {
        for (std::size_t i = 0; i < N; ++i) {
            const std::string name = "x" + std::to_string(i + 1);
            addInputVariable(name, "Coordinate " + name, "", 0.0, &mpX[i]);
        }
        addOutputVariable("out", "Function value", "", 0.0, &mpOut);
        addConditionalConstant("function", "Test function",
                               {"Rosenbrock Function", "Sphere Function", "Styblinski-Tang Function"}, 0, mFunction);
    }

    void initialize() override { simulateOneTimestep(); }

    void simulateOneTimestep() override
    {
        std::array<double, N> x;
        for (std::size_t i = 0; i < N; ++i) x[i] = *mpX[i];
        switch (mFunction) {
        case 0: *mpOut = testfunctions::rosenbrock(x); break;
        case 1: *mpOut = testfunctions::sphere(x); break;
        case 2: *mpOut = testfunctions::styblinskiTang(x); break;
        default: *mpOut = 0.0; break;
        }
    }

private:
    std::array<double*, N> mpX{};
    double* mpOut = nullptr;
    int mFunction = 0;
};

} // namespace tlmhub
