// One damped Newton-Raphson step x <- x - w[iter-1] * J^-1 * F used by
// generated components (utilities.md §17).
#pragma once

#include <vector>

#include "core/numerics/Matrix.h"

namespace tlmhub {

class EquationSystemSolver
{
public:
    explicit EquationSystemSolver(int n);

    // iter is 1-based (weights 1.0, 0.67, 0.5, 0.5; iterations beyond 4 use 0.5).
    // J is overwritten by its LU factors. Returns false if J is singular; like
    // the reference, x is still updated with whatever the factorisation gave,
    // and the caller is expected to stop the simulation.
    bool solve(Matrix& J, Vec& F, Vec& x, int iter);
    // Same with weight 1.
    bool solve(Matrix& J, Vec& F, Vec& x);

    int size() const { return mN; }

private:
    bool solveWeighted(Matrix& J, Vec& F, Vec& x, double w);

    int mN;
    std::vector<int> mOrder;
    Vec mDx;
};

} // namespace tlmhub
