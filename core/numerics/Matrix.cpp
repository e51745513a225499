#include "core/numerics/Matrix.h"

#include <cmath>

namespace tlmhub {

// ------------------------------------------------------------ Matrix

void Matrix::create(int rows, int cols)
{
    mRows = rows < 0 ? 0 : rows;
    mCols = cols < 0 ? 0 : cols;
    mStorage.assign(static_cast<std::size_t>(mRows) * static_cast<std::size_t>(mCols), 0.0);
    mRowPtr.resize(static_cast<std::size_t>(mRows));
    for (int i = 0; i < mRows; ++i) {
        mRowPtr[static_cast<std::size_t>(i)] = mStorage.data() + static_cast<std::size_t>(i) * static_cast<std::size_t>(mCols);
    }
}

// Copies keep the logical (possibly permuted) row order but own fresh storage.
Matrix::Matrix(const Matrix& other) { *this = other; }

Matrix& Matrix::operator=(const Matrix& other)
{
    if (this != &other) {
        create(other.mRows, other.mCols);
        for (int i = 0; i < mRows; ++i) {
            for (int j = 0; j < mCols; ++j) { (*this)[i][j] = other[i][j]; }
        }
    }
    return *this;
}

// ------------------------------------------------------------ LU

namespace {

bool pivot(Matrix& a, int order[], int j)
{
    const int n = a.rows();
    int best = j;
    double maxAbs = std::fabs(a[j][j]);
    for (int i = j + 1; i < n; ++i) {
        const double v = std::fabs(a[i][j]);
        if (v > maxAbs) { // strictly larger: ties keep the earliest row
            maxAbs = v;
            best = i;
        }
    }
    if (!(maxAbs > 0.0)) { return false; } // also catches NaN
    if (best != j) {
        a.swaprows(j, best);
        const int t = order[j];
        order[j] = order[best];
        order[best] = t;
    }
    return true;
}

} // namespace

bool ludcmp(Matrix& a, int order[])
{
    const int n = a.rows();
    for (int i = 0; i < n; ++i) { order[i] = i; }
    if (n == 0) { return true; }

    if (!pivot(a, order, 0)) { return false; }
    double d = 1.0 / a[0][0];
    for (int i = 1; i < n; ++i) { a[0][i] *= d; }

    for (int j = 1; j < n - 1; ++j) {
        for (int i = j; i < n; ++i) { // column j of L
            double sum = 0.0;
            for (int k = 0; k < j; ++k) { sum += a[i][k] * a[k][j]; }
            a[i][j] -= sum;
        }
        if (!pivot(a, order, j)) { return false; }
        d = 1.0 / a[j][j];
        for (int k = j + 1; k < n; ++k) { // row j of U
            double sum = 0.0;
            for (int i = 0; i < j; ++i) { sum += a[j][i] * a[i][k]; }
            a[j][k] = (a[j][k] - sum) * d;
        }
    }

    // Last L element; the reference never checks it for zero.
    double sum = 0.0;
    for (int k = 0; k < n - 1; ++k) { sum += a[n - 1][k] * a[k][n - 1]; }
    a[n - 1][n - 1] -= sum;
    return true;
}

void solvlu(const Matrix& a, const Vec& b, Vec& x, const int order[])
{
    const int n = a.rows();
    if (n == 0) { return; }
    for (int i = 0; i < n; ++i) { x[i] = b[order[i]]; }

    x[0] = x[0] / a[0][0];
    for (int i = 1; i < n; ++i) { // L y = b
        double sum = 0.0;
        for (int j = 0; j < i; ++j) { sum += a[i][j] * x[j]; }
        x[i] = (x[i] - sum) / a[i][i];
    }
    for (int i = n - 2; i >= 0; --i) { // U x = y, unit diagonal
        double sum = 0.0;
        for (int j = i + 1; j < n; ++j) { sum += a[i][j] * x[j]; }
        x[i] = x[i] - sum;
    }
}

} // namespace tlmhub
