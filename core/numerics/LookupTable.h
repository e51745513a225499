// Piecewise-linear lookup tables in 1, 2 and 3 dimensions (utilities.md §14).
// Values are stored row-major with dimension 0 varying slowest.
#pragma once

#include <cstddef>
#include <vector>

namespace tlmhub {

class LookupTableND
{
public:
    enum class IndexOrder { StrictlyIncreasing, StrictlyDecreasing, NotStrictlyMonotone };

    explicit LookupTableND(int numDims);

    int getNumDims() const { return static_cast<int>(mIndex.size()); }
    std::vector<double>& getIndexDataRef(int dim) { return mIndex[static_cast<std::size_t>(dim)]; }
    const std::vector<double>& getIndexDataRef(int dim) const { return mIndex[static_cast<std::size_t>(dim)]; }
    std::vector<double>& getValueDataRef() { return mValues; }
    const std::vector<double>& getValueDataRef() const { return mValues; }
    std::size_t getIndexDataSize(int dim) const { return mIndex[static_cast<std::size_t>(dim)].size(); }
    std::size_t getValueDataSize() const { return mValues.size(); }

    // Every index has >= 2 entries and the product of sizes equals the number
    // of values. Caches first/last index values (0 and 1 on failure); must be
    // called (directly or via isDataOK) after the data is filled in.
    bool isDataSizeOK();
    IndexOrder getIndexOrder(int dim) const;
    bool allIndexStrictlyIncreasing() const;
    // Sizes OK and every index strictly increasing.
    bool isDataOK();
    // Reorders every index (and the value slices with it) to increasing order.
    // Duplicates stay duplicates, so re-check with isDataOK() afterwards.
    void sortIncreasing();

protected:
    // Lower interval index i with index[i] < x <= index[i+1] (0 at x == index[0]).
    std::size_t findLowerIndex(int dim, double x) const;
    static double interp1(double x, double x1, double x2, double v1, double v2)
    {
        return v1 + (x - x1) * (v2 - v1) / (x2 - x1);
    }
    double clampToRange(int dim, double x) const;

    std::vector<std::vector<double>> mIndex;
    std::vector<double> mValues;
    std::vector<double> mFirst;
    std::vector<double> mLast;

private:
    std::size_t stride(int dim) const;
    void swapSlices(int dim, std::size_t i, std::size_t j);
    void quickSort(int dim, std::ptrdiff_t lo, std::ptrdiff_t hi);
};

class LookupTable1D : public LookupTableND
{
public:
    LookupTable1D() : LookupTableND(1) {}
    // Constant extrapolation outside the index range.
    double interpolate(double x) const;
};

class LookupTable2D : public LookupTableND
{
public:
    LookupTable2D() : LookupTableND(2) {}
    // Bilinear; coordinates clamped to the index ranges.
    double interpolate(double r, double c) const;

private:
    double value(std::size_t i, std::size_t j) const { return mValues[i * mIndex[1].size() + j]; }
};

class LookupTable3D : public LookupTableND
{
public:
    LookupTable3D() : LookupTableND(3) {}
    // Trilinear: bilinear in planes k and k+1, then along the plane index.
    double interpolate(double r, double c, double p) const;

private:
    double bilinearInPlane(double r, double c, std::size_t i, std::size_t j, std::size_t k) const;
};

} // namespace tlmhub
