// Test functions of any dimension for optimisation benchmarks, shared by the
// OptimizationTestFunction2D/5D/6D components. Each takes the point x = (x1 ... xn).
#pragma once

#include <cstddef>
#include <span>

namespace tlmhub::testfunctions {

// sum over i < n of (1 - x_i)^2 + 100 (x_{i+1} - x_i^2)^2; minimum 0 at (1, ..., 1).
inline double rosenbrock(std::span<const double> x)
{
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
        const double a = 1.0 - x[i];
        const double b = x[i + 1] - x[i] * x[i];
        sum += a * a + 100.0 * b * b;
    }
    return sum;
}

// sum of x_i^2; minimum 0 at the origin.
inline double sphere(std::span<const double> x)
{
    double sum = 0.0;
    for (double xi : x) sum += xi * xi;
    return sum;
}

// (sum of x_i^4 - 16 x_i^2 + 5 x_i) / 2; minimum about -39.16617 n at x_i = -2.903534.
inline double styblinskiTang(std::span<const double> x)
{
    double sum = 0.0;
    for (double xi : x) sum += xi * xi * xi * xi - 16.0 * xi * xi + 5.0 * xi;
    return sum / 2.0;
}

} // namespace tlmhub::testfunctions
