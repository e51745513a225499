#pragma once
// The parameter sets of sweeps and Monte Carlo studies.
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <variant>
#include <vector>

namespace tlmhub::server {

// One parameter's values in a sweep: a list, or `steps` values evenly from `from` to `to`
// (both included; steps == 1 gives `from`).
struct SweepRange {
    double from = 0.0, to = 0.0;
    std::size_t steps = 1;
};
struct SweepAxis {
    std::string name;
    std::variant<std::vector<double>, SweepRange> values;
};
// grid: every combination, the first axis varying slowest; list: the i-th values of all axes
// together (all axes must have as many values); random: `samples` sets, each value drawn
// uniformly from the axis (a range: uniform in [from, to); a list: one of its values).
enum class SweepMode { Grid, List, Random };

// The values of an axis.
std::vector<double> axisValues(const SweepAxis& axis);
// How many sets a sweep makes; 0 when there are no axes, an axis has no values, or `mode` is
// List and the axes' lengths differ. Saturates at SIZE_MAX instead of overflowing (a grid of
// many long axes).
std::size_t sweepSize(const std::vector<SweepAxis>& axes, SweepMode mode, std::size_t samples);
// Set `index` (0 <= index < sweepSize) of the sweep, one value per axis in axis order;
// random sets depend only on (seed, index).
std::vector<double> sweepPoint(const std::vector<SweepAxis>& axes, SweepMode mode, std::size_t index,
                               std::uint64_t seed);

// A Monte Carlo parameter: normal(mean, sd) or uniform(min, max).
struct Distribution {
    enum class Kind { Normal, Uniform } kind = Kind::Normal;
    double a = 0.0, b = 1.0;   // normal: mean, sd; uniform: min, max
};
struct RandomParameter {
    std::string name;
    Distribution distribution;
};
// Sample `index` of a Monte Carlo study: one value per parameter; depends only on (seed, index).
std::vector<double> monteCarloPoint(const std::vector<RandomParameter>& parameters, std::size_t index,
                                    std::uint64_t seed);

// Random numbers for studies, the same with every standard library: std::mt19937_64's output
// is fixed by the standard, but <random>'s distributions are not, so values are drawn here.
std::uint64_t splitMix64(std::uint64_t x);
// The generator of draw `index` of a study seeded `seed`, independent of every other index.
std::mt19937_64 indexedGenerator(std::uint64_t seed, std::size_t index);
// Uniform in [0, 1): the top 53 bits of one output.
double uniformUnit(std::mt19937_64& random);
// Standard normal (Box-Muller, two uniform draws; its last bits depend on std::log and
// std::cos).
double standardNormal(std::mt19937_64& random);

} // namespace tlmhub::server
