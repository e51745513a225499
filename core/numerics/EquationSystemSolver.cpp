#include "core/numerics/EquationSystemSolver.h"

namespace tlmhub {

namespace {
constexpr double kWeights[4] = {1.0, 0.67, 0.5, 0.5};
}

EquationSystemSolver::EquationSystemSolver(int n)
    : mN(n < 0 ? 0 : n), mOrder(static_cast<std::size_t>(n < 0 ? 0 : n), 0), mDx(n < 0 ? 0 : n)
{
}

bool EquationSystemSolver::solve(Matrix& J, Vec& F, Vec& x, int iter)
{
    int idx = iter - 1;
    if (idx < 0) { idx = 0; }
    if (idx > 3) { idx = 3; }
    return solveWeighted(J, F, x, kWeights[idx]);
}

bool EquationSystemSolver::solve(Matrix& J, Vec& F, Vec& x) { return solveWeighted(J, F, x, 1.0); }

bool EquationSystemSolver::solveWeighted(Matrix& J, Vec& F, Vec& x, double w)
{
    const bool ok = ludcmp(J, mOrder.data());
    solvlu(J, F, mDx, mOrder.data());
    for (int i = 0; i < mN; ++i) { x[i] = x[i] - w * mDx[i]; }
    return ok;
}

} // namespace tlmhub
