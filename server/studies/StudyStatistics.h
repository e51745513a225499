#pragma once
// Statistics a sensitivity study reports: per variable the mean and standard deviation over
// the runs at every logged time (bands of ±1σ and ±2σ), accumulated one run at a time without
// keeping the runs; and the Pearson correlation of each parameter with each scalar output.
#include <cstddef>
#include <string>
#include <vector>

namespace tlmhub::server {

// Mean and sample standard deviation of a series of equally long sample vectors (Welford's
// update, numerically stable).
class SeriesBands {
public:
    // False (and nothing added) when `samples` is not as long as the first series added.
    bool add(const std::vector<double>& samples);
    std::size_t count() const { return mCount; }
    std::vector<double> mean() const;
    std::vector<double> standardDeviation() const;   // 0 with fewer than two series

private:
    std::size_t mCount = 0;
    std::vector<double> mMean, mM2;
};

// Pearson's r of x and y (equal lengths); NaN when fewer than two pairs or either is constant.
// Pairs where either value is not finite are left out.
double pearsonCorrelation(const std::vector<double>& x, const std::vector<double>& y);

} // namespace tlmhub::server
