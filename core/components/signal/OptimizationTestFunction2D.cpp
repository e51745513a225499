#include "core/components/signal/OptimizationTestFunction2D.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/OptimizationTestFunctions.h"

#include <array>
#include <cmath>

namespace tlmhub {

namespace {

double sq(double v) { return v * v; }

// Hopsan writes Euler's number as 2.71828 here; kept, so that results match its models
// (the minimum at the origin is then -1.8e-6 instead of 0).
double ackley(double x, double y)
{
    return -20.0 * std::exp(-0.2 * std::sqrt(0.5 * (x * x + y * y)))
           - std::exp(0.5 * (std::cos(2.0 * pi * x) + std::cos(2.0 * pi * y))) + 20.0 + 2.71828;
}

double beale(double x, double y)
{
    // Hopsan's first term uses 15 where the usual definition has 1.5; kept for compatibility.
    return sq(15.0 - x + x * y) + sq(2.25 - x + x * y * y) + sq(2.625 - x + x * y * y * y);
}

double booth(double x, double y) { return sq(x + 2.0 * y - 7.0) + sq(2.0 * x + y - 5.0); }

double bukin6(double x, double y) { return 100.0 * std::sqrt(std::fabs(y - 0.01 * x * x)) + 0.01 * std::fabs(x + 10.0); }

double crossInTray(double x, double y)
{
    const double inner = std::fabs(std::sin(x) * std::sin(y) * std::exp(std::fabs(100.0 - std::sqrt(x * x + y * y) / pi)));
    return -0.0001 * std::pow(inner + 1.0, 0.1);
}

double easom(double x, double y) { return -std::cos(x) * std::cos(y) * std::exp(-(sq(x - pi) + sq(y - pi))); }

double eggholder(double x, double y)
{
    return -(y + 47.0) * std::sin(std::sqrt(std::fabs(y + x / 2.0 + 47.0))) - x * std::sin(std::fabs(x - (y + 47.0)));
}

double goldsteinPrice(double x, double y)
{
    const double a = 1.0 + sq(x + y + 1.0) * (19.0 - 14.0 * x + 3.0 * x * x - 14.0 * y + 6.0 * x * y + 3.0 * y * y);
    const double b = 30.0 + sq(2.0 * x - 3.0 * y) * (18.0 - 32.0 * x + 12.0 * x * x + 48.0 * y - 36.0 * x * y + 27.0 * y * y);
    return a * b;
}

double holderTable(double x, double y)
{
    return -std::fabs(std::sin(x) * std::cos(y) * std::exp(std::fabs(1.0 - std::sqrt(x * x + y * y) / pi)));
}

double levi(double x, double y)
{
    return sq(std::sin(3.0 * pi * x)) + sq(x - 1.0) * (1.0 + sq(std::sin(3.0 * pi * y)))
           + sq(y - 1.0) * (1.0 + sq(std::sin(2.0 * pi * y)));
}

double matyas(double x, double y) { return 0.26 * (x * x + y * y) - 0.48 * x * y; }

double mcCormick(double x, double y) { return std::sin(x + y) + sq(x - y) - 1.5 * x + 2.5 * y + 1.0; }

double peaks(double x, double y)
{
    return 3.0 * sq(1.0 - x) * std::exp(-x * x - sq(y + 1.0))
           - 10.0 * (x / 5.0 - x * x * x - std::pow(y, 5)) * std::exp(-x * x - y * y)
           - std::exp(-sq(x + 1.0) - y * y) / 3.0;
}

double schaffer2(double x, double y)
{
    return 0.5 + (sq(std::sin(x * x - y * y)) - 0.5) / sq(1.0 + 0.001 * (x * x + y * y));
}

double schaffer4(double x, double y)
{
    return 0.5 + (std::cos(std::sin(std::fabs(x * x - y * y))) - 0.5) / sq(1.0 + 0.001 * (x * x + y * y));
}

double threeHumpCamel(double x, double y)
{
    return 2.0 * x * x - 1.05 * std::pow(x, 4) + std::pow(x, 6) / 6.0 + x * y + y * y;
}

} // namespace

void OptimizationTestFunction2D::configure()
{
    addInputVariable("x", "First coordinate", "", 0.0, &mpX);
    addInputVariable("y", "Second coordinate", "", 0.0, &mpY);
    addOutputVariable("out", "Function value", "", 0.0, &mpOut);
    addConditionalConstant("function", "Test function",
                           {"Ackley's' Function", "Beale's' Function", "Booth's' Function", "Bukin Function N.6",
                            "Cross-In-Tray Function", "Easom Function", "Eggholder Function",
                            "Goldstein-Price Function", "Holder Table Function", "Levi Function", "Matyas Function",
                            "McCormick Function", "Peaks Function", "Rosenbrock Function", "Schaffer Function N.2",
                            "Schaffer Function N.4", "Sphere Function", "Styblinski-Tang Function",
                            "Three-Hump Camel Function"},
                           0, mFunction);
}

void OptimizationTestFunction2D::initialize()
{
    simulateOneTimestep();
}

void OptimizationTestFunction2D::simulateOneTimestep()
{
    const double x = *mpX;
    const double y = *mpY;
    const std::array<double, 2> point{x, y};
    switch (mFunction) {
    case 0: *mpOut = ackley(x, y); break;
    case 1: *mpOut = beale(x, y); break;
    case 2: *mpOut = booth(x, y); break;
    case 3: *mpOut = bukin6(x, y); break;
    case 4: *mpOut = crossInTray(x, y); break;
    case 5: *mpOut = easom(x, y); break;
    case 6: *mpOut = eggholder(x, y); break;
    case 7: *mpOut = goldsteinPrice(x, y); break;
    case 8: *mpOut = holderTable(x, y); break;
    case 9: *mpOut = levi(x, y); break;
    case 10: *mpOut = matyas(x, y); break;
    case 11: *mpOut = mcCormick(x, y); break;
    case 12: *mpOut = peaks(x, y); break;
    case 13: *mpOut = testfunctions::rosenbrock(point); break;
    case 14: *mpOut = schaffer2(x, y); break;
    case 15: *mpOut = schaffer4(x, y); break;
    case 16: *mpOut = testfunctions::sphere(point); break;
    case 17: *mpOut = testfunctions::styblinskiTang(point); break;
    case 18: *mpOut = threeHumpCamel(x, y); break;
    default: *mpOut = 0.0; break;
    }
}

TLMHUB_REGISTER_COMPONENT(OptimizationTestFunction2D, "Signal")

} // namespace tlmhub
