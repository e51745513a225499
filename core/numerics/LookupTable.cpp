#include "core/numerics/LookupTable.h"

#include <algorithm>
#include <utility>

namespace tlmhub {

// ------------------------------------------------------------ LookupTableND

LookupTableND::LookupTableND(int numDims)
    : mIndex(static_cast<std::size_t>(numDims)),
      mFirst(static_cast<std::size_t>(numDims), 0.0),
      mLast(static_cast<std::size_t>(numDims), 1.0)
{
}

bool LookupTableND::isDataSizeOK()
{
    bool ok = true;
    std::size_t product = 1;
    for (const auto& idx : mIndex) {
        if (idx.size() < 2) { ok = false; }
        product *= idx.size();
    }
    ok = ok && (product == mValues.size());
    for (std::size_t d = 0; d < mIndex.size(); ++d) {
        if (ok) {
            mFirst[d] = mIndex[d].front();
            mLast[d] = mIndex[d].back();
        } else {
            mFirst[d] = 0.0;
            mLast[d] = 1.0;
        }
    }
    return ok;
}

LookupTableND::IndexOrder LookupTableND::getIndexOrder(int dim) const
{
    const auto& idx = mIndex[static_cast<std::size_t>(dim)];
    bool inc = true;
    bool dec = true;
    for (std::size_t i = 1; i < idx.size(); ++i) {
        if (!(idx[i] > idx[i - 1])) { inc = false; }
        if (!(idx[i] < idx[i - 1])) { dec = false; }
    }
    if (inc) { return IndexOrder::StrictlyIncreasing; }
    if (dec) { return IndexOrder::StrictlyDecreasing; }
    return IndexOrder::NotStrictlyMonotone;
}

bool LookupTableND::allIndexStrictlyIncreasing() const
{
    for (int d = 0; d < getNumDims(); ++d) {
        if (getIndexOrder(d) != IndexOrder::StrictlyIncreasing) { return false; }
    }
    return true;
}

bool LookupTableND::isDataOK()
{
    const bool sizeOk = isDataSizeOK();
    return sizeOk && allIndexStrictlyIncreasing();
}

std::size_t LookupTableND::stride(int dim) const
{
    std::size_t s = 1;
    for (std::size_t d = static_cast<std::size_t>(dim) + 1; d < mIndex.size(); ++d) { s *= mIndex[d].size(); }
    return s;
}

void LookupTableND::swapSlices(int dim, std::size_t i, std::size_t j)
{
    auto& idx = mIndex[static_cast<std::size_t>(dim)];
    std::swap(idx[i], idx[j]);
    const std::size_t n = idx.size();
    const std::size_t s = stride(dim);
    const std::size_t block = n * s;
    if (block == 0 || mValues.size() % block != 0) { return; } // sizes inconsistent: only the index is sorted
    const std::size_t outer = mValues.size() / block;
    for (std::size_t o = 0; o < outer; ++o) {
        for (std::size_t t = 0; t < s; ++t) {
            std::swap(mValues[o * block + i * s + t], mValues[o * block + j * s + t]);
        }
    }
}

// Quicksort with the middle element as pivot and Lomuto partitioning.
void LookupTableND::quickSort(int dim, std::ptrdiff_t lo, std::ptrdiff_t hi)
{
    if (lo >= hi) { return; }
    auto& idx = mIndex[static_cast<std::size_t>(dim)];
    const std::ptrdiff_t mid = lo + (hi - lo) / 2;
    swapSlices(dim, static_cast<std::size_t>(mid), static_cast<std::size_t>(hi));
    const double pivotValue = idx[static_cast<std::size_t>(hi)];
    std::ptrdiff_t store = lo;
    for (std::ptrdiff_t i = lo; i < hi; ++i) {
        if (idx[static_cast<std::size_t>(i)] < pivotValue) {
            if (i != store) { swapSlices(dim, static_cast<std::size_t>(i), static_cast<std::size_t>(store)); }
            ++store;
        }
    }
    if (store != hi) { swapSlices(dim, static_cast<std::size_t>(store), static_cast<std::size_t>(hi)); }
    quickSort(dim, lo, store - 1);
    quickSort(dim, store + 1, hi);
}

void LookupTableND::sortIncreasing()
{
    for (int d = 0; d < getNumDims(); ++d) {
        const IndexOrder order = getIndexOrder(d);
        if (order == IndexOrder::StrictlyIncreasing) { continue; }
        auto& idx = mIndex[static_cast<std::size_t>(d)];
        if (order == IndexOrder::StrictlyDecreasing && getNumDims() == 1) {
            std::reverse(idx.begin(), idx.end());
            std::reverse(mValues.begin(), mValues.end());
        } else {
            quickSort(d, 0, static_cast<std::ptrdiff_t>(idx.size()) - 1);
        }
    }
    isDataSizeOK(); // refresh the cached first/last values
}

std::size_t LookupTableND::findLowerIndex(int dim, double x) const
{
    const auto& idx = mIndex[static_cast<std::size_t>(dim)];
    std::size_t i1 = 0;
    std::size_t iend = idx.size() - 1;
    while (iend - i1 > 1) {
        const std::size_t s = i1 + (iend - i1) / 2;
        if (x <= idx[s]) {
            iend = s;
        } else {
            i1 = s;
        }
    }
    return i1;
}

double LookupTableND::clampToRange(int dim, double x) const
{
    const double lo = mFirst[static_cast<std::size_t>(dim)];
    const double hi = mLast[static_cast<std::size_t>(dim)];
    if (x < lo) { return lo; }
    if (x > hi) { return hi; }
    return x;
}

// ------------------------------------------------------------ 1D

double LookupTable1D::interpolate(double x) const
{
    const auto& idx = mIndex[0];
    if (x < mFirst[0]) { return mValues.front(); }
    if (x >= mLast[0]) { return mValues.back(); }
    const std::size_t i = findLowerIndex(0, x);
    return mValues[i] + (x - idx[i]) * (mValues[i + 1] - mValues[i]) / (idx[i + 1] - idx[i]);
}

// ------------------------------------------------------------ 2D

double LookupTable2D::interpolate(double r, double c) const
{
    r = clampToRange(0, r);
    c = clampToRange(1, c);
    const std::size_t i = findLowerIndex(0, r);
    const std::size_t j = findLowerIndex(1, c);
    const auto& R = mIndex[0];
    const auto& C = mIndex[1];
    const double vl = interp1(r, R[i], R[i + 1], value(i, j), value(i + 1, j));
    const double vr = interp1(r, R[i], R[i + 1], value(i, j + 1), value(i + 1, j + 1));
    return interp1(c, C[j], C[j + 1], vl, vr);
}

// ------------------------------------------------------------ 3D

double LookupTable3D::bilinearInPlane(double r, double c, std::size_t i, std::size_t j, std::size_t k) const
{
    const auto& R = mIndex[0];
    const auto& C = mIndex[1];
    const std::size_t nc = mIndex[1].size();
    const std::size_t np = mIndex[2].size();
    auto v = [&](std::size_t ri, std::size_t ci) { return mValues[ri * nc * np + ci * np + k]; };
    const double vl = interp1(r, R[i], R[i + 1], v(i, j), v(i + 1, j));
    const double vr = interp1(r, R[i], R[i + 1], v(i, j + 1), v(i + 1, j + 1));
    return interp1(c, C[j], C[j + 1], vl, vr);
}

double LookupTable3D::interpolate(double r, double c, double p) const
{
    r = clampToRange(0, r);
    c = clampToRange(1, c);
    p = clampToRange(2, p);
    const std::size_t k = findLowerIndex(2, p);
    const std::size_t i = findLowerIndex(0, r);
    const std::size_t j = findLowerIndex(1, c);
    const double vk = bilinearInPlane(r, c, i, j, k);
    const double vk1 = bilinearInPlane(r, c, i, j, k + 1);
    const auto& P = mIndex[2];
    return interp1(p, P[k], P[k + 1], vk, vk1);
}

} // namespace tlmhub
