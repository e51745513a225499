// Dense row-pointer matrix, vector and Crout LU factorisation with partial
// pivoting (utilities.md §16).
#pragma once

#include <cstddef>
#include <vector>

namespace tlmhub {

class Vec
{
public:
    Vec() = default;
    // Elements are zero-filled here (the reference leaves them undefined;
    // callers assign every element anyway).
    explicit Vec(int n) : mData(static_cast<std::size_t>(n < 0 ? 0 : n), 0.0) {}

    void create(int n) { mData.assign(static_cast<std::size_t>(n < 0 ? 0 : n), 0.0); }
    void set(double v)
    {
        for (double& d : mData) { d = v; }
    }
    int length() const { return static_cast<int>(mData.size()); }

    double& operator[](int i) { return mData[static_cast<std::size_t>(i)]; }
    const double& operator[](int i) const { return mData[static_cast<std::size_t>(i)]; }
    double* data() { return mData.data(); }

private:
    std::vector<double> mData;
};

class Matrix
{
public:
    Matrix() = default;
    Matrix(int rows, int cols) { create(rows, cols); }
    Matrix(const Matrix& other);
    Matrix& operator=(const Matrix& other);
    Matrix(Matrix&&) = default;
    Matrix& operator=(Matrix&&) = default;

    void create(int rows, int cols);
    int rows() const { return mRows; }
    int cols() const { return mCols; }

    // m[i][j]; after ludcmp the row pointers are permuted.
    double* operator[](int i) { return mRowPtr[static_cast<std::size_t>(i)]; }
    const double* operator[](int i) const { return mRowPtr[static_cast<std::size_t>(i)]; }

    // Swaps the row pointers (O(1)), not the row contents.
    void swaprows(int i, int j)
    {
        double* tmp = mRowPtr[static_cast<std::size_t>(i)];
        mRowPtr[static_cast<std::size_t>(i)] = mRowPtr[static_cast<std::size_t>(j)];
        mRowPtr[static_cast<std::size_t>(j)] = tmp;
    }

private:
    int mRows = 0;
    int mCols = 0;
    std::vector<double> mStorage;
    std::vector<double*> mRowPtr;
};

// In-place Crout LU (unit upper U, pivots on L's diagonal). order[i] is the
// original row now in row i. Returns false if a pivot column is all zero/NaN.
bool ludcmp(Matrix& a, int order[]);
inline bool ludcmp(Matrix& a, std::vector<int>& order) { return ludcmp(a, order.data()); }

// Solves LU*x = b (b given in original row order).
void solvlu(const Matrix& a, const Vec& b, Vec& x, const int order[]);
inline void solvlu(const Matrix& a, const Vec& b, Vec& x, const std::vector<int>& order)
{
    solvlu(a, b, x, order.data());
}

} // namespace tlmhub
